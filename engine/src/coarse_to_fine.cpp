#include "coarse_to_fine.hpp"

#include <algorithm>

namespace aco::colony_detail {

bool coarsens(const Graph& graph, int block) {
  return !graph.volumetric && graph.terrain_positions.empty() &&
         (std::max(graph.width, graph.height) + block - 1) / block >= kCoarseMapSide;
}

std::optional<CoarseProblem> coarse_problem(const Graph& graph, NodeId start, NodeId goal, int block) {
  const int width = (graph.width + block - 1) / block, height = (graph.height + block - 1) / block;
  CoarseProblem coarse;
  coarse.map = std::make_unique<OccupancyGrid>(
      width, height, graph.map->name() + " in blocks of " + std::to_string(block) + "x" + std::to_string(block));
  with_concrete_map(*graph.map, [&](const auto& map) {
    for (int by = 0; by < height; ++by)
      for (int bx = 0; bx < width; ++bx) {
        bool free = true;
        for (int y = by * block; free && y < std::min(graph.height, (by + 1) * block); ++y)
          for (int x = bx * block; free && x < std::min(graph.width, (bx + 1) * block); ++x)
            free = map.passable({x, y});
        coarse.map->set_blocked({bx, by}, !free);
      }
  });
  const auto block_of = [block](Cell c) { return Cell{c.x / block, c.y / block}; };
  const Cell start_block = block_of(graph.cell(start)), goal_block = block_of(graph.cell(goal));
  if (start_block == goal_block) return std::nullopt;
  coarse.map->set_blocked(start_block, false);
  coarse.map->set_blocked(goal_block, false);
  coarse.graph = build_graph(*coarse.map, graph.options);
  coarse.start = coarse.graph.node(start_block);
  coarse.goal = coarse.graph.node(goal_block);
  if (!reachable(coarse.graph, coarse.start, coarse.goal)) return std::nullopt;
  return coarse;
}

std::vector<std::uint8_t> coarse_corridor(const Graph& graph, const CoarseProblem& coarse,
                                          std::span<const NodeId> coarse_path, int block) {
  std::vector<std::uint8_t> open_block(static_cast<std::size_t>(coarse.graph.num_nodes()), 0);
  for (const NodeId n : coarse_path) {
    const Cell c = coarse.graph.cell(n);
    for (int y = std::max(0, c.y - 1); y <= std::min(coarse.graph.height - 1, c.y + 1); ++y)
      for (int x = std::max(0, c.x - 1); x <= std::min(coarse.graph.width - 1, c.x + 1); ++x)
        open_block[static_cast<std::size_t>(coarse.graph.node({x, y}))] = 1;
  }
  // Opened block by block, with no division per cell of the map.
  std::vector<std::uint8_t> closed(static_cast<std::size_t>(graph.num_nodes()), 1);
  for (NodeId b = 0; b < coarse.graph.num_nodes(); ++b) {
    if (!open_block[static_cast<std::size_t>(b)]) continue;
    const Cell c = coarse.graph.cell(b);
    const int x0 = c.x * block, x1 = std::min(graph.width, x0 + block);
    for (int y = c.y * block; y < std::min(graph.height, (c.y + 1) * block); ++y)
      std::fill_n(closed.begin() + graph.node({x0, y}), x1 - x0, std::uint8_t{0});
  }
  return closed;
}

}  // namespace aco::colony_detail
