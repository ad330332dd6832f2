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
  for (std::size_t i = 1; i + 1 < points.size(); ++i) {
    const Eigen::Vector3d a = points[i] - points[i - 1];
    const Eigen::Vector3d b = points[i + 1] - points[i];
    if (a.squaredNorm() == 0.0 || b.squaredNorm() == 0.0) continue;
    // Same heading when parallel and pointing the same way (relative tolerance).
    const bool parallel = a.cross(b).norm() <= 1e-9 * a.norm() * b.norm();
    if (!(parallel && a.dot(b) > 0.0)) ++turns;
  }
  return turns;
}

}  // namespace aco
