#pragma once
// The artificial potential field of paper 000 (EPF-ACO), shared by the potential_field init and
// heuristic plugins: per node a total force F_tot = F_att + F_rep that points towards the goal
// and away from obstacles and from ground higher than the start.
//
// Reading (see plugins/init/potential_field/README.md for the paper's equations):
// - The field lives in the map plane (x, y). Heights only weigh the repulsion: a height is in
//   map units that need not match the cell spacing (the paper's terrain has cells of 1 and
//   heights of 800-1000), so a 3D force would be dominated by height.
// - Attraction: k times the unit vector towards the goal (zero at the goal). The paper's
//   -k (S - E) grows with the distance, which would drown the repulsion far from the goal.
// - Repulsion (eq. 12-13): every cell m within planar distance rho0 of node n whose height
//   exceeds the start height z0 pushes n away from it with
//       theta * h_m * (1/rho - 1/rho0) / rho^2,   h_m = (z_m - z0) / (z_max - z0) in (0, 1],
//   where z_max is the highest passable cell of the map. Blocked cells (obstacles on flat
//   maps) push as the highest ground, h = 1. Cells at or below z0 do not push. Normalising
//   the excess height keeps theta unit-free, the same on flat maps and on terrain.
#include <Eigen/Core>
#include <boost/config.hpp>
#include <cstddef>
#include <vector>

#include "aco/graph.hpp"
#include "aco/settings_table.hpp"

namespace aco {

struct PotentialFieldGains {
  double k = 1.0;  // attraction gain
  double theta = 1.0;  // repulsion gain
  double rho0 = 2.0;  // repulsion range, in map units (paper 000: 2)
};

// The parameters k, theta and rho0, for the tables of plugins that use the field (through
// nested(), see settings_table.hpp).
inline std::vector<SettingsField<PotentialFieldGains>> potential_field_fields() {
  using G = PotentialFieldGains;
  return {
      field("k", &G::k, "0:1e6", "attraction gain: the pull towards the goal, the same at any distance"),
      field("theta", &G::theta, "0:1e6",
            "repulsion gain: a cell at distance rho <= rho0 pushes with theta * h * (1/rho - 1/rho0) / rho^2, h its "
            "normalised height above the start (1 for obstacles)"),
      field("rho0", &G::rho0, "(0:1e3]", "repulsion range in map units (paper 000: 2)"),
  };
}

// F_tot of every node, in the map plane; zero for blocked cells.
BOOST_SYMBOL_VISIBLE std::vector<Eigen::Vector2d> potential_forces(const Graph& graph, NodeId start, NodeId goal,
                                                                   const PotentialFieldGains& gains);

// The field of a graph, in the plane (grids, terrains: potential_forces()) or, in a voxel world,
// in space: the same attraction and repulsion in 3D, the window a cube, every blocked voxel
// pushing with h = 1 (a voxel world has no heights). What the plugins read per edge.
class BOOST_SYMBOL_VISIBLE PotentialField {
 public:
  PotentialField(const Graph& graph, NodeId start, NodeId goal, const PotentialFieldGains& gains);
  // F_tot at the edge's source along the edge's unit direction.
  double along(EdgeId e) const;
  // |F_tot| at the edge's source.
  double strength(EdgeId e) const;

 private:
  const Graph& graph_;
  std::vector<Eigen::Vector2d> planar_;  // per node, on a grid or terrain
  std::vector<Eigen::Vector3d> spatial_;  // per node, in a voxel world
};

// Unit direction of edge e in the map plane.
inline Eigen::Vector2d planar_direction(const Graph& graph, EdgeId e) {
  return (graph.position(graph.targets[e]) - graph.position(graph.source(e))).head<2>().normalized();
}

}  // namespace aco
