// One segment rule: aco::segment_free with corner cutting is the any-angle yardstick's rule
// (aco::any_angle_segment_free, aco::any_angle_path_valid). The oracle here is the yardstick's own
// former test, an exact walk over the map refined into half cells; random maps of several sizes
// and densities and random segments on the half-cell lattice (axis-aligned, diagonal, through
// cell corners, along and beyond the map's border) hold the three equal.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/graph.hpp"
#include "support.hpp"

namespace {

// The oracle, in half units: map point (x, y) is (2x + 1, 2y + 1), half cell (i, j) the unit
// square [i, i+1] x [j, j+1] of map cell (i >> 1, j >> 1).
struct Point {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

struct HalfCells {
  const aco::Map& map;
  bool operator()(std::int64_t i, std::int64_t j) const {
    if (i < 0 || j < 0 || i >= 2 * std::int64_t{map.width()} || j >= 2 * std::int64_t{map.height()}) return false;
    return map.passable({static_cast<int>(i >> 1), static_cast<int>(j >> 1)});
  }
};

// Whether the free half cells around vertex v connect the side a path comes from (direction `in`)
// to the side it leaves by (`out`): three or four free connect all, two only when not diagonal.
bool passage_ok(const HalfCells& free, Point v, Point in, Point out) {
  bool open[2][2];
  int count = 0;
  for (int qy = 0; qy < 2; ++qy)
    for (int qx = 0; qx < 2; ++qx) count += open[qy][qx] = free(v.x - 1 + qx, v.y - 1 + qy);
  const auto sides = [](std::int64_t d, bool before) -> std::pair<int, int> {
    if (d == 0) return {0, 1};
    const int q = (d > 0) == before ? 0 : 1;
    return {q, q};
  };
  const auto [bx0, bx1] = sides(in.x, true);
  const auto [by0, by1] = sides(in.y, true);
  const auto [ax0, ax1] = sides(out.x, false);
  const auto [ay0, ay1] = sides(out.y, false);
  for (int byq = by0; byq <= by1; ++byq)
    for (int bxq = bx0; bxq <= bx1; ++bxq) {
      if (!open[byq][bxq]) continue;
      for (int ayq = ay0; ayq <= ay1; ++ayq)
        for (int axq = ax0; axq <= ax1; ++axq) {
          if (!open[ayq][axq]) continue;
          const bool diagonal = bxq != axq && byq != ayq;
          if (!diagonal || count >= 3) return true;
        }
    }
  return false;
}

bool oracle_segment_free(const HalfCells& free, Point p, Point q) {
  if (p == q) return free(p.x - 1, p.y - 1) || free(p.x, p.y - 1) || free(p.x - 1, p.y) || free(p.x, p.y);
  const std::int64_t dx = q.x - p.x, dy = q.y - p.y;
  const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
  const Point dir{dx == 0 ? 0 : sx, dy == 0 ? 0 : sy};
  if (dx == 0 || dy == 0) {
    const std::int64_t n = std::max(std::llabs(dx), std::llabs(dy));
    Point v = p;
    for (std::int64_t k = 0; k < n; ++k) {
      if (k > 0 && !passage_ok(free, v, dir, dir)) return false;
      const bool edge_free = dy == 0 ? free(std::min(v.x, v.x + sx), v.y - 1) || free(std::min(v.x, v.x + sx), v.y)
                                     : free(v.x - 1, std::min(v.y, v.y + sy)) || free(v.x, std::min(v.y, v.y + sy));
      if (!edge_free) return false;
      v.x += dir.x;
      v.y += dir.y;
    }
    return true;
  }
  const std::int64_t adx = std::llabs(dx), ady = std::llabs(dy);
  std::int64_t cx = p.x + (sx > 0 ? 0 : -1), cy = p.y + (sy > 0 ? 0 : -1);
  if (!free(cx, cy)) return false;
  std::int64_t ix = 0, iy = 0;
  while (true) {
    const std::int64_t order = (ix + 1) * ady - (iy + 1) * adx;
    if (order == 0) {
      if (ix + 1 == adx) return true;
      const Point v{p.x + sx * (ix + 1), p.y + sy * (iy + 1)};
      if (!passage_ok(free, v, dir, dir)) return false;
      cx += sx;
      cy += sy;
      ++ix;
      ++iy;
    } else if (order < 0) {
      cx += sx;
      ++ix;
    } else {
      cy += sy;
      ++iy;
    }
    if (!free(cx, cy)) return false;
  }
}

bool oracle_path_valid(const HalfCells& free, std::vector<Point> path) {
  path.erase(std::unique(path.begin(), path.end()), path.end());
  if (path.size() == 1) return oracle_segment_free(free, path[0], path[0]);
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!oracle_segment_free(free, path[i], path[i + 1])) return false;
  const auto sign = [](std::int64_t v) -> std::int64_t { return (v > 0) - (v < 0); };
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const Point in{sign(path[i].x - path[i - 1].x), sign(path[i].y - path[i - 1].y)};
    const Point out{sign(path[i + 1].x - path[i].x), sign(path[i + 1].y - path[i].y)};
    if (!passage_ok(free, path[i], in, out)) return false;
  }
  return true;
}

Eigen::Vector2d planar(Point p) { return {(double(p.x) - 1) / 2, (double(p.y) - 1) / 2}; }
Eigen::Vector3d spatial(Point p) { return {(double(p.x) - 1) / 2, (double(p.y) - 1) / 2, 0.0}; }

// Random segments on the half-cell lattice of a w x h map and a margin of one cell beyond it
// (outside is blocked), of every kind the rule treats apart.
class Segments {
 public:
  Segments(std::mt19937& rng, int w, int h) : rng_(rng), w_(w), h_(h) {}

