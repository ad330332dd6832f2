#pragma once
// The best-first loop of the exact searches on a graph: A* (aco/astar.hpp), Theta*
// (aco/any_angle.hpp) and mapgen's Dijkstra. One order for all of them: the open list yields the
// least key and, among equal keys, the smaller node id, so a search expands the same nodes in the
// same order on every machine.
#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#include "aco/graph.hpp"

namespace aco {

// One search over a graph's nodes: each node's cost from the start and the node it was reached
// from. A node is keyed by its cost plus heuristic(node), an estimate of the cost left (0 for
// Dijkstra); an improved node is opened again, and only its first time out of the open list
// counts.
template <class Heuristic>
class BestFirstSearch {
 public:
  static constexpr double unreached = std::numeric_limits<double>::infinity();

  BestFirstSearch(int num_nodes, Heuristic heuristic)
      : cost_(num_nodes, unreached), parent_(num_nodes, -1), closed_(num_nodes, 0), heuristic_(std::move(heuristic)) {}

  // Node reached at cost g from parent (-1 for the start): kept and opened if g beats its cost.
  void relax(NodeId node, double g, NodeId parent) {
    if (g < cost_[node]) {
      cost_[node] = g;
      parent_[node] = parent;
      open_.push({g + heuristic_(node), node});
    }
  }

  // Takes the open nodes in order and calls expand(n), which relaxes n's successors, on each the
  // first time it comes; stops when goal comes (unexpanded) or none is left. Goal -1: none.
  template <class Expand>
  void run(NodeId goal, Expand&& expand) {
    while (!open_.empty()) {
      const NodeId n = open_.top().second;
      open_.pop();
      if (closed_[n]) continue;
      closed_[n] = 1;
      if (n == goal) return;
      expand(n);
    }
  }

  double cost(NodeId n) const { return cost_[n]; }
  NodeId parent(NodeId n) const { return parent_[n]; }
  bool closed(NodeId n) const { return closed_[n] != 0; }
  // The nodes from the start to n along the parents; n must have been reached.
  std::vector<NodeId> path_to(NodeId n) const {
    std::vector<NodeId> path;
    for (; n != -1; n = parent_[n]) path.push_back(n);
    std::reverse(path.begin(), path.end());
    return path;
  }
  // Every node's cost (unreached where none), moved out of the search.
  std::vector<double> take_costs() { return std::move(cost_); }

 private:
  using Entry = std::pair<double, NodeId>;  // (key, node): std::pair's order is the search's
  std::vector<double> cost_;
  std::vector<NodeId> parent_;
  std::vector<std::uint8_t> closed_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open_;
  Heuristic heuristic_;
};

// A* (Dijkstra with a heuristic of 0) over the graph's edges at their costs, from start until
// goal is taken from the open list (goal -1: until every reachable node is).
template <class Heuristic>
BestFirstSearch<Heuristic> search_edges(const Graph& graph, NodeId start, NodeId goal, Heuristic heuristic) {
  BestFirstSearch<Heuristic> search(graph.num_nodes(), std::move(heuristic));
  search.relax(start, 0.0, -1);
  search.run(goal, [&](NodeId n) {
    for (EdgeId e = graph.edges_begin(n); e < graph.edges_end(n); ++e)
      search.relax(graph.targets[e], search.cost(n) + graph.cost(e), n);
  });
  return search;
}

}  // namespace aco
