#pragma once
// Coarse to fine (ColonySettings::coarse_to_fine): the coarse map a colony plans on first, and the
// corridor its best path leaves the ants on the map itself. A 2D map's corridor is chosen inside
// run_colony(); a voxel world's before its graph is built (aco/planning/plan_request.hpp), whose
// whole graph may not fit in memory.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "aco/graph.hpp"
#include "aco/map.hpp"

namespace aco {

// The map in blocks of `block` cells a side (block x block, or block x block x block in a voxel
// world), a block free where all its cells (in the map) are free; the blocks of start and goal,
// and those within `opened` blocks of them, are free whatever their cells. None where start and
// goal are in one block.
struct CoarseMap {
  std::unique_ptr<Map> map;
  Cell start;
  Cell goal;
};
std::optional<CoarseMap> coarse_map(const Map& map, Cell start, Cell goal, int block, int opened);

struct CoarseProblem {
  std::unique_ptr<Map> map;  // the graph points to it
  Graph graph;
  NodeId start = 0;
  NodeId goal = 0;
};

// Whether a 2D map is planned coarse to fine in blocks of `block` cells a side: its cells are at
// their coordinates (no terrain), and it is large enough that its blocks still number
// kCoarseMapSide along its longer side. A smaller coarse map gains little and misses the doors
// its blocks close.
constexpr int kCoarseMapSide = 256;
bool coarsens(const Graph& graph, int block);

// Whether a voxel world is planned coarse to fine: one of at least kCoarseWorldVoxels (160^3,
// Warframe's Complex and larger), whose whole graph of 26 moves per voxel takes gigabytes. Its
// coarse world is planned coarse to fine in turn while it is that large.
constexpr std::int64_t kCoarseWorldVoxels = std::int64_t{1} << 22;
bool coarsens_world(const Map& world);

// coarse_map() with the graph of the map's `options`: none also where the coarse start and goal
// are not connected.
std::optional<CoarseProblem> coarse_problem(const Map& map, const GraphOptions& options, Cell start, Cell goal,
                                            int block);

// Per node of the map itself: 0 within `radius` blocks of the coarse path's blocks (nodes of
// `blocks`, the coarse map's graph), 1 elsewhere.
std::vector<std::uint8_t> coarse_corridor(const Map& map, const Graph& blocks, std::span<const NodeId> coarse_path,
                                          int block, int radius = 1);

}  // namespace aco
