#include "aco/graph.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <bit>
#include <boost/multiprecision/cpp_int.hpp>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "aco/parallel.hpp"
#include "aco/voxel.hpp"

namespace aco {
namespace {

// King moves first (straight, then diagonal), then knight moves; the order fixes edge ids and
// so, with the seed, every run's random choices.
constexpr std::array<Move, 16> kMoves = {{{1, 0},
                                          {0, 1},
                                          {-1, 0},
                                          {0, -1},
                                          {1, 1},
                                          {-1, 1},
                                          {-1, -1},
                                          {1, -1},
                                          {2, 1},
                                          {1, 2},
                                          {-1, 2},
                                          {-2, 1},
                                          {-2, -1},
                                          {-1, -2},
                                          {1, -2},
                                          {2, -1}}};

// In 3D: the 6 faces, the 12 edges, the 8 corners, each group in a fixed order.
constexpr std::array<Move, 26> kMoves3d = {
    {{1, 0, 0},  {0, 1, 0},  {-1, 0, 0},  {0, -1, 0},  {0, 0, 1},  {0, 0, -1},  {1, 1, 0},    {-1, 1, 0},  {-1, -1, 0},
     {1, -1, 0}, {1, 0, 1},  {-1, 0, 1},  {-1, 0, -1}, {1, 0, -1}, {0, 1, 1},   {0, -1, 1},   {0, -1, -1}, {0, 1, -1},
     {1, 1, 1},  {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1},  {1, 1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}}};

// The cells a move's segment passes through besides its two ends, and whether touching
// them only at a corner (diagonal moves) is what they guard.
template <class M>
bool move_clear(const M& map, Cell from, Move m, bool corner_cutting) {
  const int adx = m.dx < 0 ? -m.dx : m.dx;
  const int ady = m.dy < 0 ? -m.dy : m.dy;
  if (adx + ady == 1) return true;
  if (adx == 1 && ady == 1) {
    if (corner_cutting) return true;
    return map.passable({from.x + m.dx, from.y}) && map.passable({from.x, from.y + m.dy});
  }
  // Knight move: the segment crosses the two cells beside its midpoint.
  const int sx = m.dx > 0 ? 1 : -1;
  const int sy = m.dy > 0 ? 1 : -1;
  if (adx == 2) return map.passable({from.x + sx, from.y}) && map.passable({from.x + sx, from.y + sy});
  return map.passable({from.x, from.y + sy}) && map.passable({from.x + sx, from.y + sy});
}

// A 3D move without corner cutting: every voxel of the box it spans is free (the two ends are
// checked by the caller).
template <class M>
bool box_clear(const M& map, Cell from, Move m) {
  for (int x = 0; x <= (m.dx != 0 ? 1 : 0); ++x)
    for (int y = 0; y <= (m.dy != 0 ? 1 : 0); ++y)
      for (int z = 0; z <= (m.dz != 0 ? 1 : 0); ++z)
        if (!map.passable({from.x + x * m.dx, from.y + y * m.dy, from.z + z * m.dz})) return false;
  return true;
}

}  // namespace

std::span<const Move> moves(Neighbourhood neighbourhood) {
  if (volumetric(neighbourhood)) return std::span<const Move>(kMoves3d).first(static_cast<std::size_t>(neighbourhood));
  return std::span<const Move>(kMoves).first(static_cast<std::size_t>(neighbourhood));
}

std::string describe(const GraphOptions& options) {
  return std::to_string(static_cast<int>(options.neighbourhood)) + "-neighbourhood, " +
         (options.corner_cutting ? "corner cutting" : "no corner cutting");
}

// Index of each (dx, dy) in [-2, 2]^2 in kMoves, or -1.
constexpr std::array<std::int8_t, 25> kMoveIndex = [] {
  std::array<std::int8_t, 25> index{};
  index.fill(-1);
  for (std::size_t k = 0; k < kMoves.size(); ++k)
    index[(kMoves[k].dx + 2) * 5 + kMoves[k].dy + 2] = static_cast<std::int8_t>(k);
  return index;
}();

// Index of each (dx, dy, dz) in [-1, 1]^3 in kMoves3d, or -1.
constexpr std::array<std::int8_t, 27> kMoveIndex3d = [] {
  std::array<std::int8_t, 27> index{};
  index.fill(-1);
  for (std::size_t k = 0; k < kMoves3d.size(); ++k)
    index[(kMoves3d[k].dx + 1) * 9 + (kMoves3d[k].dy + 1) * 3 + kMoves3d[k].dz + 1] = static_cast<std::int8_t>(k);
  return index;
}();

namespace {

// std::popcount, without a call: built for any x86-64 (no -mpopcnt), GCC calls libgcc's
// __popcountdi2 for it, 2 % of a small map's run in edge_by_move(). Moves are at most 26 bits.
int count_moves(std::uint32_t mask) {
  mask = mask - ((mask >> 1) & 0x55555555u);
  mask = (mask & 0x33333333u) + ((mask >> 2) & 0x33333333u);
  return static_cast<int>((((mask + (mask >> 4)) & 0x0F0F0F0Fu) * 0x01010101u) >> 24);
}

}  // namespace

EdgeId Graph::edge_by_move(NodeId from, int dx, int dy, int dz) const {
  int k = -1;
  if (volumetric) {
    if (dx < -1 || dx > 1 || dy < -1 || dy > 1 || dz < -1 || dz > 1) return -1;
    k = kMoveIndex3d[(dx + 1) * 9 + (dy + 1) * 3 + dz + 1];
  } else {
    if (dx < -2 || dx > 2 || dy < -2 || dy > 2 || dz != 0) return -1;
    k = kMoveIndex[(dx + 2) * 5 + dy + 2];
  }
  if (k < 0 || !(move_mask[from] >> k & 1u)) return -1;
  // Edges are stored in move order, skipping missing moves: count the moves before k.
  return offsets[from] + count_moves(move_mask[from] & ((1u << k) - 1u));
}

EdgeId Graph::reverse_edge(EdgeId e) const {
  const Move& m = volumetric ? kMoves3d[edge_moves[e]] : kMoves[edge_moves[e]];
  return edge_by_move(targets[e], -m.dx, -m.dy, -m.dz);
}

Graph subgraph(const Graph& graph, std::span<const std::uint8_t> closed) {
  Graph open;
  open.map = graph.map;
  open.options = graph.options;
  open.width = graph.width;
  open.height = graph.height;
  open.depth = graph.depth;
  open.volumetric = graph.volumetric;
  open.move_lengths = graph.move_lengths;
  const NodeId n = graph.num_nodes();
  open.offsets.assign(static_cast<std::size_t>(n) + 1, 0);
  open.move_mask.assign(static_cast<std::size_t>(n), 0);
  const bool terrain = !graph.terrain_positions.empty();
  if (terrain) open.terrain_positions = graph.terrain_positions;
  const auto kept = [&](EdgeId e) { return !closed[graph.targets[e]]; };
  std::size_t edges = 0;  // counted first: the edges of a large corridor would grow by doubling
  for (NodeId a = 0; a < n; ++a)
    if (!closed[a])
      for (EdgeId e = graph.edges_begin(a); e < graph.edges_end(a); ++e) edges += kept(e);
  open.targets.reserve(edges);
  open.edge_moves.reserve(edges);
  if (terrain) open.terrain_costs.reserve(edges);
  for (NodeId a = 0; a < n; ++a) {
    open.offsets[a] = static_cast<EdgeId>(open.targets.size());
    if (closed[a]) continue;
    for (EdgeId e = graph.edges_begin(a); e < graph.edges_end(a); ++e) {
      if (!kept(e)) continue;
      open.targets.push_back(graph.targets[e]);
      open.edge_moves.push_back(graph.edge_moves[e]);
      open.move_mask[a] |= 1u << graph.edge_moves[e];
      if (terrain) open.terrain_costs.push_back(graph.terrain_costs[e]);
    }
  }
  open.offsets[n] = static_cast<EdgeId>(open.targets.size());
  return open;
}

std::vector<EdgeId> edges_in(const Graph& graph, const Graph& part) {
  std::vector<EdgeId> ids(static_cast<std::size_t>(part.num_edges()));
  for (NodeId a = 0; a < part.num_nodes(); ++a)
    for (EdgeId e = part.edges_begin(a), in_graph = graph.edges_begin(a); e < part.edges_end(a); ++e) {
      while (graph.edge_moves[in_graph] != part.edge_moves[e]) ++in_graph;  // both in move order
      ids[static_cast<std::size_t>(e)] = in_graph++;
    }
  return ids;
}

std::vector<double> per_edge(const Graph& graph, std::span<const EdgeId> edges, std::span<const double> values) {
  std::vector<double> whole(static_cast<std::size_t>(graph.num_edges()), 0.0);
  for (std::size_t i = 0; i < edges.size(); ++i) whole[static_cast<std::size_t>(edges[i])] = values[i];
  return whole;
}

EdgeId Graph::find_edge(NodeId a, NodeId b) const {
  const Cell ca = cell(a), cb = cell(b);
  return edge_by_move(a, cb.x - ca.x, cb.y - ca.y, cb.z - ca.z);
}

namespace {

void check_neighbourhood_fits(const Map& map, const GraphOptions& options) {
  const int moves = static_cast<int>(options.neighbourhood);
  if (map.volumetric() && !volumetric(options.neighbourhood))
    throw Error(map.name() + " is a voxel world: it takes the 6-, 18- or 26-neighbourhood, not the " +
                std::to_string(moves) + "-neighbourhood");
  if (!map.volumetric() && volumetric(options.neighbourhood))
    throw Error("the " + std::to_string(moves) + "-neighbourhood is for voxel worlds; " + map.name() +
                " is a 2D map: it takes the 4-, 8- or 16-neighbourhood");
  // A knight move needs room: without any, a "16-neighbourhood" would silently be the 8 one.
  const int w = map.width(), h = map.height();
  const bool knight_fits = std::min(w, h) >= 2 && std::max(w, h) >= 3;
  if (options.neighbourhood == Neighbourhood::sixteen && !knight_fits)
    throw Error("16-neighbourhood needs a map at least 3 cells long in one direction and 2 in the other; " +
                map.name() + " is " + std::to_string(w) + "x" + std::to_string(h));
}

// An OccupancyGrid (final) keeps Map's position() and step rule, and answers passable() from
// several threads at once (with_concrete_map() hands it over as itself).
template <class M>
constexpr bool kPlainGrid = std::is_same_v<M, OccupancyGrid>;
// A voxel world (final) has Map's position() and is read from several threads at once too: its
// 26 moves per voxel are what building a large world's graph costs.
template <class M>
constexpr bool kReadInParallel = kPlainGrid<M> || std::is_same_v<M, VoxelMap>;

// Whether a cell's move k leads to a free cell by the neighbourhood's rule.
template <class M>
bool move_allowed(const M& map, const Graph& g, Cell c, const Move& m, int k) {
  const Cell to{c.x + m.dx, c.y + m.dy, c.z + m.dz};
  if (!map.passable(to)) return false;
  if (g.volumetric) return g.options.corner_cutting || k < 6 || box_clear(map, c, m);
  if (!move_clear(map, c, m, g.options.corner_cutting)) return false;
  if constexpr (kPlainGrid<M>) return true;  // Map's step rule allows every step
  return map.step_allowed(c, to);
}

// A terrain's cell centres are not at their coordinates (heights, cell size): only there are
// positions and step lengths stored.
template <class M>
bool places_cells_elsewhere(const M& map, const Graph& g) {
  if constexpr (kReadInParallel<M>) return false;  // Map's position(): the cell's coordinates
  for (NodeId id = 0; id < g.num_nodes(); ++id) {
    const Cell c = g.cell(id);
    if (map.position(c) != Eigen::Vector3d(c.x, c.y, c.z)) return true;
  }
  return false;
}

// Each node's moves (move_mask), none from or into a node marked in `closed` (if given): rows in
// parallel on a plain grid or a voxel world; a map plugin's map is asked from one thread.
template <class M>
void mark_moves(const M& map, Graph& g, std::span<const std::uint8_t> closed) {
  const auto all = moves(g.options.neighbourhood);
  const int count = static_cast<int>(all.size());
  const auto mark = [&](int first_row, int end_row) {  // rows of all layers: z * height + y
    for (int row = first_row; row < end_row; ++row)
      for (int x = 0; x < g.width; ++x) {
        const Cell c{x, row % g.height, row / g.height};
        const std::size_t id = static_cast<std::size_t>(row) * g.width + x;
        std::uint32_t mask = 0;
        if (map.passable(c) && (closed.empty() || !closed[id]))
          for (int k = 0; k < count; ++k)
            if (move_allowed(map, g, c, all[k], k) &&
                (closed.empty() || !closed[g.node({c.x + all[k].dx, c.y + all[k].dy, c.z + all[k].dz})]))
              mask |= 1u << k;
        g.move_mask[id] = mask;
      }
  };
  const int rows = g.height * g.depth;
  if constexpr (kReadInParallel<M>)
    aco::parallel_for(tbb::blocked_range<int>(0, rows, 16),
                      [&](const tbb::blocked_range<int>& r) { mark(r.begin(), r.end()); });
  else
    mark(0, rows);
}

// A step rule (a terrain's slope limit, Map::step_allowed()) may be asymmetric (uphill vs
// downhill); the engine needs reversible edges for node-based pheromone, so say so instead of
// failing later. A plain grid's moves and a voxel world's are symmetric by construction.
template <class M>
void check_reversible(const M& map, const Graph& g) {
  if (kPlainGrid<M> || g.volumetric) return;
  for (NodeId id = 0; id < g.num_nodes(); ++id)
    for (EdgeId e = g.edges_begin(id); e < g.edges_end(id); ++e)
      if (g.reverse_edge(e) < 0)
        throw Error(map.name() + ": the step " + to_string(g.cell(id)) + " -> " + to_string(g.cell(g.targets[e])) +
                    " is allowed but its reverse is not");
}

// Targets and moves, in move order per node.
template <class M>
void build_edges(const M& map, Graph& g, std::span<const std::uint8_t> closed) {
  const auto all = moves(g.options.neighbourhood);
  const NodeId n = g.num_nodes();
  mark_moves(map, g, closed);
  // One pass to count, one to fill: the edges would otherwise grow a vector of tens or hundreds
  // of millions by doubling, twice its size at the peak.
  for (NodeId id = 0; id < n; ++id) g.offsets[id + 1] = g.offsets[id] + count_moves(g.move_mask[id]);
  if (g.volumetric) check_voxel_graph_memory(n, g.offsets[n], map.name());
  g.targets.resize(static_cast<std::size_t>(g.offsets[n]));
  g.edge_moves.resize(g.targets.size());
  for (NodeId id = 0; id < n; ++id) {
    EdgeId e = g.offsets[id];
    for (std::uint32_t mask = g.move_mask[id]; mask != 0; mask &= mask - 1) {
      const int k = std::countr_zero(mask);
      const Move& m = all[k];
      g.targets[e] = id + (m.dz * g.height + m.dy) * g.width + m.dx;
      g.edge_moves[e] = static_cast<std::uint8_t>(k);
      ++e;
    }
  }
  check_reversible(map, g);
}

}  // namespace

Graph build_graph(const Map& map, const GraphOptions& options) { return build_graph(map, options, {}); }

Graph build_graph(const Map& map, const GraphOptions& options, std::span<const std::uint8_t> closed) {
  check_neighbourhood_fits(map, options);
  Graph g;
  g.map = &map;
  g.options = options;
  g.width = map.width();
  g.height = map.height();
  g.depth = map.depth();
  g.volumetric = map.volumetric();
  const int move_count = static_cast<int>(options.neighbourhood);
  bool terrain = false;
  with_concrete_world(map, [&](const auto& concrete) { terrain = places_cells_elsewhere(concrete, g); });
  // A voxel world is checked once its edges are counted (build_edges()): in a city or a
  // forest most of them are, but not all, and the worst case would refuse worlds that fit.
  if (!g.volumetric) check_planning_memory(g.width, g.height, options.neighbourhood, map.name(), terrain);
  // Node and edge ids are 32-bit: a map with more cells or possible edges than that (reachable
  // only with a raised memory limit) is refused instead of overflowing them.
  const std::int64_t cells = std::int64_t{g.width} * g.height * g.depth;
  if (cells * move_count > std::numeric_limits<EdgeId>::max())
    throw Error(map.name() + ": " + std::to_string(cells) + " cells with the " + std::to_string(move_count) +
                "-neighbourhood exceed the graph's 32-bit node and edge ids");
  const int n = g.num_nodes();
  if (g.volumetric) check_voxel_graph_memory(n, 0, map.name());  // the per-voxel arrays, before they are made
  g.offsets.assign(n + 1, 0);
  g.move_mask.assign(n, 0);
  const auto all = moves(options.neighbourhood);
  for (std::size_t k = 0; k < all.size(); ++k)
    g.move_lengths[k] = std::sqrt(double(all[k].dx * all[k].dx + all[k].dy * all[k].dy + all[k].dz * all[k].dz));
  if (!closed.empty() && closed.size() != static_cast<std::size_t>(n))
    throw Error("build_graph: `closed` has " + std::to_string(closed.size()) + " entries for " + std::to_string(n) +
                " nodes");
  with_concrete_world(map, [&](const auto& concrete) { build_edges(concrete, g, closed); });
  if (!terrain) return g;
  g.terrain_positions.resize(static_cast<std::size_t>(n));
  for (NodeId id = 0; id < n; ++id) g.terrain_positions[id] = map.position(g.cell(id));
  g.terrain_costs.resize(g.targets.size());
  for (NodeId id = 0; id < n; ++id)
    for (EdgeId e = g.edges_begin(id); e < g.edges_end(id); ++e) g.terrain_costs[e] = g.distance(id, g.targets[e]);
  return g;
}

bool reachable(const Graph& graph, NodeId start, NodeId goal, std::span<const std::uint8_t> closed) {
  // Depth first, the neighbour nearest the goal first: on open ground it heads almost straight
  // there, where a breadth-first search visits every cell closer than the goal (a tenth of a
  // second on a 2048x2048 map, before every run). Unreachable, both visit the start's component.
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(graph.num_nodes()), 0);
  if (!closed.empty()) std::copy(closed.begin(), closed.end(), seen.begin());
  std::vector<NodeId> stack{start};
  seen[start] = 1;
  const Cell target = graph.cell(goal);
  std::vector<std::pair<int, NodeId>> next;  // (distance to the goal, node), one node's unseen neighbours
  while (!stack.empty()) {
    const NodeId n = stack.back();
    stack.pop_back();
    if (n == goal) return true;
    next.clear();
    for (EdgeId e = graph.edges_begin(n); e < graph.edges_end(n); ++e) {
      const NodeId m = graph.targets[e];
      if (seen[m]) continue;
      seen[m] = 1;
      const Cell c = graph.cell(m);
      next.emplace_back(std::max({std::abs(c.x - target.x), std::abs(c.y - target.y), std::abs(c.z - target.z)}), m);
    }
    std::sort(next.begin(), next.end(), std::greater<>());  // the nearest on top of the stack
    for (const auto& [distance, m] : next) stack.push_back(m);
  }
  return false;
}

