#include "aco/engine/dead_ends.hpp"

#include <algorithm>

#include "aco/engine/zero_pages.hpp"

namespace aco {

std::vector<std::uint8_t> dead_ends(const Graph& g, NodeId start, NodeId goal, std::span<const std::uint8_t> closed) {
  const int n = g.num_nodes();
  std::vector<std::uint8_t> dead(n, 1);
  dead[start] = dead[goal] = 0;
  if (start == goal) return dead;
  // Depth-first search from start whose first (and only) tree edge is the extra edge to goal;
  // start is the root, so every vertex left on the vertex stack when goal's subtree is done
  // forms, with start, the block of that edge. Blocks inside the subtree are popped as Tarjan's
  // algorithm finds them. Iterative: a 512x512 maze is a path of 130,000 cells.
  // Discovery numbers from 1 (0: not yet found), in pages written where the search goes: on a
  // corridor of a large map (coarse to fine) a few percent of them.
  ZeroPages<int> order(static_cast<std::size_t>(n)), low(static_cast<std::size_t>(n));
  std::vector<NodeId> vertices;
  struct Frame {
    NodeId node;
    NodeId parent;
    EdgeId next;
  };
  std::vector<Frame> stack;
  int counter = 1;
  order[start] = low[start] = counter++;
  order[goal] = low[goal] = counter++;
  vertices.push_back(goal);
  stack.push_back({goal, start, g.edges_begin(goal)});
  while (!stack.empty()) {
    Frame& f = stack.back();
    if (f.next < g.edges_end(f.node)) {
      const NodeId next = g.targets[f.next++];
      if (next == f.parent || (!closed.empty() && closed[next] && next != start)) continue;
      if (order[next] == 0) {
        order[next] = low[next] = counter++;
        vertices.push_back(next);
        stack.push_back({next, f.node, g.edges_begin(next)});
      } else {
        low[f.node] = std::min(low[f.node], order[next]);
      }
      continue;
    }
    const Frame done = f;
    stack.pop_back();
    if (stack.empty()) break;
    const NodeId parent = stack.back().node;
    low[parent] = std::min(low[parent], low[done.node]);
    if (low[done.node] >= order[parent]) {
      // parent separates done's subtree from start (goal included: a pocket behind the goal):
      // that block holds no start-goal path.
      while (vertices.back() != done.node) vertices.pop_back();
      vertices.pop_back();
    }
  }
  for (NodeId v : vertices) dead[v] = 0;
  return dead;
}

}  // namespace aco
