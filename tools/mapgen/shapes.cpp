// Drawing on an occupancy grid: see shapes.hpp.
#include "shapes.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "aco/error.hpp"

namespace mapgen {

void block(aco::OccupancyGrid& g, aco::Cell c) {
  if (g.contains(c)) g.set_blocked(c, true);
}

void fill_rect(aco::OccupancyGrid& g, int x0, int y0, int x1, int y1) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) block(g, {x, y});
}

void fill_ellipse(aco::OccupancyGrid& g, double cx, double cy, double rx, double ry) {
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) {
      const double u = (x - cx) / rx;
      const double v = (y - cy) / ry;
      if (u * u + v * v <= 1.0) block(g, {x, y});
    }
}

void draw_curve(aco::OccupancyGrid& g, const std::vector<Eigen::Vector2d>& points) {
  std::optional<aco::Cell> previous;
  for (const auto& p : points) {
    const aco::Cell c{static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
    if (previous && previous->x != c.x && previous->y != c.y) block(g, {c.x, previous->y});
    block(g, c);
    previous = c;
  }
}

void draw_parabola(aco::OccupancyGrid& g, Eigen::Vector2d vertex, Eigen::Vector2d axis, double k, double half_width) {
  axis.normalize();
  const Eigen::Vector2d across(-axis.y(), axis.x());
  std::vector<Eigen::Vector2d> points;
  constexpr double step = 0.05;
  const int n = static_cast<int>(std::ceil(2.0 * half_width / step));
  for (int i = 0; i <= n; ++i) {
    const double v = -half_width + 2.0 * half_width * i / n;
    points.push_back(vertex + axis * (k * v * v) + across * v);
  }
  draw_curve(g, points);
}

int blocked_cells(const aco::OccupancyGrid& g) {
  int count = 0;
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) count += g.blocked({x, y}) ? 1 : 0;
  return count;
}

std::string format_density(double p) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", p);
  return buffer;
}

bool near(aco::Cell a, aco::Cell b, int radius) {
  return std::abs(a.x - b.x) <= radius && std::abs(a.y - b.y) <= radius;
}

void scatter(aco::OccupancyGrid& g, aco::Rng& rng, double p, const std::function<bool(aco::Cell)>& keep_free) {
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) {
      const bool hit = rng.uniform() < p;
      const aco::Cell c{x, y};
      if (hit && !g.blocked(c) && !keep_free(c)) g.set_blocked(c, true);
    }
}

void scatter_isolated(aco::OccupancyGrid& g, aco::Rng& rng, int count, aco::Cell start, aco::Cell goal, int margin) {
  for (int placed = 0; placed < count; ++placed) {
    std::vector<aco::Cell> candidates;
    for (int y = 1; y + 1 < g.height(); ++y)
      for (int x = 1; x + 1 < g.width(); ++x) {
        const aco::Cell c{x, y};
        if (near(c, start, margin) || near(c, goal, margin)) continue;
        bool clear = true;
        for (int dy = -1; dy <= 1 && clear; ++dy)
          for (int dx = -1; dx <= 1 && clear; ++dx) clear = !g.blocked({x + dx, y + dy});
        if (clear) candidates.push_back(c);
      }
    if (candidates.empty()) throw aco::Error("no room left for an isolated obstacle cell");
    g.set_blocked(candidates[rng.below(candidates.size())], true);
  }
}

}  // namespace mapgen