bool BreadthFirstSearch::find(const Graph& graph, NodeId from, NodeId to, std::span<const std::uint8_t> blocked,
                              NodeId avoid, std::size_t limit) {
  if (seen_.size() != static_cast<std::size_t>(graph.num_nodes())) {
    seen_.assign(graph.num_nodes(), 0);
    parent_.assign(graph.num_nodes(), -1);
    stamp_ = 0;
  }
  if (++stamp_ == 0) std::fill(seen_.begin(), seen_.end(), 0), stamp_ = 1;
  queue_.clear();
  queue_.push_back(from);
  seen_[from] = stamp_;
  if (avoid >= 0) seen_[avoid] = stamp_;
  for (std::size_t head = 0; head < queue_.size() && head < limit; ++head) {
    const NodeId n = queue_[head];
    if (n == to) {
      path_.clear();
      for (NodeId m = n; m != from; m = parent_[m]) path_.push_back(m);
      path_.push_back(from);
      std::reverse(path_.begin(), path_.end());
      return true;
    }
    for (EdgeId e = graph.edges_begin(n); e < graph.edges_end(n); ++e) {
      const NodeId m = graph.targets[e];
      if (seen_[m] != stamp_ && (blocked.empty() || !blocked[m])) {
        seen_[m] = stamp_;
        parent_[m] = n;
        queue_.push_back(m);
      }
    }
  }
  return false;
}