  std::array<Point, 2> next(int kind) {
    switch (kind % 7) {
      case 0:  // anywhere
        return {any(), any()};
      case 1: {  // along a row or a column, often on a grid line
        Point p = any(), q = any();
        const bool on_line = coin();
        if (coin()) {
          q.y = p.y = on_line ? even(2 * h_) : p.y;
        } else {
          q.x = p.x = on_line ? even(2 * w_) : p.x;
        }
        return {p, q};
      }
      case 2: {  // at 45 degrees
        const Point p = any();
        const std::int64_t k = between(1, 2 * std::max(w_, h_) + 2);
        return {p, {p.x + (coin() ? k : -k), p.y + (coin() ? k : -k)}};
      }
      case 3:  // through or from a cell corner, at a random slope
      case 4: {
        const Point v = corner(), d = direction();
        const std::int64_t before = between(0, 3), after = between(1, 3);
        return {Point{v.x - before * d.x, v.y - before * d.y}, Point{v.x + after * d.x, v.y + after * d.y}};
      }
      case 5: {  // from the border, along it or into the map
        const auto border = [&] {
          return coin() ? Point{coin() ? 0 : 2 * w_, between(-1, 2 * h_ + 1)}
                        : Point{between(-1, 2 * w_ + 1), coin() ? 0 : 2 * h_};
        };
        const Point p = border();
        return {p, coin() ? border() : any()};
      }
      default: {  // a point
        const Point p = any();
        return {p, p};
      }
    }
  }
  Point any() { return {between(-2, 2 * w_ + 2), between(-2, 2 * h_ + 2)}; }
  // Into a cell corner from one side and out of it to another.
  std::vector<Point> turn_at_corner() {
    const Point v = corner(), in = direction(), out = direction();
    const std::int64_t before = between(1, 3), after = between(1, 3);
    return {{v.x - before * in.x, v.y - before * in.y}, v, {v.x + after * out.x, v.y + after * out.y}};
  }

 private:
  std::int64_t between(std::int64_t low, std::int64_t high) {
    return std::uniform_int_distribution<std::int64_t>(low, high)(rng_);
  }
  std::int64_t even(std::int64_t high) { return 2 * between(0, high / 2); }
  bool coin() { return between(0, 1) == 1; }
  Point corner() { return {even(2 * w_), even(2 * h_)}; }
  Point direction() {
    while (true)
      if (const Point d{between(-3, 3), between(-3, 3)}; !(d == Point{})) return d;
  }

  std::mt19937& rng_;
  std::int64_t w_, h_;
};

std::string describe(const aco::OccupancyGrid& map, Point p, Point q) {
  std::ostringstream out;
  out << "(" << planar(p).x() << ", " << planar(p).y() << ") -> (" << planar(q).x() << ", " << planar(q).y()
      << ") on\n";
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) out << (map.passable({x, y}) ? '.' : '#');
    out << "\n";
  }
  return out.str();
}

}  // namespace

TEST_CASE("segment_free with corner cutting is the any-angle rule on random maps", "[segment_free][any_angle]") {
  const std::array<std::array<int, 2>, 9> sizes = {
      {{1, 1}, {1, 6}, {7, 1}, {2, 2}, {5, 4}, {9, 8}, {16, 16}, {33, 20}, {64, 64}}};
  const std::array<double, 6> densities = {0.0, 0.1, 0.25, 0.4, 0.6, 0.85};
  int segments = 0, free_segments = 0, failures = 0, paths = 0, valid_paths = 0;
  std::uint32_t seed = 1;
  for (const auto& [w, h] : sizes)
    for (const double density : densities) {
      std::mt19937 rng(seed++);
      aco::OccupancyGrid map(w, h, "random");
      std::bernoulli_distribution blocked(density);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) map.set_blocked({x, y}, blocked(rng));
      const HalfCells free{map};
      Segments random(rng, w, h);
      for (int k = 0; k < 3000; ++k) {
        const auto [p, q] = random.next(k);
        const bool expected = oracle_segment_free(free, p, q);
        const bool same = aco::segment_free(map, planar(p), planar(q), true) == expected &&
                          aco::segment_free(map, planar(q), planar(p), true) == expected &&
                          aco::any_angle_segment_free(map, spatial(p), spatial(q)) == expected;
        if (!same && ++failures <= 10) {
          INFO(describe(map, p, q) << "oracle: " << expected);
          CHECK(aco::segment_free(map, planar(p), planar(q), true) == expected);
          CHECK(aco::segment_free(map, planar(q), planar(p), true) == expected);
          CHECK(aco::any_angle_segment_free(map, spatial(p), spatial(q)) == expected);
        }
        ++segments;
        free_segments += expected;
      }
      // Polylines: turns at cell corners, where the turn rule decides, and random chains.
      for (int k = 0; k < 1000; ++k) {
        std::vector<Point> path;
        if (k % 2 == 0) {
          path = random.turn_at_corner();
        } else {
          const auto [p, q] = random.next(k);
          path = {p, q};
          for (int more = k % 3; more > 0; --more) path.push_back(random.next(k + more)[1]);
        }
        std::vector<Eigen::Vector3d> points;
        for (const Point& point : path) points.push_back(spatial(point));
        const bool expected = oracle_path_valid(free, path);
        if (aco::any_angle_path_valid(map, points) != expected && ++failures <= 10) {
          INFO(describe(map, path.front(), path.back()) << path.size() << " points, oracle: " << expected);
          CHECK(aco::any_angle_path_valid(map, points) == expected);
        }
        ++paths;
        valid_paths += expected;
      }
    }
  CHECK(failures == 0);
  // Both answers are common enough to mean something.
  CHECK(free_segments > segments / 10);
  CHECK(segments - free_segments > segments / 10);
  CHECK(valid_paths > paths / 20);
}
