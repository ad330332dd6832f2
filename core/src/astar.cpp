#include "aco/astar.hpp"

#include "aco/best_first.hpp"

namespace aco {

std::optional<ShortestPath> astar(const Graph& graph, NodeId start, NodeId goal) {
  const auto search = search_edges(graph, start, goal, [&](NodeId n) { return graph.distance(n, goal); });
  if (search.cost(goal) == search.unreached) return std::nullopt;
  return ShortestPath{search.path_to(goal), search.cost(goal)};
}

}  // namespace aco
