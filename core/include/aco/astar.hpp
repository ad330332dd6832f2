#pragma once
// Exact reference planner on the same graph (same neighbourhood and corner rule) as the colony.
#include <optional>
#include <vector>

#include "aco/graph.hpp"

namespace aco {

struct ShortestPath {
  std::vector<NodeId> nodes;
  double length = 0.0;
};

// A* with the straight-line distance as heuristic (admissible: every step costs its Euclidean
// length). Empty optional when the goal is unreachable.
std::optional<ShortestPath> astar(const Graph& graph, NodeId start, NodeId goal);

}  // namespace aco
