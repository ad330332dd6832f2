#include "aco/engine/coarse_to_fine.hpp"

#include <tbb/blocked_range.h>

#include <algorithm>

#include "aco/parallel.hpp"
#include "aco/voxel.hpp"

namespace aco {

bool coarsens(const Graph& graph, int block) {
  return !graph.volumetric && graph.terrain_positions.empty() &&
         (std::max(graph.width, graph.height) + block - 1) / block >= kCoarseMapSide;
}

namespace {

int block_count(int cells, int block) { return (cells + block - 1) / block; }

}  // namespace

bool coarsens_world(const Map& world) {
  return world.volumetric() && std::int64_t{world.width()} * world.height() * world.depth() >= kCoarseWorldVoxels;
}

std::optional<CoarseMap> coarse_map(const Map& map, Cell start, Cell goal, int block, int opened) {
  const int width = block_count(map.width(), block), height = block_count(map.height(), block);
  const int depth = map.volumetric() ? block_count(map.depth(), block) : 1;
  const int layer = map.volumetric() ? block : 1;
  const auto block_of = [&](Cell c) { return Cell{c.x / block, c.y / block, c.z / layer}; };
  CoarseMap coarse{nullptr, block_of(start), block_of(goal)};
  if (coarse.start == coarse.goal) return std::nullopt;
  const std::string side = std::to_string(block);
  std::string name = map.name() + " in blocks of " + side + "x" + side;
  OccupancyGrid* grid = nullptr;
  VoxelMap* world = nullptr;
  if (map.volumetric())
    coarse.map = std::unique_ptr<Map>(world = new VoxelMap(width, height, depth, name.append("x").append(side)));
  else
    coarse.map = std::unique_ptr<Map>(grid = new OccupancyGrid(width, height, name));
  const auto set_blocked = [&](Cell c, bool blocked) {
    if (world)
      world->set_blocked(c, blocked);
    else
      grid->set_blocked(c, blocked);
  };
  // Rows of blocks in parallel: each writes its own blocks, and the map is only read.
  with_concrete_world(map, [&](const auto& concrete) {
    aco::parallel_for(tbb::blocked_range<int>(0, depth * height), [&](const tbb::blocked_range<int>& rows) {
      for (int row = rows.begin(); row < rows.end(); ++row) {
        const int by = row % height, bz = row / height;
        for (int bx = 0; bx < width; ++bx) {
          bool free = true;
          for (int z = bz * layer; free && z < std::min(map.depth(), (bz + 1) * layer); ++z)
            for (int y = by * block; free && y < std::min(map.height(), (by + 1) * block); ++y)
              for (int x = bx * block; free && x < std::min(map.width(), (bx + 1) * block); ++x)
                free = concrete.passable({x, y, z});
          set_blocked({bx, by, bz}, !free);
        }
      }
    });
  });
  for (const Cell end : {coarse.start, coarse.goal})
    for (int z = std::max(0, end.z - opened); z <= std::min(depth - 1, end.z + opened); ++z)
      for (int y = std::max(0, end.y - opened); y <= std::min(height - 1, end.y + opened); ++y)
        for (int x = std::max(0, end.x - opened); x <= std::min(width - 1, end.x + opened); ++x)
          set_blocked({x, y, z}, false);
  return coarse;
}

std::optional<CoarseProblem> coarse_problem(const Map& map, const GraphOptions& options, Cell start, Cell goal,
                                            int block) {
  std::optional<CoarseMap> blocks = coarse_map(map, start, goal, block, 0);
  if (!blocks) return std::nullopt;
  CoarseProblem coarse;
  coarse.map = std::move(blocks->map);
  coarse.graph = build_graph(*coarse.map, options);
  coarse.start = coarse.graph.node(blocks->start);
  coarse.goal = coarse.graph.node(blocks->goal);
  if (!reachable(coarse.graph, coarse.start, coarse.goal)) return std::nullopt;
  return coarse;
}

std::vector<std::uint8_t> coarse_corridor(const Map& map, const Graph& blocks, std::span<const NodeId> coarse_path,
                                          int block, int radius) {
  std::vector<std::uint8_t> open_block(static_cast<std::size_t>(blocks.num_nodes()), 0);
  for (const NodeId n : coarse_path) {
    const Cell c = blocks.cell(n);
    for (int z = std::max(0, c.z - radius); z <= std::min(blocks.depth - 1, c.z + radius); ++z)
      for (int y = std::max(0, c.y - radius); y <= std::min(blocks.height - 1, c.y + radius); ++y)
        for (int x = std::max(0, c.x - radius); x <= std::min(blocks.width - 1, c.x + radius); ++x)
          open_block[static_cast<std::size_t>(blocks.node({x, y, z}))] = 1;
  }
  // Opened block by block, with no division per cell of the map.
  const int width = map.width(), height = map.height(), depth = map.depth();
  const int layer = map.volumetric() ? block : 1;
  std::vector<std::uint8_t> closed(static_cast<std::size_t>(width) * height * depth, 1);
  for (NodeId b = 0; b < blocks.num_nodes(); ++b) {
    if (!open_block[static_cast<std::size_t>(b)]) continue;
    const Cell c = blocks.cell(b);
    const int x0 = c.x * block, x1 = std::min(width, x0 + block);
    for (int z = c.z * layer; z < std::min(depth, (c.z + 1) * layer); ++z)
      for (int y = c.y * block; y < std::min(height, (c.y + 1) * block); ++y)
        std::fill_n(closed.begin() + (static_cast<std::size_t>(z) * height + y) * width + x0, x1 - x0, std::uint8_t{0});
  }
  return closed;
}

}  // namespace aco
