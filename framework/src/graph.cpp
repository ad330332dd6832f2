#include "aco/graph.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <limits>

#include "aco/error.hpp"
#include "aco/memory_limit.hpp"

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

// The cells a move's segment passes through besides its two ends, and whether touching
// them only at a corner (diagonal moves) is what they guard.
bool move_clear(const Map& map, Cell from, Move m, bool corner_cutting) {
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

}  // namespace

std::span<const Move> moves(Neighbourhood neighbourhood) {
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

EdgeId Graph::edge_by_move(NodeId from, int dx, int dy) const {
  if (dx < -2 || dx > 2 || dy < -2 || dy > 2) return -1;
  const int k = kMoveIndex[(dx + 2) * 5 + dy + 2];
  if (k < 0 || !(move_mask[from] >> k & 1u)) return -1;
  // Edges are stored in move order, skipping missing moves: count the moves before k.
  return offsets[from] + std::popcount(static_cast<unsigned>(move_mask[from] & ((1u << k) - 1u)));
}

EdgeId Graph::find_edge(NodeId a, NodeId b) const {
  const Cell ca = cell(a), cb = cell(b);
  return edge_by_move(a, cb.x - ca.x, cb.y - ca.y);
}

Graph build_graph(const Map& map, const GraphOptions& options) {
  Graph g;
  g.map = &map;
  g.options = options;
  g.width = map.width();
  g.height = map.height();
  // A knight move needs room: without any, a "16-neighbourhood" would silently be the 8 one.
  const bool knight_fits = std::min(g.width, g.height) >= 2 && std::max(g.width, g.height) >= 3;
  if (options.neighbourhood == Neighbourhood::sixteen && !knight_fits)
    throw Error("16-neighbourhood needs a map at least 3 cells long in one direction and 2 in the other; " +
                map.name() + " is " + std::to_string(g.width) + "x" + std::to_string(g.height));
  const int moves = static_cast<int>(options.neighbourhood);
  check_planning_memory(g.width, g.height, options.neighbourhood, map.name());
  // Node and edge ids are 32-bit: a map with more cells or possible edges than that (reachable
  // only with a raised memory limit) is refused instead of overflowing them.
  const std::int64_t cells = std::int64_t{g.width} * g.height;
  if (cells * moves > std::numeric_limits<EdgeId>::max())
    throw Error(map.name() + ": " + std::to_string(g.width) + "x" + std::to_string(g.height) + " cells with the " +
                std::to_string(moves) + "-neighbourhood exceed the graph's 32-bit node and edge ids");
  const int n = g.num_nodes();
  g.offsets.assign(n + 1, 0);
  g.move_mask.assign(n, 0);
  g.positions.resize(n);
  for (NodeId id = 0; id < n; ++id) {
    const Cell c = g.cell(id);
    g.positions[id] = map.position(c);
    if (map.passable(c)) {
      for (int k = 0; k < moves; ++k) {
        const Cell to{c.x + kMoves[k].dx, c.y + kMoves[k].dy};
        if (!map.passable(to) || !move_clear(map, c, kMoves[k], options.corner_cutting) || !map.step_allowed(c, to))
          continue;
        g.targets.push_back(g.node(to));
        g.move_mask[id] |= static_cast<std::uint16_t>(1u << k);
      }
    }
    g.offsets[id + 1] = static_cast<EdgeId>(g.targets.size());
  }
  g.costs.resize(g.targets.size());
  g.reverse.assign(g.targets.size(), -1);
  for (NodeId id = 0; id < n; ++id) {
    for (EdgeId e = g.edges_begin(id); e < g.edges_end(id); ++e) {
      g.costs[e] = g.distance(id, g.targets[e]);
      g.reverse[e] = g.find_edge(g.targets[e], id);
      // A terrain's step_allowed() may be asymmetric (uphill vs downhill); the engine needs
      // reversible edges for node-based pheromone, so say so instead of failing later.
      if (g.reverse[e] < 0)
        throw Error(map.name() + ": the step " + to_string(g.cell(id)) + " -> " + to_string(g.cell(g.targets[e])) +
                    " is allowed but its reverse is not");
    }
  }
  return g;
}

bool reachable(const Graph& graph, NodeId start, NodeId goal) { return BreadthFirstSearch().find(graph, start, goal); }

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
    length += graph.costs[e];
  }
  return length;
}

bool line_of_sight(const Map& map, Cell a, Cell b, bool corner_cutting) {
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
    if (!map.passable(c) || !map.step_allowed(previous, c)) return false;
  }
  return true;
}

}  // namespace aco
