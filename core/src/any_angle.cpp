#include "aco/any_angle.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "aco/best_first.hpp"
#include "aco/error.hpp"

namespace aco {

// Everything below works on the grid refined into half cells, in integer "half units": a point
// (x, y) of the map is (2x + 1, 2y + 1) here, so cell centres and cell corners are both grid
// vertices. Half cell (i, j) is the unit square [i, i+1] x [j, j+1], part of map cell
// (i >> 1, j >> 1). The refinement keeps the rule: a blocked cell is four blocked half cells, and
// the rule's edges and vertices inside it are between blocked half cells. Row Y is the line y = Y;
// strip j the half cells between rows j and j + 1.
namespace {

struct Point {
  std::int64_t x = 0;
  std::int64_t y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

double distance(Point a, Point b) { return std::hypot(double(a.x - b.x), double(a.y - b.y)); }

// The map point a point in half units is.
Eigen::Vector2d map_point(Point p) { return {(double(p.x) - 1) / 2, (double(p.y) - 1) / 2}; }

// Half cell (i, j) of a map is free when its map cell is passable.
struct MapFree {
  const Map& map;
  bool operator()(std::int64_t i, std::int64_t j) const {
    if (i < 0 || j < 0 || i >= 2 * std::int64_t{map.width()} || j >= 2 * std::int64_t{map.height()}) return false;
    return map.passable({static_cast<int>(i >> 1), static_cast<int>(j >> 1)});
  }
};

// Whether the free half cells around vertex v connect the side a path comes from (direction
// `in`, pointing into v) to the side it leaves by (direction `out`). A side is the cell the path
// is inside next to v, or the edge it runs along (its two cells). The free cells around v
// connect through shared edges: three or four free connect all, two only when not diagonal.
bool passage_ok(const MapFree& free, Point v, Point in, Point out) {
  // The four cells as quadrants (qx, qy): cell (v.x - 1 + qx, v.y - 1 + qy).
  bool open[2][2];
  int count = 0;
  for (int qy = 0; qy < 2; ++qy)
    for (int qx = 0; qx < 2; ++qx) count += open[qy][qx] = free(v.x - 1 + qx, v.y - 1 + qy);
  // The quadrants beside the point v - eps * in (before) and v + eps * out (after): a quadrant
  // component is 0 or 1 where the direction says which, both where it is along the line.
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

// A map point (2x + 1 and 2y + 1 integers) in half units, or an Error.
Point half_units(const Eigen::Vector3d& point) {
  const auto one = [&](double v) {
    const double h = 2.0 * v + 1.0;
    if (!std::isfinite(h) || h != std::nearbyint(h) || std::fabs(h) > 1e15)
      throw Error("any-angle rule: point (" + std::to_string(point.x()) + ", " + std::to_string(point.y()) +
                  ") is not on the half-cell lattice (cell centres and corners)");
    return static_cast<std::int64_t>(h);
  };
  return {one(point.x()), one(point.y())};
}

// An exact rational n / d, d > 0, reduced. Interval ends on a row are projections along lines
// through two grid points, so d stays below the grid's height and products fit in 64 bits.
struct Rational {
  std::int64_t n = 0;
  std::int64_t d = 1;
  static Rational make(std::int64_t n, std::int64_t d) {
    if (d < 0) n = -n, d = -d;
    const std::int64_t g = std::gcd(n, d);
    return g > 1 ? Rational{n / g, d / g} : Rational{n, d};
  }
  static Rational of(std::int64_t v) { return {v, 1}; }
  double value() const { return double(n) / double(d); }
  bool is(std::int64_t v) const { return d == 1 && n == v; }
  friend bool operator<(const Rational& a, const Rational& b) { return a.n * b.d < b.n * a.d; }
  friend bool operator<=(const Rational& a, const Rational& b) { return a.n * b.d <= b.n * a.d; }
  friend bool operator==(const Rational& a, const Rational& b) { return a.n == b.n && a.d == b.d; }
};

Rational min(Rational a, Rational b) { return b < a ? b : a; }
Rational max(Rational a, Rational b) { return a < b ? b : a; }

// Where the line from r through point (p, row) meets row `to`.
Rational project(Point r, Rational p, std::int64_t row, std::int64_t to) {
  std::int64_t k_num = to - r.y, k_den = row - r.y;
  if (k_den < 0) k_num = -k_num, k_den = -k_den;
  return Rational::make(r.x * p.d * k_den + (p.n - r.x * p.d) * k_num, p.d * k_den);
}

}  // namespace

struct AnyAngleSearch::State {
  static constexpr double kTie = 1e-9;  // g values closer than this (half units) are one
  struct Root {
    Point at;
    double g = 0.0;
    int parent = -1;
  };
  enum class Kind : std::uint8_t { cone, flat };
  struct Node {
    Rational a, b;  // the interval [a, b] on row y
    std::int64_t y = 0;
    int root = 0;
    Kind kind = Kind::cone;
    std::int8_t dir = 0;  // a flat node's direction along the row, away from its root
    bool goal = false;  // the goal lies in the interval
    double f = 0.0;
    double g = 0.0;
  };
  struct Later {
    bool operator()(const Node& x, const Node& y) const { return x.f != y.f ? x.f > y.f : x.g < y.g; }
  };

