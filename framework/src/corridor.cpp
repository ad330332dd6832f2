#include "aco/corridor.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace aco {

CorridorTest::CorridorTest(const Map& map) {
  const int w = map.width(), h = map.height();
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(w) * h, 0);
  std::vector<Cell> stack;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Cell first{x, y};
      if (map.passable(first) || seen[static_cast<std::size_t>(y) * w + x]) continue;
      bool edge = false;
      seen[static_cast<std::size_t>(y) * w + x] = 1;
      stack.push_back(first);
      while (!stack.empty()) {
        const Cell c = stack.back();
        stack.pop_back();
        edge = edge || c.x == 0 || c.y == 0 || c.x == w - 1 || c.y == h - 1;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const Cell n{c.x + dx, c.y + dy};
            if (!map.contains(n) || map.passable(n)) continue;
            std::uint8_t& s = seen[static_cast<std::size_t>(n.y) * w + n.x];
            if (!s) {
              s = 1;
              stack.push_back(n);
            }
          }
      }
      // Inside the cell, off every half-cell line a grid path or an any-angle path runs along:
      // no path passes through it, and the ray from it meets path vertices only by accident.
      if (!edge) points_.emplace_back(x + 0.1875, y + 0.3125);
    }
  std::sort(points_.begin(), points_.end(), [](const auto& a, const auto& b) { return a.y() < b.y(); });
}

bool CorridorTest::same(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b) const {
  if (points_.empty() || a.empty() || b.empty()) return true;
  // The loop a, then b backwards; each edge adds its crossing of the ray from a point towards +x
  // to that point's winding number. An edge counts the points with y in [min y, max y): each
  // crossing once, at vertices on the ray too.
  std::vector<Eigen::Vector2d> loop;
  loop.reserve(a.size() + b.size() + 1);
  for (const auto& p : a) loop.emplace_back(p.x(), p.y());
  for (auto it = b.rbegin(); it != b.rend(); ++it) loop.emplace_back(it->x(), it->y());
  loop.push_back(loop.front());
  std::vector<int> winding(points_.size(), 0);
  const auto by_y = [](const Eigen::Vector2d& point, double y) { return point.y() < y; };
  for (std::size_t i = 0; i + 1 < loop.size(); ++i) {
    const Eigen::Vector2d& p = loop[i];
    const Eigen::Vector2d& q = loop[i + 1];
    if (p.y() == q.y()) continue;
    const double low = std::min(p.y(), q.y()), high = std::max(p.y(), q.y());
    const int direction = q.y() > p.y() ? 1 : -1;
    auto it = std::lower_bound(points_.begin(), points_.end(), low, by_y);
    for (; it != points_.end() && it->y() < high; ++it) {
      const double x = p.x() + (it->y() - p.y()) * (q.x() - p.x()) / (q.y() - p.y());
      if (x > it->x()) winding[static_cast<std::size_t>(it - points_.begin())] += direction;
    }
  }
  return std::all_of(winding.begin(), winding.end(), [](int n) { return n == 0; });
}

OptimalCorridor::OptimalCorridor(const Map& map, Cell start, Cell goal) {
  if (!dynamic_cast<const OccupancyGrid*>(&map)) return;
  optimum_ = any_angle_optimum(map, start, goal);
  if (optimum_) test_.emplace(map);
}

std::optional<bool> OptimalCorridor::contains(std::span<const Eigen::Vector3d> path) const {
  if (!optimum_ || path.empty()) return std::nullopt;
  return test_->same(path, optimum_->waypoints);
}

}  // namespace aco
