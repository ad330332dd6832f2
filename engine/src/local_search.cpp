#include "aco/engine/local_search.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace aco {

void WalkScratch::reset(int num_nodes) {
  if (static_cast<int>(marks.size()) == num_nodes) return;
  marks = ZeroPages<Mark>(static_cast<std::size_t>(num_nodes));
  current = 0;
}

std::uint32_t WalkScratch::next_stamp() {
  if (++current == 0) {
    for (Mark& m : marks) m.stamp = 0;
    current = 1;
  }
  return current;
}

WalkShortener::WalkShortener(const Graph& graph, const std::vector<std::uint8_t>& forbidden, int window)
    : g_(graph), forbidden_(forbidden), window_(window) {
  const std::span<const Move> all = moves(graph.options.neighbourhood);
  for (std::size_t m = 0; m < all.size(); ++m) {
    const Move& move = all[m];
    inverse_length_.push_back(1.0 / (move.dz == 0
                                         ? std::hypot(move.dx, move.dy)
                                         : std::sqrt(move.dx * move.dx + move.dy * move.dy + move.dz * move.dz)));
    if (std::abs(all[m].dx) <= 1 && std::abs(all[m].dy) <= 1 && all[m].dz == 0)
      unit_move_[(all[m].dy + 1) * 3 + all[m].dx + 1] = static_cast<int>(m);
  }
  eight_ = graph.options.neighbourhood == Neighbourhood::eight;
  inverse_diagonal_ = 1.0 / std::hypot(1, 1);
}

namespace {

void prefix_costs(const Graph& g, const std::vector<NodeId>& nodes, std::vector<double>& prefix) {
  prefix.assign(nodes.size(), 0.0);
  for (std::size_t k = 1; k < nodes.size(); ++k) prefix[k] = prefix[k - 1] + g.distance(nodes[k - 1], nodes[k]);
}

}  // namespace

void WalkShortener::cut_loops(std::vector<NodeId>& nodes, WalkScratch& s) const {
  const std::uint32_t stamp = s.next_stamp();
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    s.marks[nodes[k]] = {stamp, static_cast<std::int32_t>(k)};
  }
  prefix_costs(g_, nodes, s.prefix);
  s.segment.clear();
  const std::size_t last = nodes.size() - 1;
  std::size_t k = 0;
  while (k < last) {
    s.segment.push_back(nodes[k]);
    std::size_t next = k + 1;
    for (EdgeId e = g_.edges_begin(nodes[k]); e < g_.edges_end(nodes[k]); ++e) {
      const NodeId t = g_.targets[e];
      const WalkScratch::Mark mark = s.marks[t];
      if (mark.stamp != stamp) continue;
      const auto j = static_cast<std::size_t>(mark.index);
      if (j > next && g_.cost(e) < s.prefix[j] - s.prefix[k]) next = j;
    }
    k = next;
  }
  s.segment.push_back(nodes[last]);
  nodes.swap(s.segment);
}

bool WalkShortener::straight_segment(NodeId from, NodeId to, std::vector<NodeId>& segment) const {
  segment.clear();
  const std::span<const Move> all = moves(g_.options.neighbourhood);
  Cell at = g_.cell(from);
  const Cell end = g_.cell(to);
  NodeId node = from;
  const int limit = 2 * (std::abs(at.x - end.x) + std::abs(at.y - end.y) + std::abs(at.z - end.z));
  while (node != to) {
    // The move best aligned with the direction to the end (largest cosine); if the graph has
    // no such edge here, or its cell is forbidden, the straight segment is blocked.
    const int dx = end.x - at.x, dy = end.y - at.y, dz = end.z - at.z;
    int best = -1;
    if (eight_) {
      // The loop below for the 8-neighbourhood, in closed form and the same arithmetic: the
      // diagonal towards the end when its cosine, (|dx| + |dy|) / sqrt 2, beats the larger axis's
      // (a tie goes to the straight move, first in move order).
      const int ax = std::abs(dx), ay = std::abs(dy);
      const int sx = (dx > 0) - (dx < 0), sy = (dy > 0) - (dy < 0);
      const bool diagonal = (ax + ay) * inverse_diagonal_ > std::max(ax, ay);
      best = diagonal   ? unit_move_[(sy + 1) * 3 + sx + 1]
             : ax >= ay ? unit_move_[4 + sx]
                        : unit_move_[(sy + 1) * 3 + 1];
    } else {
      double best_alignment = 0.0;
      for (std::size_t m = 0; m < all.size(); ++m) {
        const double alignment = (all[m].dx * dx + all[m].dy * dy + all[m].dz * dz) * inverse_length_[m];
        if (alignment > best_alignment) {
          best_alignment = alignment;
          best = static_cast<int>(m);
        }
      }
    }
    if (best < 0 || static_cast<int>(segment.size()) >= limit) return false;
    // The move exists where the node's mask has it (the graph's move order is the moves' order);
    // its target is the cell it leads to. No edge id is needed until the walk is rebuilt.
    if (!(g_.move_mask[node] >> best & 1u)) return false;
    node += (all[best].dz * g_.height + all[best].dy) * g_.width + all[best].dx;
    if (forbidden_[node]) return false;
    at = {at.x + all[best].dx, at.y + all[best].dy, at.z + all[best].dz};
    segment.push_back(node);
  }
  return true;
}

