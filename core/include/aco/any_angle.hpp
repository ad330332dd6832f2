#pragma once
// A yardstick for continuous paths: the exact shortest any-angle path on a grid map (Anya), and
// basic Theta* as a check on it.
//
// Geometry. Cells are unit squares centred on integer (x, y); start and goal are cell centres; a
// path is a polyline. A segment is free when it
//   - enters the interior of no blocked cell (outside the map is blocked),
//   - runs along a cell edge only where at least one of the two cells beside it is free, and
//   - passes through a grid vertex only where the free cells around that vertex connect the side
//     it comes from to the side it leaves by: never between two diagonally adjacent blocked cells
//     through their shared vertex.
// A polyline is valid when its segments are free and it turns at no vertex in a way a segment
// could not pass it (so not from one free cell into the diagonal one between two blocked cells).
// Touching a blocked cell's boundary is allowed: grazing a corner, running along an obstacle's
// edge. These are exactly the limits of paths that keep a positive distance from every obstacle,
// so every stricter rule (the graph's no-corner-cutting rule, line_of_sight with or without corner
// cutting, a robot's clearance) allows a subset of these paths, and the optimum here is a LOWER
// bound on the length of every path they allow. Taut optimal paths turn only at convex obstacle
// corners (grid vertices with exactly one blocked cell around them).
//
// Bounds, for start and goal on free cells (lengths in cell units):
//   euclidean(start, goal) <= any_angle_optimum <= theta_star (no corner cutting) <= A* (8-neighbourhood,
//   no corner cutting, the octile optimum of Moving AI's .scen files).
// A graph with corner cutting allows diagonal steps between two blocked cells, which this rule
// does not: its A* and Theta* lengths are not bounded below by the optimum here.
//
// Only occupancy counts (Map::passable): the rule is planar and in cell units, whatever a terrain
// map's heights, cell size or step rule.
#include <Eigen/Core>
#include <boost/config.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>

#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/path.hpp"

namespace aco {

struct AnyAnglePath {
  double length = 0.0;  // in cell units
  Waypoints waypoints;  // the start's centre, the vertices it turns at, the goal's centre (z = 0)
};

// The exact shortest valid path from the centre of start to the centre of goal (Anya: Harabor,
// Grastien, Oz, Aksakalli, "Optimal any-angle pathfinding in practice", JAIR 2016, on the grid
// refined into half cells so that cell centres are grid points; exact rational interval ends).
// Empty when start or goal is blocked or no valid path joins them.
std::optional<AnyAnglePath> any_angle_optimum(const Map& map, Cell start, Cell goal);

// The same for many queries on one map: the map's free runs and corners are found once.
class BOOST_SYMBOL_VISIBLE AnyAngleSearch {
 public:
  explicit AnyAngleSearch(const Map& map);
  ~AnyAngleSearch();
  AnyAngleSearch(const AnyAngleSearch&) = delete;
  AnyAngleSearch& operator=(const AnyAngleSearch&) = delete;
  std::optional<AnyAnglePath> find(Cell start, Cell goal);
  // The same, asking `give_up` every 1024 expansions: true ends the search with none (a time limit).
  std::optional<AnyAnglePath> find(Cell start, Cell goal, const std::function<bool()>& give_up);
  std::size_t expanded() const;  // search nodes expanded by the last find()

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Basic Theta* (Nash, Daniel, Koenig, Felner 2007) on the graph's cells: A* over the graph's
// moves where a cell takes its parent's parent when line_of_sight (with the graph's corner option)
// joins them. Empty when the goal is unreachable. Never longer than A* on the same graph.
std::optional<AnyAnglePath> theta_star(const Graph& graph, NodeId start, NodeId goal);

// Whether the straight segment from a to b is free under the rule above: segment_free
// (aco/graph.hpp) with corner cutting, for a and b on the half-cell lattice (cell centres, cell
// corners, edge midpoints: 2x and 2y integers); other points are an Error. z is ignored.
bool any_angle_segment_free(const Map& map, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
// Whether a polyline is valid under the rule above (every segment free, every turn passable);
// points as for any_angle_segment_free. An empty polyline is not; a single point is when it lies
// on a free cell.
bool any_angle_path_valid(const Map& map, std::span<const Eigen::Vector3d> points);

}  // namespace aco