  const Map& map;
  std::int64_t w = 0, h = 0;  // the map's size in cells
  std::vector<std::uint8_t> open;  // per map cell: passable
  std::vector<std::vector<std::pair<std::int64_t, std::int64_t>>> runs;  // per map row: free runs [L, R) in half units
  std::vector<std::vector<std::int64_t>> corners;  // per map vertex row: the corners' x in half units, sorted

  // Per query.
  Point goal;
  std::vector<Root> roots;
  std::vector<double> best;  // per map vertex: the least g it was a root with, valid where stamped
  std::vector<std::uint32_t> stamp;
  std::uint32_t current = 0;
  std::priority_queue<Node, std::vector<Node>, Later> queue;
  std::size_t expanded = 0;

  explicit State(const Map& m) : map(m), w(m.width()), h(m.height()) {
    open.resize(static_cast<std::size_t>(w * h));
    // The taut smoother's corridors are plain grids the size of the path's bounding box, searched
    // up to four times a run.
    with_concrete_map(m, [this](const auto& concrete) { fill_open(concrete); });
    runs.resize(h);
    for (std::int64_t y = 0; y < h; ++y)
      for (std::int64_t x = 0; x < w;) {
        if (!open[y * w + x]) {
          ++x;
          continue;
        }
        std::int64_t end = x;
        while (end < w && open[y * w + end]) ++end;
        runs[y].push_back({2 * x, 2 * end});
        x = end;
      }
    // A corner touches three free cells: only the vertices of free cells are tried, row by row
    // (a corridor is a thin band of its bounding box).
    corners.resize(h + 1);
    for (std::int64_t y = 0; y < h; ++y)
      for (const auto& [left, right] : runs[y])
        for (std::int64_t v = y; v <= y + 1; ++v)
          for (std::int64_t u = left / 2; u <= right / 2; ++u)
            if (is_corner(2 * u, 2 * v)) corners[v].push_back(2 * u);
    for (auto& row : corners) {
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
    }
    best.resize(static_cast<std::size_t>((w + 1) * (h + 1)));
    stamp.resize(best.size(), 0);
  }

  template <class M>
  void fill_open(const M& m) {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) open[y * w + x] = m.passable({x, y}) ? 1 : 0;
  }

  bool cell(std::int64_t x, std::int64_t y) const { return x >= 0 && y >= 0 && x < w && y < h && open[y * w + x]; }
  bool free(std::int64_t i, std::int64_t j) const { return cell(i >> 1, j >> 1); }

  // A convex obstacle corner: a vertex with exactly one blocked cell around it (map vertices only).
  bool is_corner(std::int64_t x, std::int64_t y) const {
    if ((x & 1) || (y & 1) || x <= 0 || y <= 0 || x >= 2 * w || y >= 2 * h) return false;
    const std::int64_t u = x / 2, v = y / 2;
    return !cell(u - 1, v - 1) + !cell(u, v - 1) + !cell(u - 1, v) + !cell(u, v) == 1;
  }
  // Whether a path along row y may pass through vertex x.
  bool row_passage(std::int64_t x, std::int64_t y) const {
    return (free(x - 1, y - 1) && free(x, y - 1)) || (free(x - 1, y) && free(x, y));
  }

  const std::vector<std::pair<std::int64_t, std::int64_t>>& strip_runs(std::int64_t j) const {
    static const std::vector<std::pair<std::int64_t, std::int64_t>> none;
    return j < 0 || j >= 2 * h ? none : runs[j >> 1];
  }
  // The free run [L, R) of strip j holding half-cell column i (which must be free).
  std::pair<std::int64_t, std::int64_t> run_at(std::int64_t j, std::int64_t i) const {
    const auto& list = strip_runs(j);
    auto it =
        std::upper_bound(list.begin(), list.end(), i, [](std::int64_t v, const auto& run) { return v < run.first; });
    return *std::prev(it);
  }

