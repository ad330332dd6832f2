#include "aco/path.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "aco/robot.hpp"

namespace aco {
namespace {

std::string to_text(const Eigen::Vector3d& p) {
  std::ostringstream text;
  text << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return text.str();
}

// Distance from the segment a-b to the unit square centred on c, when they do not cross: the
// nearest pair is an end of the segment and the square, or a corner of the square and the segment.
double distance_to_cell(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  double d = std::min(distance_to_square(a, c, 1.0), distance_to_square(b, c, 1.0));
  const Eigen::Vector2d ab = b - a;
  for (const Eigen::Vector2d& corner :
       {Eigen::Vector2d(c.x() - 0.5, c.y() - 0.5), Eigen::Vector2d(c.x() + 0.5, c.y() - 0.5),
        Eigen::Vector2d(c.x() - 0.5, c.y() + 0.5), Eigen::Vector2d(c.x() + 0.5, c.y() + 0.5)}) {
    const double t = ab.squaredNorm() > 0.0 ? std::clamp((corner - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    d = std::min(d, (a + t * ab - corner).norm());
  }
  return d;
}

// The cells whose closed interval along one axis holds v (in cells): two on their border. The
// tolerance takes in the rounding of a position divided back by a terrain's cell size.
std::pair<int, int> cells_around(double v) {
  constexpr double kTolerance = 1e-9;
  return {static_cast<int>(std::ceil(v - 0.5 - kTolerance)), static_cast<int>(std::floor(v + 0.5 + kTolerance))};
}

// on_free_cell in a voxel world, whose voxel (x, y, z) is the unit cube centred on (x, y, z).
bool on_free_voxel(const Map& map, const Eigen::Vector3d& p) {
  if (!(p.x() > -1.0 && p.y() > -1.0 && p.z() > -1.0 && p.x() < map.width() && p.y() < map.height() &&
        p.z() < map.depth()))
    return false;
  const auto [x_low, x_high] = cells_around(p.x());
  const auto [y_low, y_high] = cells_around(p.y());
  const auto [z_low, z_high] = cells_around(p.z());
  for (int z = z_low; z <= z_high; ++z)
    for (int y = y_low; y <= y_high; ++y)
      for (int x = x_low; x <= x_high; ++x)
        if (map.passable({x, y, z})) return true;
  return false;
}

}  // namespace

Waypoints to_waypoints(const Graph& graph, std::span<const NodeId> path) {
  Waypoints points;
  points.reserve(path.size());
  for (NodeId n : path) points.push_back(graph.position(n));
  return points;
}

double polyline_length(std::span<const Eigen::Vector3d> points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) length += (points[i] - points[i - 1]).norm();
  return length;
}

int count_turns(std::span<const Eigen::Vector3d> points, bool in_space) {
  int turns = 0;
  Eigen::Vector3d heading = Eigen::Vector3d::Zero();  // direction of the last non-empty segment
  for (std::size_t i = 1; i < points.size(); ++i) {
    // Heading on the ground: on terrain the climb angle changes at almost every waypoint, and
    // that is no turn for the robot's steering.
    Eigen::Vector3d step = points[i] - points[i - 1];
    if (!in_space) step.z() = 0.0;
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

bool on_free_cell(const Graph& graph, const Eigen::Vector3d& point) {
  // Cell (x, y) is centred on origin + (x, y) * unit (Map::position), a square of side unit.
  const Map& map = *graph.map;
  if (graph.volumetric) return on_free_voxel(map, point);
  const Eigen::Vector3d origin = map.position({0, 0});
  const double unit_x = map.position({1, 0}).x() - origin.x(), unit_y = map.position({0, 1}).y() - origin.y();
  const double x = (point.x() - origin.x()) / unit_x, y = (point.y() - origin.y()) / unit_y;
  if (!(x > -1.0 && y > -1.0 && x < map.width() && y < map.height())) return false;  // beyond every cell's border
  // The cells whose closed square holds the point.
  const auto [x_low, x_high] = cells_around(x);
  const auto [y_low, y_high] = cells_around(y);
  for (int cy = y_low; cy <= y_high; ++cy)
    for (int cx = x_low; cx <= x_high; ++cx)
      if (map.passable({cx, cy})) return true;
  return false;
}

std::string waypoint_problem(const Graph& graph, NodeId start, NodeId goal, std::span<const Eigen::Vector3d> points) {
  if (points.empty()) return "no waypoints";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string which = "waypoint " + std::to_string(i) + " (0-based) of " + std::to_string(points.size()) +
                              ", " + to_text(points[i]) + ", ";
    if (!points[i].allFinite()) return which + "is not finite";
    if (!on_free_cell(graph, points[i])) return which + "lies on no free cell";
  }
  if (points.front() != graph.position(start))
    return "the first waypoint, " + to_text(points.front()) + ", is not the start " +
           graph.map->describe(graph.cell(start)) + " at " + to_text(graph.position(start));
  if (points.back() != graph.position(goal))
    return "the last waypoint, " + to_text(points.back()) + ", is not the goal " +
           graph.map->describe(graph.cell(goal)) + " at " + to_text(graph.position(goal));
  return "";
}

std::vector<std::size_t> greedy_shortcuts(std::size_t n, std::size_t max_lookahead,
                                          const std::function<bool(std::size_t, std::size_t)>& can_join) {
  std::vector<std::size_t> kept;
  if (n == 0) return kept;
  const std::size_t last = n - 1;
  kept.push_back(0);
  std::size_t i = 0;
  while (i < last) {
    const std::size_t farthest = max_lookahead == 0 ? last : std::min(last, i + max_lookahead);
    std::size_t next = i + 1;
    for (std::size_t j = farthest; j >= i + 2; --j)
      if (can_join(i, j)) {
        next = j;
        break;
      }
    kept.push_back(next);
    i = next;
  }
  return kept;
}

bool keeps_clear(const Map& map, Cell a, Cell b, double clearance) {
  const Eigen::Vector2d pa(a.x, a.y), pb(b.x, b.y);
  for (int y = std::min(a.y, b.y) - 1; y <= std::max(a.y, b.y) + 1; ++y)
    for (int x = std::min(a.x, b.x) - 1; x <= std::max(a.x, b.x) + 1; ++x)
      if (!map.passable({x, y}) && distance_to_cell(pa, pb, Eigen::Vector2d(x, y)) < clearance) return false;
  return true;
}

}  // namespace aco
