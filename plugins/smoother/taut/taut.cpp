// The taut path in the grid path's corridor (issue 40): the shortest continuous path among those
// that stay within a few cells of the grid path, found by the framework's exact any-angle search
// (Anya) on a cropped map where only the corridor is free, and re-run on the corridor of its own
// result until it stops getting shorter. On maps whose positions are not the cells' plane
// (terrains: heights, cell size) and with a clearance, Anya's rule does not fit; there the plugin
// pulls the string over the grid path's nodes and takes a shortcut only when it is shorter over
// the surface and, with a clearance, keeps clear. README.md gives the readings.
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstddef>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  int corridor_width = 2;
  int rounds = 4;
  double clearance = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("corridor_width", &Parameters::corridor_width, "0:64",
               "cells added around the path on every side to make the corridor the search may use"),
    aco::field("rounds", &Parameters::rounds, "1:100",
               "most any-angle searches, each in the corridor of the last one's path; stops early once no shorter"),
    aco::field("clearance", &Parameters::clearance, "0:0.5",
               "a robot's radius: shortcuts must pass this far from every blocked cell (smoother/prune's rule, over "
               "the grid path's nodes); 0 = the taut path, which may graze obstacle corners"),
});

// Whether the graph's positions are its cells' (x, y) in the plane, as Anya's geometry assumes.
bool planar(const aco::Graph& g, std::span<const aco::NodeId> path) {
  return std::all_of(path.begin(), path.end(), [&g](aco::NodeId n) {
    const aco::Cell c = g.cell(n);
    return g.position(n) == Eigen::Vector3d(c.x, c.y, 0.0);
  });
}

// The points of the straight segment from cell a's centre to cell b's, b included, a not, where it
// crosses the columns (or rows, when it is steeper) of cell centres, each at the height linearly
// interpolated between the two cells it passes between: the surface the graph's steps measure (a
// step costs the 3D distance of two cell centres) continued along the segment. A neighbour
// without height data (NODATA, outside the map) gives way to the cell the segment is in.
aco::Waypoints over_surface(const aco::Map& map, aco::Cell a, aco::Cell b) {
  const int dx = b.x - a.x, dy = b.y - a.y;
  const int steps = std::max(std::abs(dx), std::abs(dy));
  const bool along_x = std::abs(dx) >= std::abs(dy);
  aco::Waypoints points;
  for (int k = 1; k <= steps; ++k) {
    const double major = along_x ? a.x + double(k) * dx / steps : a.y + double(k) * dy / steps;
    const double minor = along_x ? a.y + double(k) * dy / steps : a.x + double(k) * dx / steps;
    const int low = static_cast<int>(std::floor(minor));
    const double f = minor - low;
    const int m = static_cast<int>(std::lround(major));
    const aco::Cell c0 = along_x ? aco::Cell{m, low} : aco::Cell{low, m};
    const aco::Cell c1 = along_x ? aco::Cell{m, low + 1} : aco::Cell{low + 1, m};
    const Eigen::Vector3d p0 = map.position(c0), p1 = map.position(c1);
    Eigen::Vector3d p = (1 - f) * p0 + f * p1;
    if (f == 0.0)
      p = p0;
    else if (!(map.contains(c0) && map.contains(c1) && std::isfinite(p0.z()) && std::isfinite(p1.z())))
      p.z() = (f < 0.5 ? p0 : p1).z();
    points.push_back(p);
  }
  return points;
}

// String pulling over the grid path's nodes: the farthest later node whose segment is in line of
// sight (the graph's corner rule), keeps the clearance and is no longer over the surface than the
// grid steps it replaces. The waypoints follow the surface between kept nodes.
aco::Waypoints pull_over_nodes(const aco::Graph& g, std::span<const aco::NodeId> path, double clearance, bool surface) {
  std::vector<double> along(path.size(), 0.0);  // grid length from path[0] to path[k]
  for (std::size_t k = 1; k < path.size(); ++k) along[k] = along[k - 1] + g.distance(path[k - 1], path[k]);
  const aco::Map& map = *g.map;
  const auto segment = [&](std::size_t i, std::size_t j) {
    if (!surface) return aco::Waypoints{g.position(path[j])};
    aco::Waypoints points = over_surface(map, g.cell(path[i]), g.cell(path[j]));
    points.back() = g.position(path[j]);
    return points;
  };
  const auto can_join = [&](std::size_t i, std::size_t j) {
    const aco::Cell from = g.cell(path[i]), to = g.cell(path[j]);
    if (!aco::line_of_sight(map, from, to, g.options.corner_cutting)) return false;
    if (clearance > 0.0 && !aco::keeps_clear(map, from, to, clearance)) return false;
    if (!surface) return true;  // a straight segment in the plane is never longer (triangle inequality)
    aco::Waypoints points = segment(i, j);
    points.insert(points.begin(), g.position(path[i]));
    // Equal lengths still join, to drop the nodes of a straight run.
    return aco::polyline_length(points) <= (along[j] - along[i]) * (1 + 1e-12);
  };
  const std::vector<std::size_t> kept = aco::greedy_shortcuts(path.size(), 0, can_join);
  aco::Waypoints points{g.position(path[kept.front()])};
  for (std::size_t k = 1; k < kept.size(); ++k)
    for (const Eigen::Vector3d& p : segment(kept[k - 1], kept[k])) {
      // A sample where the surface keeps its slope adds nothing but a waypoint.
      if (points.size() >= 2) {
        const Eigen::Vector3d before = points.back() - points[points.size() - 2], after = p - points.back();
        if (before.cross(after).norm() <= 1e-12 * before.norm() * after.norm() && before.dot(after) > 0)
          points.pop_back();
      }
      points.push_back(p);
    }
  return points;
}