double path_length(const Graph& graph, std::span<const NodeId> path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const EdgeId e = graph.find_edge(path[i - 1], path[i]);
    if (e < 0)
      throw Error("path step " + to_string(graph.cell(path[i - 1])) + " -> " + to_string(graph.cell(path[i])) +
                  " is not an edge of the graph");
    length += graph.cost(e);
  }
  return length;
}

namespace {

// line_of_sight in a voxel world: the same traversal over three axes. The next boundary crossed
// is the axis k with the smallest (2 * i_k + 1) / |d_k| (cross-multiplied, exact); several at
// once mean the segment passes through an edge or a corner, where the box of voxels around it
// obeys the move rule.
bool voxel_line_of_sight(const Map& map, Cell a, Cell b, bool corner_cutting) {
  if (!map.passable(a)) return false;
  const std::array<std::int64_t, 3> d = {std::int64_t{b.x} - a.x, std::int64_t{b.y} - a.y, std::int64_t{b.z} - a.z};
  std::array<std::int64_t, 3> crossed = {0, 0, 0}, span{};
  std::array<int, 3> sign{};
  for (int k = 0; k < 3; ++k) {
    span[k] = d[k] < 0 ? -d[k] : d[k];
    sign[k] = d[k] > 0 ? 1 : -1;
  }
  Cell c = a;
  for (;;) {
    int first = -1;
    std::array<bool, 3> step = {false, false, false};
    for (int k = 0; k < 3; ++k) {
      if (crossed[k] == span[k]) continue;
      const std::int64_t order =
          first < 0 ? -1 : (2 * crossed[k] + 1) * span[first] - (2 * crossed[first] + 1) * span[k];
      if (order < 0) {
        step = {false, false, false};
        first = k;
      }
      if (order <= 0) step[k] = true;
    }
    if (first < 0) return true;
    const Cell next{c.x + (step[0] ? sign[0] : 0), c.y + (step[1] ? sign[1] : 0), c.z + (step[2] ? sign[2] : 0)};
    if (step[0] + step[1] + step[2] > 1) {
      bool any_side_free = false, every_side_free = true;
      for (int x = 0; x <= int(step[0]); ++x)
        for (int y = 0; y <= int(step[1]); ++y)
          for (int z = 0; z <= int(step[2]); ++z) {
            const Cell side{c.x + x * sign[0], c.y + y * sign[1], c.z + z * sign[2]};
            if (side == c || side == next) continue;
            const bool free = map.passable(side);
            any_side_free = any_side_free || free;
            every_side_free = every_side_free && free;
          }
      if (corner_cutting ? !any_side_free : !every_side_free) return false;
    }
    for (int k = 0; k < 3; ++k) crossed[k] += step[k] ? 1 : 0;
    c = next;
    if (!map.passable(c)) return false;
  }
}

}  // namespace