  // The end of a flat walk from x along row y in direction dir: at the first corner, or where it
  // can go no further; x itself when it cannot move.
  std::int64_t walk(std::int64_t x, std::int64_t y, int dir) const {
    while (true) {
      const std::int64_t column = dir > 0 ? x : x - 1;
      if (!free(column, y - 1) && !free(column, y)) return x;
      x += dir;
      if (is_corner(x, y) || !row_passage(x, y)) return x;
    }
  }

  double heuristic(const Node& n) const {
    const Point r = roots[n.root].at;
    const double a = n.a.value(), b = n.b.value(), row = double(n.y);
    const double rx = double(r.x), ry = double(r.y), gx = double(goal.x);
    double gy = double(goal.y);
    if ((r.y < n.y && goal.y < n.y) || (r.y > n.y && goal.y > n.y)) gy = 2.0 * row - gy;  // mirrored
    double px;
    if (goal.y == n.y || gy == row)
      px = gx;
    else if (r.y == n.y)
      px = rx;
    else
      px = rx + (gx - rx) * (row - ry) / (gy - ry);
    px = std::clamp(px, a, b);
    return std::hypot(px - rx, row - ry) + std::hypot(gx - px, gy - row);
  }

  void push(Rational a, Rational b, std::int64_t y, int root, Kind kind, int dir = 0) {
    Node n{a, b, y, root, kind, static_cast<std::int8_t>(dir)};
    n.goal = y == goal.y && a <= Rational::of(goal.x) && Rational::of(goal.x) <= b;
    n.g = roots[root].g;
    n.f = n.g + heuristic(n);
    queue.push(n);
  }
  // A cone interval on row y, split at the corners inside it.
  void push_cone(Rational a, Rational b, std::int64_t y, int root) {
    if ((y & 1) == 0 && y > 0 && y < 2 * h) {
      const auto& list = corners[y / 2];
      const auto before = [](const Rational& v, std::int64_t x) { return v < Rational::of(x); };
      for (auto it = std::upper_bound(list.begin(), list.end(), a, before); it != list.end() && Rational::of(*it) < b;
           ++it) {
        push(a, Rational::of(*it), y, root, Kind::cone);
        a = Rational::of(*it);
      }
    }
    push(a, b, y, root, Kind::cone);
  }
  void push_flat(std::int64_t from, std::int64_t y, int dir, int root) {
    const std::int64_t to = walk(from, y, dir);
    if (to == from) return;
    push(Rational::of(std::min(from, to)), Rational::of(std::max(from, to)), y, root, Kind::flat, dir);
  }

  std::size_t vertex_index(Point p) const { return static_cast<std::size_t>((p.y / 2) * (w + 1) + p.x / 2); }
  // A new root at corner p reached from root `parent`; -1 when p already is a root with a g as
  // small (to kTie). The successors of a root depend on the root it was reached from and on p
  // alone, so a second arrival from the same root would repeat them, and an arrival from another
  // root at the same cost continues as well: a taut continuation of one is taut for the other, or
  // a shortcut of it would be shorter than optimal.
  int new_root(Point p, int parent) {
    const double g = roots[parent].g + distance(roots[parent].at, p);
    const std::size_t i = vertex_index(p);
    if (stamp[i] == current && g >= best[i] - kTie) return -1;
    stamp[i] = current;
    best[i] = g;
    roots.push_back({p, g, parent});
    return static_cast<int>(roots.size()) - 1;
  }
  bool stale(const Node& n) const {
    if (n.root == 0) return false;
    const std::size_t i = vertex_index(roots[n.root].at);
    return roots[n.root].g > best[i] + kTie;
  }

  void expand_flat(const Node& n) {
    const std::int64_t y = n.y;
    const std::int64_t p = n.dir > 0 ? n.b.n : n.a.n;  // the far end, a vertex
    if (row_passage(p, y)) push_flat(p, y, n.dir, n.root);
    if (!is_corner(p, y)) return;
    // Turning at p: the blocked cell is behind p, above or below the row.
    const std::int64_t behind = n.dir > 0 ? p - 1 : p, ahead = n.dir > 0 ? p : p - 1;
    for (const std::int64_t strip : {y - 1, y}) {
      if (free(behind, strip)) continue;
      const int root = new_root({p, y}, n.root);
      if (root < 0) return;
      const auto [left, right] = run_at(strip, ahead);
      push_cone(Rational::of(left), Rational::of(right), strip == y ? y + 1 : y - 1, root);
    }
  }