// Adds the cells whose closed square the polyline touches: sampled every quarter cell, with every
// cell a sample lies on the border of. A sliver of a cell the samples skip is within one cell of a
// sampled one, so a corridor width of 1 or more covers it.
void add_touched_cells(const aco::Waypoints& points, std::vector<aco::Cell>& cells) {
  const auto add_point = [&cells](double x, double y) {
    for (int cy = static_cast<int>(std::ceil(y - 0.5 - 1e-9)); cy <= static_cast<int>(std::floor(y + 0.5 + 1e-9)); ++cy)
      for (int cx = static_cast<int>(std::ceil(x - 0.5 - 1e-9)); cx <= static_cast<int>(std::floor(x + 0.5 + 1e-9));
           ++cx)
        cells.push_back({cx, cy});
  };
  if (points.size() == 1) add_point(points[0].x(), points[0].y());
  for (std::size_t k = 1; k < points.size(); ++k) {
    const Eigen::Vector3d& a = points[k - 1];
    const Eigen::Vector3d& b = points[k];
    const int samples = static_cast<int>(std::ceil(4 * (b - a).head<2>().norm()));
    for (int s = 0; s <= samples; ++s) {
      const double t = samples == 0 ? 0.0 : double(s) / samples;
      add_point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
    }
  }
}

// The shortest valid path (any_angle.hpp's rule) from start to goal through the cells within
// `width` of `cells` that are free on the map, searched on a map cropped to them. None once the
// run's time limit has passed (Context::deadline), the search given up.
std::optional<aco::AnyAnglePath> shortest_in_corridor(const aco::Context& c, const aco::Map& map,
                                                      const std::vector<aco::Cell>& cells, int width, aco::Cell start,
                                                      aco::Cell goal) {
  int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;
  for (const aco::Cell& c : cells) {
    x0 = std::min(x0, c.x), y0 = std::min(y0, c.y), x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
  }
  x0 = std::max(0, x0 - width), y0 = std::max(0, y0 - width);
  x1 = std::min(map.width() - 1, x1 + width), y1 = std::min(map.height() - 1, y1 + width);
  aco::OccupancyGrid corridor(x1 - x0 + 1, y1 - y0 + 1, map.name());
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) corridor.set_blocked({x - x0, y - y0}, true);
  for (const aco::Cell& c : cells)
    for (int y = std::max(y0, c.y - width); y <= std::min(y1, c.y + width); ++y)
      for (int x = std::max(x0, c.x - width); x <= std::min(x1, c.x + width); ++x)
        if (map.passable({x, y})) corridor.set_blocked({x - x0, y - y0}, false);
  aco::AnyAngleSearch search(corridor);
  if (c.past_deadline()) return std::nullopt;
  auto found =
      search.find({start.x - x0, start.y - y0}, {goal.x - x0, goal.y - y0}, [&c] { return c.past_deadline(); });
  if (found)
    for (Eigen::Vector3d& p : found->waypoints) p += Eigen::Vector3d(x0, y0, 0.0);
  return found;
}

class TautSmoother final : public aco::Smoother {
 public:
  explicit TautSmoother(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  std::vector<Eigen::Vector3d> smooth(const aco::Context& c, std::span<const aco::NodeId> path) const override {
    const aco::Graph& g = *c.graph;
    if (path.size() <= 1) return aco::to_waypoints(g, path);
    const bool flat = planar(g, path);
    aco::Waypoints best = pull_over_nodes(g, path, p_.clearance, !flat);
    if (!flat || p_.clearance > 0.0) return best;
    // The pulled string seeds the corridor: it already cuts across open ground, where dilating the
    // grid path's cells would take many rounds to reach.
    double best_length = aco::polyline_length(best);
    std::vector<aco::Cell> cells;
    for (const aco::NodeId n : path) cells.push_back(g.cell(n));
    add_touched_cells(best, cells);
    // Within a time limit a round begins only where one as long as the last still ends before it.
    std::chrono::steady_clock::duration last_round{};
    for (int round = 0; round < p_.rounds && c.leaves_time_for(last_round); ++round) {
      const auto round_began = std::chrono::steady_clock::now();
      const auto found =
          shortest_in_corridor(c, *g.map, cells, p_.corridor_width, g.cell(path.front()), g.cell(path.back()));
      if (!found || !(found->length < best_length * (1 - 1e-12))) break;
      best = found->waypoints;
      best_length = found->length;
      cells.clear();
      add_touched_cells(best, cells);
      last_round = std::chrono::steady_clock::now() - round_began;
    }
    // Exactly the nodes' positions at the ends, whatever the search's arithmetic.
    best.front() = g.position(path.front());
    best.back() = g.position(path.back());
    return best;
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(smoother, taut, TautSmoother, "1.0",
           "the shortest continuous path in the grid path's corridor (exact any-angle search, Anya)", kParams)
