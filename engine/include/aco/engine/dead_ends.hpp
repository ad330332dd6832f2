#pragma once
// Dead-end filling, generalised: the cells that lie on no loop-free path from start to goal.
// An ant's walk is loop-free (its tabu list), so it can enter such a cell only to get stuck or
// back out again; forbidding them before the first iteration changes no path an ant can find.
// In a maze with one path between any two cells (a tree) only the solution path remains.
#include <cstdint>
#include <span>
#include <vector>

#include "aco/graph.hpp"

namespace aco {

// Per node: 1 where the node lies on no simple start-goal path (walls, other components, dead
// ends, rooms behind a single door), 0 elsewhere. Start and goal are always 0.
// Linear time: a node v lies on a simple start-goal path iff, in the graph plus an extra edge
// start-goal, v shares a biconnected component with that edge (Hopcroft and Tarjan 1973).
// Nodes marked in `closed` (if given) are left out of the graph, as walls are.
std::vector<std::uint8_t> dead_ends(const Graph& graph, NodeId start, NodeId goal,
                                    std::span<const std::uint8_t> closed = {});

}  // namespace aco