  void expand_cone(const Node& n) {
    const Point r = roots[n.root].at;
    const std::int64_t y = n.y;
    const int d = y > r.y ? 1 : -1;
    const std::int64_t next = y + d;
    const std::int64_t far = d > 0 ? y : y - 1;  // the strip between y and next
    const std::int64_t near = d > 0 ? y - 1 : y;  // the strip on the root's side of y
    const auto project_to_next = [&](Rational p) { return project(r, p, y, next); };
    const auto back = [&](std::int64_t x) {  // the point of row y that projects to (x, next)
      return Rational::make(r.x * (next - r.y) + (x - r.x) * (y - r.y), next - r.y);
    };
    // Observable: the rays through the interval that cross the next strip inside one free run.
    const Rational pa = project_to_next(n.a), pb = project_to_next(n.b);
    const Rational low = min(n.a, pa), high = max(n.b, pb);
    for (const auto& [left, right] : strip_runs(far)) {
      if (Rational::of(right) < low) continue;
      if (high < Rational::of(left)) break;
      const Rational lo = max(max(n.a, Rational::of(left)), back(left));
      const Rational hi = min(min(n.b, Rational::of(right)), back(right));
      if (hi < lo) continue;
      // A single ray through the run's end vertex: it passes between two diagonal blocked cells
      // unless the cell on the root's side beyond that vertex is free.
      if (lo == hi && ((lo.is(left) && !free(left, near)) || (lo.is(right) && !free(right - 1, near)))) continue;
      push_cone(project_to_next(lo), project_to_next(hi), next, n.root);
    }
    // Non-observable: the interval ends at a corner the path can turn around.
    if (n.b.d == 1 && is_corner(n.b.n, y)) {
      const std::int64_t x = n.b.n;
      const Rational t = project_to_next(n.b);
      if (!free(x, near)) {  // the obstacle is on the root's side, right of x
        const int root = new_root({x, y}, n.root);
        if (root >= 0) {
          push_flat(x, y, 1, root);
          const auto [left, right] = run_at(far, x);
          if (t < Rational::of(right)) push_cone(t, Rational::of(right), next, root);
        }
      } else if (!free(x, far) && t < Rational::of(x)) {  // beyond the row, right of x
        const int root = new_root({x, y}, n.root);
        if (root >= 0) {
          const auto [left, right] = run_at(far, x - 1);
          push_cone(max(t, Rational::of(left)), Rational::of(x), next, root);
        }
      }
    }
    if (n.a.d == 1 && is_corner(n.a.n, y)) {
      const std::int64_t x = n.a.n;
      const Rational t = project_to_next(n.a);
      if (!free(x - 1, near)) {  // the obstacle is on the root's side, left of x
        const int root = new_root({x, y}, n.root);
        if (root >= 0) {
          push_flat(x, y, -1, root);
          const auto [left, right] = run_at(far, x - 1);
          if (Rational::of(left) < t) push_cone(Rational::of(left), t, next, root);
        }
      } else if (!free(x - 1, far) && Rational::of(x) < t) {  // beyond the row, left of x
        const int root = new_root({x, y}, n.root);
        if (root >= 0) {
          const auto [left, right] = run_at(far, x);
          push_cone(Rational::of(x), min(t, Rational::of(right)), next, root);
        }
      }
    }
  }