namespace {

// line_of_sight() in the plane, for the concrete map (with_concrete_map()): the smoothers' string
// pulling asks it thousands of times along a long path, a virtual call per cell otherwise.
template <class M>
bool planar_line_of_sight(const M& map, Cell a, Cell b, bool corner_cutting) {
  // Amanatides-Woo traversal in exact integers. Seen from a's centre, the segment leaves the
  // current column after crossing x-distance ix + 1/2, i.e. at t = (2*ix + 1) / (2*|dx|), and
  // the current row at t = (2*iy + 1) / (2*|dy|). Cross-multiplied: compare (2*ix + 1) * |dy|
  // with (2*iy + 1) * |dx|; equal means both at once, i.e. through a grid vertex.
  if (!map.passable(a)) return false;
  const std::int64_t dx = std::int64_t{b.x} - a.x;
  const std::int64_t dy = std::int64_t{b.y} - a.y;
  const int sx = dx > 0 ? 1 : -1;
  const int sy = dy > 0 ? 1 : -1;
  const std::int64_t adx = dx < 0 ? -dx : dx;
  const std::int64_t ady = dy < 0 ? -dy : dy;
  std::int64_t ix = 0, iy = 0;  // columns and rows crossed so far
  Cell c = a;
  while (ix < adx || iy < ady) {
    const Cell previous = c;
    // With one direction exhausted the other comes first; otherwise both are strictly inside
    // the segment and the cross-multiplied comparison is valid (adx, ady > 0).
    std::int64_t order = 0;  // < 0: column boundary first, > 0: row boundary first, 0: vertex
    if (iy == ady)
      order = -1;
    else if (ix == adx)
      order = 1;
    else
      order = (2 * ix + 1) * ady - (2 * iy + 1) * adx;
    if (order < 0) {
      c.x += sx;
      ++ix;
    } else if (order > 0) {
      c.y += sy;
      ++iy;
    } else {
      const bool side_x = map.passable({c.x + sx, c.y});
      const bool side_y = map.passable({c.x, c.y + sy});
      if (corner_cutting ? !side_x && !side_y : !side_x || !side_y) return false;
      c.x += sx;
      c.y += sy;
      ++ix;
      ++iy;
    }
    if (!map.passable(c)) return false;
    if constexpr (!std::is_same_v<M, OccupancyGrid>)  // a plain grid allows every step between free cells
      if (!map.step_allowed(previous, c)) return false;
  }
  return true;
}

}  // namespace

