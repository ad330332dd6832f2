#include "aco/corridor.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace aco {

std::vector<Cell> obstacles_inside(const Map& map) {
  const int w = map.width(), h = map.height();
  // The blocked cells in a frame of free ones, read from the map once: the flood then reads
  // bytes (on a 2048x2048 cave, millions of blocked cells with eight neighbours each) and needs
  // no bounds test.
  enum : std::uint8_t { kFree, kBlocked, kSeen };
  const std::ptrdiff_t row = w + 2;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(row) * (h + 2), kFree);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (!map.passable({x, y})) cells[static_cast<std::size_t>((y + 1) * row + x + 1)] = kBlocked;
  const std::ptrdiff_t around[] = {-row - 1, -row, -row + 1, -1, 1, row - 1, row, row + 1};
  std::vector<std::ptrdiff_t> stack;
  std::vector<Cell> inside;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::ptrdiff_t first = (y + 1) * row + x + 1;
      if (cells[static_cast<std::size_t>(first)] != kBlocked) continue;
      bool edge = false;
      cells[static_cast<std::size_t>(first)] = kSeen;
      stack.push_back(first);
      while (!stack.empty()) {
        const std::ptrdiff_t c = stack.back();
        stack.pop_back();
        const std::ptrdiff_t cy = c / row - 1, cx = c % row - 1;
        edge = edge || cx == 0 || cy == 0 || cx == w - 1 || cy == h - 1;
        for (const std::ptrdiff_t step : around)
          if (std::uint8_t& n = cells[static_cast<std::size_t>(c + step)]; n == kBlocked) {
            n = kSeen;
            stack.push_back(c + step);
          }
      }
      if (!edge) inside.push_back({x, y});
    }
  return inside;
}

CorridorTest::CorridorTest(const Map& map) {
  // Inside the cell, off every half-cell line a grid path or an any-angle path runs along:
  // no path passes through it, and the ray from it meets path vertices only by accident.
  for (const Cell& c : obstacles_inside(map)) points_.emplace_back(c.x + 0.1875, c.y + 0.3125);
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

namespace {

// SplitMix64's finaliser: well-spread keys from the obstacles' numbers, the same on every run.
std::uint64_t obstacle_key(std::uint64_t n) {
  std::uint64_t z = n * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

CorridorKeys::CorridorKeys(const Map& map)
    : width_(map.width()), height_(map.height()), row_begin_(static_cast<std::size_t>(map.height()) + 1, 0) {
  const std::vector<Cell> cells = obstacles_inside(map);
  obstacles_ = cells.size();
  std::vector<std::size_t> order(cells.size());  // by row, then by x; an obstacle's key is its number's
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cells[a].y != cells[b].y ? cells[a].y < cells[b].y : cells[a].x < cells[b].x;
  });
  for (const Cell& c : cells) ++row_begin_[static_cast<std::size_t>(c.y) + 1];
  for (int y = 0; y < height_; ++y)
    row_begin_[static_cast<std::size_t>(y) + 1] += row_begin_[static_cast<std::size_t>(y)];
  ray_x_.reserve(cells.size());
  up_to_.reserve(cells.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Cell c = cells[order[k]];
    const bool first_of_row = k == row_begin_[static_cast<std::size_t>(c.y)];
    ray_x_.push_back(c.x);
    up_to_.push_back(obstacle_key(order[k] + 1) + (first_of_row ? 0 : up_to_.back()));  // running sums along the row
  }
}

// The keys of the rays a segment crosses, signed. The ray of the obstacle in cell (ox, oy) runs
// along y = oy - epsilon from x = ox on: a segment from a to b crosses it towards larger y when
// ay < oy <= by and the segment's x at y = oy is larger than ox (it cannot equal ox, the centre
// of a blocked cell, on a valid path), and back when by < oy <= ay.
std::uint64_t CorridorKeys::crossing(double ax, double ay, double bx, double by) const {
  if (ay == by) return 0;
  const bool down = by > ay;  // towards larger y
  const double low = down ? ay : by, high = down ? by : ay;
  std::uint64_t sum = 0;
  const auto first = static_cast<std::int64_t>(std::max(0.0, std::floor(low) + 1.0));
  const auto last = static_cast<std::int64_t>(std::min<double>(height_ - 1.0, std::floor(high)));
  for (std::int64_t r = first; r <= last; ++r) {
    // The obstacles of the row left of x: those with ox <= floor(x) (ox == x is impossible).
    const double x = std::floor(ax + (bx - ax) * (double(r) - ay) / (by - ay));
    if (x >= 0.0) sum += keys_up_to(static_cast<int>(r), static_cast<int>(std::min<double>(x, width_ - 1.0)));
  }
  return down ? sum : std::uint64_t{0} - sum;
}

std::uint64_t CorridorKeys::key(std::span<const Eigen::Vector3d> path) const {
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    sum += crossing(path[i].x(), path[i].y(), path[i + 1].x(), path[i + 1].y());
  return sum;
}

// crossing()'s rule, with a one-row step (every step of the 4- and 8-neighbourhoods) in integers:
// it crosses the rays of the lower cell's row (larger y) at that cell's x. A 2D graph numbers its
// nodes as the cells, row by row, so a node's column is its offset from its row's first. Its row is found from
// the last node's without a division where it is the same or the next one up or down: this runs
// on every walk that arrives, and on a 20x20 map a division per node was 8 % of a run.
std::uint64_t CorridorKeys::key(const Graph& graph, std::span<const NodeId> walk) const {
  if (walk.empty()) return 0;
  std::uint64_t sum = 0;
  const std::int64_t width = graph.width;
  int row = walk[0] / graph.width;
  for (std::size_t i = 0; i + 1 < walk.size(); ++i) {
    const NodeId a = walk[i], b = walk[i + 1];
    const std::int64_t row_begin = row * width, column = b - row_begin;
    const int next_row = column >= 0 && column < width           ? row
                         : column >= width && column < 2 * width ? row + 1
                         : column < 0 && column >= -width        ? row - 1
                                                                 : b / graph.width;
    if (next_row == row + 1)
      sum += keys_up_to(next_row, static_cast<int>(column - width));
    else if (next_row == row - 1)
      sum -= keys_up_to(row, static_cast<int>(a - row_begin));
    else if (next_row != row)
      sum += crossing(a % graph.width, row, b % graph.width, next_row);
    row = next_row;
  }
  return sum;
}

OptimalCorridor::OptimalCorridor(const Map& map, Cell start, Cell goal) {
  if (!dynamic_cast<const OccupancyGrid*>(&map)) return;
  optimum_ = any_angle_optimum(map, start, goal);
  if (!optimum_) return;
  test_.emplace(map);
  optimum_key_ = CorridorKeys(map).key(optimum_->waypoints);
}

std::optional<bool> OptimalCorridor::contains(std::span<const Eigen::Vector3d> path) const {
  if (!optimum_ || path.empty()) return std::nullopt;
  return test_->same(path, optimum_->waypoints);
}

std::optional<bool> OptimalCorridor::among(std::span<const std::uint64_t> corridor_keys) const {
  if (!optimum_) return std::nullopt;
  return std::find(corridor_keys.begin(), corridor_keys.end(), optimum_key_) != corridor_keys.end();
}

}  // namespace aco
