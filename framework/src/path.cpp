#include "aco/path.hpp"

namespace aco {

Waypoints to_waypoints(const Graph& graph, std::span<const NodeId> path) {
  Waypoints points;
  points.reserve(path.size());
  for (NodeId n : path) points.push_back(graph.positions[n]);
  return points;
}

double polyline_length(std::span<const Eigen::Vector3d> points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

int count_turns(std::span<const Eigen::Vector3d> points) {
  int turns = 0;
  Eigen::Vector3d heading = Eigen::Vector3d::Zero();  // direction of the last non-empty segment
  for (std::size_t i = 1; i < points.size(); ++i) {
    // Heading on the ground: on terrain the climb angle changes at almost every waypoint, and
    // that is no turn for the robot's steering.
    Eigen::Vector3d step = points[i] - points[i - 1];
    step.z() = 0.0;
    if (step.squaredNorm() == 0.0) continue;  // a repeated waypoint is no move, and hides no turn
    if (heading.squaredNorm() > 0.0) {
      // Same heading when parallel and pointing the same way (relative tolerance).
      const bool parallel = heading.cross(step).norm() <= 1e-9 * heading.norm() * step.norm();
      if (!(parallel && heading.dot(step) > 0.0)) ++turns;
    }
    heading = step;
  }
  return turns;
}

}  // namespace aco