bool line_of_sight(const Map& map, Cell a, Cell b, bool corner_cutting) {
  if (map.volumetric()) return voxel_line_of_sight(map, a, b, corner_cutting);
  bool free = false;
  with_concrete_map(map, [&](const auto& concrete) { free = planar_line_of_sight(concrete, a, b, corner_cutting); });
  return free;
}

namespace {

// segment_free's geometry, in doubled coordinates (doubling a double is exact): cell i spans the
// open interval (2i - 1, 2i + 1) and the grid lines lie on the odd integers.

bool on_grid_line(double v) { return std::floor(v) == v && std::fmod(v, 2.0) != 0.0; }

// The cell whose open interval holds v, v on no grid line.
std::int64_t cell_of(double v) {
  const auto k = static_cast<std::int64_t>(std::floor(v));
  return k % 2 == 0 ? k / 2 : (k + 1) / 2;
}

// The cell the segment is in just after v, heading `direction` (+1 or -1).
std::int64_t cell_towards(double v, int direction) {
  if (!on_grid_line(v)) return cell_of(v);
  const auto line = static_cast<std::int64_t>(v);
  return direction > 0 ? (line + 1) / 2 : (line - 1) / 2;
}

// The cells whose closed interval holds v: one, or the two beside a grid line.
std::pair<std::int64_t, std::int64_t> cells_touching(double v) {
  if (!on_grid_line(v)) return {cell_of(v), cell_of(v)};
  const auto line = static_cast<std::int64_t>(v);
  return {(line - 1) / 2, (line + 1) / 2};
}

// The sign of (b - a) x (v - a), exactly: > 0 when v lies left of the line from a to b. In
// doubles where Shewchuk's error bound for this expression (orient2d, stage A: 3.3e-16 times
// the sum of the products' magnitudes; here 8.9e-16) decides, else in exact rationals.
int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& v) {
  const double left = (b.x() - a.x()) * (v.y() - a.y());
  const double right = (b.y() - a.y()) * (v.x() - a.x());
  const double det = left - right;
  const double magnitude = std::abs(left) + std::abs(right);
  constexpr double kBound = 4.0 * std::numeric_limits<double>::epsilon();
  if (magnitude > 1e-250 && std::abs(det) > kBound * magnitude) return det > 0.0 ? 1 : -1;  // 1e-250: no underflow
  using Rational = boost::multiprecision::cpp_rational;  // a double converts exactly
  const Rational exact = (Rational(b.x()) - Rational(a.x())) * (Rational(v.y()) - Rational(a.y())) -
                         (Rational(b.y()) - Rational(a.y())) * (Rational(v.x()) - Rational(a.x()));
  return exact.sign();
}

}  // namespace