void WalkShortener::straighten(std::vector<NodeId>& nodes, WalkScratch& s) const {
  prefix_costs(g_, nodes, s.prefix);
  std::vector<NodeId>& out = s.nodes;
  out.clear();
  out.push_back(nodes[0]);
  const std::size_t last = nodes.size() - 1;
  // From each anchor, the farthest walk node the straight segment reaches: doubling the reach
  // while the segment is free, then halving the step back from the first failure (greedy, like
  // the prune smoother). The walk's own stretch is kept where the segment is not cheaper.
  const auto free_to = [&](std::size_t k, std::size_t j) { return straight_segment(nodes[k], nodes[j], s.segment); };
  std::size_t k = 0;
  while (k < last) {
    std::size_t good = k + 1, reach = 2;
    while (reach <= static_cast<std::size_t>(window_) && k + reach <= last && free_to(k, k + reach)) {
      good = k + reach;
      reach *= 2;
    }
    std::size_t bad = std::min(last + 1, k + reach);
    while (bad - good > 1) {
      const std::size_t mid = good + (bad - good) / 2;
      (free_to(k, mid) ? good : bad) = mid;
    }
    if (good >= k + 2 && free_to(k, good)) {
      double cost = 0.0;
      NodeId previous = nodes[k];
      for (NodeId n : s.segment) {
        cost += g_.distance(previous, n);
        previous = n;
      }
      if (cost < s.prefix[good] - s.prefix[k] - 1e-9) {
        out.insert(out.end(), s.segment.begin(), s.segment.end());
        k = good;
        continue;
      }
    }
    out.insert(out.end(), nodes.begin() + static_cast<std::ptrdiff_t>(k) + 1,
               nodes.begin() + static_cast<std::ptrdiff_t>(good) + 1);
    k = good;
  }
  // A straight segment may cross the rest of the walk: cut the loops that made.
  const std::uint32_t stamp = s.next_stamp();
  nodes.clear();
  for (NodeId n : out) {
    const WalkScratch::Mark mark = s.marks[n];
    const auto at = static_cast<std::size_t>(mark.index);
    if (mark.stamp == stamp && at < nodes.size() && nodes[at] == n) {
      nodes.resize(at + 1);
      continue;
    }
    s.marks[n] = {stamp, static_cast<std::int32_t>(nodes.size())};
    nodes.push_back(n);
  }
}

void WalkShortener::shorten(Ant& ant, WalkScratch& s) const {
  if (!ant.arrived || ant.nodes.size() < 3) return;
  s.reset(g_.num_nodes());
  cut_loops(ant.nodes, s);
  if (window_ >= 2) {
    straighten(ant.nodes, s);
    cut_loops(ant.nodes, s);
  }
  ant.edges.resize(ant.nodes.size() - 1);
  ant.length = 0.0;
  for (std::size_t k = 0; k + 1 < ant.nodes.size(); ++k) {
    ant.edges[k] = g_.find_edge(ant.nodes[k], ant.nodes[k + 1]);
    ant.length += g_.cost(ant.edges[k]);
  }
}

BandSearch::BandSearch(const Graph& graph, const std::vector<std::uint8_t>& forbidden, int radius)
    : g_(graph), forbidden_(forbidden), radius_(radius) {}

bool BandSearch::improve(Ant& ant) {
  if (stamp_.empty()) {
    const auto n = static_cast<std::size_t>(g_.num_nodes());
    stamp_ = ZeroPages<std::uint32_t>(n);
    hops_ = ZeroPages<std::int32_t>(n);
    via_ = ZeroPages<EdgeId>(n);
    distance_ = ZeroPages<double>(n);
  }
  if (++current_ == 0) {
    std::fill(stamp_.begin(), stamp_.end(), 0);
    current_ = 1;
  }
  const NodeId start = ant.nodes.front(), goal = ant.nodes.back();
  const auto enter = [&](NodeId n, int hops) {
    stamp_[n] = current_;
    hops_[n] = hops;
    via_[n] = -1;
    distance_[n] = std::numeric_limits<double>::infinity();
    queue_.push_back(n);
  };
  // The band: breadth-first from every node of the walk, `radius_` moves out, around forbidden nodes.
  queue_.clear();
  for (NodeId n : ant.nodes)
    if (stamp_[n] != current_) enter(n, 0);
  for (std::size_t k = 0; k < queue_.size(); ++k) {
    const NodeId n = queue_[k];
    if (hops_[n] == radius_) continue;
    for (EdgeId e = g_.edges_begin(n); e < g_.edges_end(n); ++e) {
      const NodeId t = g_.targets[e];
      if (stamp_[t] != current_ && !forbidden_[t]) enter(t, hops_[n] + 1);
    }
  }
  // Dijkstra from the start within the band; ties broken by node id, so the result is the same
  // on every machine.
  using Entry = std::pair<double, NodeId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  distance_[start] = 0.0;
  open.push({0.0, start});
  while (!open.empty()) {
    const auto [d, n] = open.top();
    open.pop();
    if (n == goal) break;
    if (d > distance_[n]) continue;
    for (EdgeId e = g_.edges_begin(n); e < g_.edges_end(n); ++e) {
      const NodeId t = g_.targets[e];
      if (stamp_[t] != current_ || d + g_.cost(e) >= distance_[t]) continue;
      distance_[t] = d + g_.cost(e);
      via_[t] = e;
      open.push({distance_[t], t});
    }
  }
  double walked = 0.0;
  for (EdgeId e : ant.edges) walked += g_.cost(e);
  // Only a real gain: summing the same steps in another order may differ in the last bits.
  if (!(distance_[goal] < walked - 1e-9 * walked)) return false;
  ant.nodes.clear();
  ant.edges.clear();
  for (NodeId n = goal; n != start; n = g_.source(via_[n])) {
    ant.nodes.push_back(n);
    ant.edges.push_back(via_[n]);
  }
  ant.nodes.push_back(start);
  std::reverse(ant.nodes.begin(), ant.nodes.end());
  std::reverse(ant.edges.begin(), ant.edges.end());
  ant.length = 0.0;
  for (EdgeId e : ant.edges) ant.length += g_.cost(e);
  return true;
}

}  // namespace aco
