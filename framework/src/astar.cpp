#include "aco/astar.hpp"

#include <algorithm>
#include <limits>
#include <queue>

namespace aco {

std::optional<ShortestPath> astar(const Graph& graph, NodeId start, NodeId goal) {
  constexpr double unreached = std::numeric_limits<double>::infinity();
  std::vector<double> cost(graph.num_nodes(), unreached);
  std::vector<NodeId> parent(graph.num_nodes(), -1);
  std::vector<std::uint8_t> closed(graph.num_nodes(), 0);
  using Entry = std::pair<double, NodeId>;  // (f = g + h, node)
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[start] = 0.0;
  open.push({graph.distance(start, goal), start});
  while (!open.empty()) {
    const NodeId n = open.top().second;
    open.pop();
    if (closed[n]) continue;
    closed[n] = 1;
    if (n == goal) break;
    for (EdgeId e = graph.edges_begin(n); e < graph.edges_end(n); ++e) {
      const NodeId m = graph.targets[e];
      const double g = cost[n] + graph.cost(e);
      if (g < cost[m]) {
        cost[m] = g;
        parent[m] = n;
        open.push({g + graph.distance(m, goal), m});
      }
    }
  }
  if (cost[goal] == unreached) return std::nullopt;
  ShortestPath result;
  result.length = cost[goal];
  for (NodeId n = goal; n != -1; n = parent[n]) result.nodes.push_back(n);
  std::reverse(result.nodes.begin(), result.nodes.end());
  return result;
}

}  // namespace aco
