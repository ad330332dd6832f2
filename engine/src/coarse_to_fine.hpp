#pragma once
// Coarse to fine (ColonySettings::coarse_to_fine): the coarse map a colony plans on first, and the
// corridor its best path leaves the ants on the map itself.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "aco/graph.hpp"
#include "aco/map.hpp"

namespace aco::colony_detail {

struct CoarseProblem {
  std::unique_ptr<OccupancyGrid> map;  // the graph points to it
  Graph graph;
  NodeId start = 0;
  NodeId goal = 0;
};

// Whether a map is planned coarse to fine in blocks of `block` cells a side: a 2D map whose cells
// are at their coordinates (no terrain), large enough that its blocks still number
// kCoarseMapSide along its longer side. A smaller coarse map gains little and misses the doors
// its blocks close.
constexpr int kCoarseMapSide = 256;
bool coarsens(const Graph& graph, int block);

// The map in blocks of `block` x `block` cells, a block free where all its cells (in the map) are
// free, with the graph options of the map itself. The blocks of start and goal are free whatever
// their cells. None where the coarse start and goal are one block or not connected.
std::optional<CoarseProblem> coarse_problem(const Graph& graph, NodeId start, NodeId goal, int block);

// Per node of the map itself: 0 within one block of the coarse path's blocks, 1 elsewhere.
std::vector<std::uint8_t> coarse_corridor(const Graph& graph, const CoarseProblem& coarse,
                                          std::span<const NodeId> coarse_path, int block);

}  // namespace aco::colony_detail
