#pragma once
// Measures of final paths (waypoint lists), independent of how they were planned.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "aco/graph.hpp"

namespace aco {

using Waypoints = std::vector<Eigen::Vector3d>;

Waypoints to_waypoints(const Graph& graph, std::span<const NodeId> path);
double polyline_length(std::span<const Eigen::Vector3d> points);
// Number of heading changes along the path: interior waypoints where the direction of travel
// in the (x, y) plane changes (collinear repeats are not turns; on terrain, neither is a change
// of slope alone).
int count_turns(std::span<const Eigen::Vector3d> points);

}  // namespace aco