bool segment_free(const Map& map, const Eigen::Vector2d& a, const Eigen::Vector2d& b, bool corner_cutting) {
  if (!a.allFinite() || !b.allFinite()) return false;
  // An end beyond the map's closed rectangle puts a piece of the segment in cells outside it.
  const auto inside = [&](const Eigen::Vector2d& p) {
    return p.x() >= -0.5 && p.y() >= -0.5 && p.x() <= map.width() - 0.5 && p.y() <= map.height() - 0.5;
  };
  if (!inside(a) || !inside(b)) return false;
  const Eigen::Vector2d from = 2.0 * a, to = 2.0 * b;
  const auto free = [&](std::int64_t x, std::int64_t y) {
    return map.passable({static_cast<int>(x), static_cast<int>(y)});
  };
  // The cells whose closed square holds p (one, two beside an edge, four around a vertex): all
  // passable, or (corner cutting) one.
  const auto touching_free = [&](const Eigen::Vector2d& p, bool all) {
    const auto [x0, x1] = cells_touching(p.x());
    const auto [y0, y1] = cells_touching(p.y());
    bool any = false, every = true;
    for (auto y = y0; y <= y1; ++y)
      for (auto x = x0; x <= x1; ++x) {
        const bool f = free(x, y);
        any = any || f;
        every = every && f;
      }
    return all ? every : any;
  };
  if (from == to) return touching_free(from, !corner_cutting);
  // Without corner cutting the ends may not touch a blocked cell either (an end on a grid line
  // touches the cells behind it, which the traversal below does not enter).
  if (!corner_cutting && !(touching_free(from, true) && touching_free(to, true))) return false;

  if (from.x() == to.x() || from.y() == to.y()) {
    // Along a row or a column: the cells i along it, j across it.
    const bool along_x = from.y() == to.y();
    const double low = along_x ? std::min(from.x(), to.x()) : std::min(from.y(), to.y());
    const double high = along_x ? std::max(from.x(), to.x()) : std::max(from.y(), to.y());
    const double across = along_x ? from.y() : from.x();
    const auto cell = [&](std::int64_t i, std::int64_t j) { return along_x ? free(i, j) : free(j, i); };
    const std::int64_t first = cell_towards(low, 1), last = cell_towards(high, -1);
    if (!on_grid_line(across)) {
      const std::int64_t j = cell_of(across);
      for (auto i = first; i <= last; ++i)
        if (!cell(i, j)) return false;
      return true;
    }
    // On a grid line, along the edges between cells (i, j0) and (i, j1).
    const auto [j0, j1] = cells_touching(across);
    for (auto i = first; i <= last; ++i) {
      const bool free0 = cell(i, j0), free1 = cell(i, j1);
      if (corner_cutting ? !free0 && !free1 : !free0 || !free1) return false;
      // Through the vertex between cells i and i + 1: not between a blocked diagonal pair.
      if (corner_cutting && i < last && ((!free0 && !cell(i + 1, j1)) || (!free1 && !cell(i + 1, j0)))) return false;
    }
    return true;
  }

  // Across rows and columns: line_of_sight's traversal, the next border decided by which side of
  // the segment the next vertex lies on.
  const int sx = to.x() > from.x() ? 1 : -1;
  const int sy = to.y() > from.y() ? 1 : -1;
  std::int64_t x = cell_towards(from.x(), sx), y = cell_towards(from.y(), sy);
  const std::int64_t end_x = cell_towards(to.x(), -sx), end_y = cell_towards(to.y(), -sy);
  if (!free(x, y)) return false;
  while (x != end_x || y != end_y) {
    int order = 0;  // > 0: the column's border first, < 0: the row's, 0: both at once (a vertex)
    if (y == end_y)
      order = 1;
    else if (x == end_x)
      order = -1;
    else
      order = orientation(from, to, {2.0 * double(x) + sx, 2.0 * double(y) + sy}) * sx * sy;
    if (order > 0) {
      x += sx;
    } else if (order < 0) {
      y += sy;
    } else {
      const bool side_x = free(x + sx, y);
      const bool side_y = free(x, y + sy);
      if (corner_cutting ? !side_x && !side_y : !side_x || !side_y) return false;
      x += sx;
      y += sy;
    }
    if (!free(x, y)) return false;
  }
  return true;
}

}  // namespace aco
