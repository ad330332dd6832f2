#pragma once
// Measures of final paths (waypoint lists), independent of how they were planned.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "aco/graph.hpp"

namespace aco {

using Waypoints = std::vector<Eigen::Vector3d>;

Waypoints to_waypoints(const Graph& graph, std::span<const NodeId> path);
double polyline_length(std::span<const Eigen::Vector3d> points);
// Number of heading changes along the path: interior waypoints where the direction of travel
// in the (x, y) plane changes (collinear repeats are not turns; on terrain, neither is a change
// of slope alone). In space (a voxel world, where z is a layer and not a height), the direction
// in 3D: a climb or a descent that begins is a turn too.
int count_turns(std::span<const Eigen::Vector3d> points, bool in_space = false);

// Whether a point in planning units lies on a passable cell of the graph's map (its x and y; z is
// the terrain's height; in a voxel world x, y and z, on a free voxel). A point on the border of cells lies on each of
// them: a waypoint on the corner of an obstacle, where a shortest any-angle path turns, is on a free cell when one cell
// it touches is free.
bool on_free_cell(const Graph& graph, const Eigen::Vector3d& point);

// What is wrong with a smoother's waypoints for the path from start to goal, or "" if nothing:
// each must be finite and on a free cell, the first the start's position and the last the goal's.
std::string waypoint_problem(const Graph& graph, NodeId start, NodeId goal, std::span<const Eigen::Vector3d> points);

// Greedy string pulling over a path of n nodes: from node 0, jump to the farthest later node j in
// [i+2, min(n-1, i+max_lookahead)] (0 = unlimited) with can_join(i, j), scanning down from the
// end, or to i+1 if there is none; repeat from there. The indices kept, 0 and n-1 included (just
// {0} for n == 1, nothing for n == 0). Adjacent nodes are joined unchecked: they are a graph edge.
std::vector<std::size_t> greedy_shortcuts(std::size_t n, std::size_t max_lookahead,
                                          const std::function<bool(std::size_t, std::size_t)>& can_join);

// Whether every blocked cell (outside the map included) is at least `clearance` from the segment
// between the centres of cells a and b (exact segment-to-square distances, in cell units).
bool keeps_clear(const Map& map, Cell a, Cell b, double clearance);

}  // namespace aco