  std::optional<AnyAnglePath> find(Cell start_cell, Cell goal_cell, const std::function<bool()>& give_up) {
    expanded = 0;
    if (!map.passable(start_cell) || !map.passable(goal_cell)) return std::nullopt;
    const Point s{2 * std::int64_t{start_cell.x} + 1, 2 * std::int64_t{start_cell.y} + 1};
    goal = {2 * std::int64_t{goal_cell.x} + 1, 2 * std::int64_t{goal_cell.y} + 1};
    const auto waypoint = [](Point p) { return Eigen::Vector3d(map_point(p).x(), map_point(p).y(), 0.0); };
    if (s == goal) return AnyAnglePath{0.0, {waypoint(s)}};
    if (++current == 0) {
      std::fill(stamp.begin(), stamp.end(), 0);
      current = 1;
    }
    roots.clear();
    queue = {};
    roots.push_back({s, 0.0, -1});
    push_flat(s.x, s.y, 1, 0);
    push_flat(s.x, s.y, -1, 0);
    for (const std::int64_t strip : {s.y - 1, s.y}) {
      const auto [left, right] = run_at(strip, s.x);
      push_cone(Rational::of(left), Rational::of(right), strip == s.y ? s.y + 1 : s.y - 1, 0);
    }
    while (!queue.empty()) {
      const Node n = queue.top();
      queue.pop();
      if (stale(n)) continue;
      if (n.goal) {
        AnyAnglePath path;
        path.length = (roots[n.root].g + distance(roots[n.root].at, goal)) / 2.0;
        path.waypoints.push_back(waypoint(goal));
        for (int i = n.root; i >= 0; i = roots[i].parent) path.waypoints.push_back(waypoint(roots[i].at));
        std::reverse(path.waypoints.begin(), path.waypoints.end());
        return path;
      }
      if (++expanded % 1024 == 0 && give_up && give_up()) return std::nullopt;
      if (n.kind == Kind::flat)
        expand_flat(n);
      else
        expand_cone(n);
    }
    return std::nullopt;
  }
};

AnyAngleSearch::AnyAngleSearch(const Map& map) : state_(std::make_unique<State>(map)) {}
AnyAngleSearch::~AnyAngleSearch() = default;
std::optional<AnyAnglePath> AnyAngleSearch::find(Cell start, Cell goal) { return state_->find(start, goal, {}); }
std::optional<AnyAnglePath> AnyAngleSearch::find(Cell start, Cell goal, const std::function<bool()>& give_up) {
  return state_->find(start, goal, give_up);
}
std::size_t AnyAngleSearch::expanded() const { return state_->expanded; }

std::optional<AnyAnglePath> any_angle_optimum(const Map& map, Cell start, Cell goal) {
  return AnyAngleSearch(map).find(start, goal);
}

std::optional<AnyAnglePath> theta_star(const Graph& graph, NodeId start, NodeId goal) {
  const Map& map = *graph.map;
  const auto planar = [&](NodeId a, NodeId b) {
    const Cell ca = graph.cell(a), cb = graph.cell(b);
    return std::hypot(double(ca.x - cb.x), double(ca.y - cb.y));
  };
  BestFirstSearch search(graph.num_nodes(), [&](NodeId n) { return planar(n, goal); });
  search.relax(start, 0.0, -1);
  search.run(goal, [&](NodeId n) {
    const NodeId up = search.parent(n);
    for (EdgeId e = graph.edges_begin(n); e < graph.edges_end(n); ++e) {
      const NodeId m = graph.targets[e];
      if (search.closed(m)) continue;
      // Path 2 (the parent's line of sight), else path 1 (the move itself).
      if (up >= 0 && line_of_sight(map, graph.cell(up), graph.cell(m), graph.options.corner_cutting))
        search.relax(m, search.cost(up) + planar(up, m), up);
      else
        search.relax(m, search.cost(n) + planar(n, m), n);
    }
  });
  if (search.cost(goal) == search.unreached) return std::nullopt;
  AnyAnglePath path;
  path.length = search.cost(goal);
  for (const NodeId n : search.path_to(goal)) {
    const Cell c = graph.cell(n);
    path.waypoints.push_back({double(c.x), double(c.y), 0.0});
  }
  return path;
}

// The rule is segment_free's with corner cutting (tests/test_segment_rule.cpp holds them equal);
// half_units() refuses points off the lattice.
bool any_angle_segment_free(const Map& map, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  half_units(a);
  half_units(b);
  return segment_free(map, a.head<2>(), b.head<2>(), true);
}

bool any_angle_path_valid(const Map& map, std::span<const Eigen::Vector3d> points) {
  if (points.empty()) return false;
  std::vector<Point> path;
  for (const auto& p : points)
    if (const Point q = half_units(p); path.empty() || !(q == path.back())) path.push_back(q);
  const auto free_between = [&](Point p, Point q) { return segment_free(map, map_point(p), map_point(q), true); };
  if (path.size() == 1) return free_between(path[0], path[0]);
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    if (!free_between(path[i], path[i + 1])) return false;
  const MapFree free{map};
  const auto sign = [](std::int64_t v) -> std::int64_t { return (v > 0) - (v < 0); };
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    const Point in{sign(path[i].x - path[i - 1].x), sign(path[i].y - path[i - 1].y)};
    const Point out{sign(path[i + 1].x - path[i].x), sign(path[i + 1].y - path[i].y)};
    if (!passage_ok(free, path[i], in, out)) return false;
  }
  return true;
}

}  // namespace aco
