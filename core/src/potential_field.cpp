#include "aco/potential_field.hpp"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>

#include "aco/parallel.hpp"

namespace aco {

namespace {

// The field in D dimensions: the map plane (D = 2; heights weigh the repulsion) or a voxel
// world's space (D = 3; every voxel at z = 0 height, so only blocked voxels push).
template <int D>
std::vector<Eigen::Matrix<double, D, 1>> forces_in(const Graph& graph, NodeId start, NodeId goal,
                                                   const PotentialFieldGains& gains) {
  using Vector = Eigen::Matrix<double, D, 1>;
  std::vector<Vector> forces(graph.num_nodes(), Vector::Zero());
  const auto planar = [&](NodeId n) -> Vector { return graph.position(n).template head<D>(); };

  const double z0 = D == 2 ? graph.position(start).z() : 0.0;
  double z_max = z0;
  if constexpr (D == 2)
    for (NodeId n = 0; n < graph.num_nodes(); ++n)
      if (graph.passable(n)) z_max = std::max(z_max, graph.position(n).z());
  // Weight of cell m as a source of repulsion: 0 at or below the start height.
  std::vector<double> weight(graph.num_nodes(), 0.0);
  for (NodeId m = 0; m < graph.num_nodes(); ++m) {
    const double z = D == 2 ? graph.position(m).z() : 0.0;
    weight[m] = !graph.passable(m) ? 1.0 : z > z0 ? (z - z0) / (z_max - z0) : 0.0;
  }

  // The cells within rho0 lie in a square (cube) window of this many cells around a node.
  const double spacing = graph.width > 1    ? (planar(1) - planar(0)).norm()
                         : graph.height > 1 ? (planar(graph.width) - planar(0)).norm()
                                            : 0.0;
  const int radius = spacing > 0.0 ? static_cast<int>(std::ceil(gains.rho0 / spacing)) : 0;
  const int layers = D == 3 ? radius : 0;

  // Each node on its own: the result does not depend on the thread count.
  aco::parallel_for(tbb::blocked_range<NodeId>(0, graph.num_nodes()), [&](const tbb::blocked_range<NodeId>& r) {
    for (NodeId n = r.begin(); n != r.end(); ++n) {
      if (!graph.passable(n)) continue;
      Vector force = Vector::Zero();
      const Vector to_goal = planar(goal) - planar(n);
      if (n != goal && to_goal.norm() > 0.0) force += gains.k * to_goal.normalized();
      const Cell c = graph.cell(n);
      for (int z = std::max(0, c.z - layers); z <= std::min(graph.depth - 1, c.z + layers); ++z) {
        for (int y = std::max(0, c.y - radius); y <= std::min(graph.height - 1, c.y + radius); ++y) {
          for (int x = std::max(0, c.x - radius); x <= std::min(graph.width - 1, c.x + radius); ++x) {
            const NodeId m = graph.node({x, y, z});
            const Vector away = planar(n) - planar(m);
            const double rho = away.norm();
            if (weight[m] == 0.0 || rho == 0.0 || rho >= gains.rho0) continue;
            force += gains.theta * weight[m] * (1.0 / rho - 1.0 / gains.rho0) / (rho * rho) * (away / rho);
          }
        }
      }
      forces[n] = force;
    }
  });
  return forces;
}

}  // namespace

std::vector<Eigen::Vector2d> potential_forces(const Graph& graph, NodeId start, NodeId goal,
                                              const PotentialFieldGains& gains) {
  return forces_in<2>(graph, start, goal, gains);
}

PotentialField::PotentialField(const Graph& graph, NodeId start, NodeId goal, const PotentialFieldGains& gains)
    : graph_(graph) {
  if (graph.volumetric)
    spatial_ = forces_in<3>(graph, start, goal, gains);
  else
    planar_ = potential_forces(graph, start, goal, gains);
}

double PotentialField::along(EdgeId e) const {
  const NodeId from = graph_.source(e);
  if (!graph_.volumetric) return planar_[from].dot(planar_direction(graph_, e));
  return spatial_[from].dot((graph_.position(graph_.targets[e]) - graph_.position(from)).normalized());
}

double PotentialField::strength(EdgeId e) const {
  const NodeId from = graph_.source(e);
  return graph_.volumetric ? spatial_[from].norm() : planar_[from].norm();
}

}  // namespace aco
