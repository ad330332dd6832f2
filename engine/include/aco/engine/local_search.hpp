#pragma once
// Local search on an ant's walk (the "ACO plus local search" of Dorigo and Stuetzle, ch. 3.7): an
// arrived ant's walk is shortened before it deposits pheromone, so the colony learns from walks
// that are at least locally taut. It looks only along the walk and a few cells beside it; it
// never searches the map.
#include <cstdint>
#include <vector>

#include "aco/engine/zero_pages.hpp"
#include "aco/strategies.hpp"

namespace aco {

// Per-thread buffers, reused from walk to walk.
struct WalkScratch {
  // Per node: its position on the walk, valid where the stamp is the current one. One entry of
  // two words, so a lookup is one cache line, not one in each of two arrays. The pages of the
  // nodes the thread's walks have been on only.
  struct Mark {
    std::uint32_t stamp = 0;
    std::int32_t index = 0;
  };
  ZeroPages<Mark> marks;
  std::uint32_t current = 0;
  std::vector<NodeId> nodes;
  std::vector<NodeId> segment;
  std::vector<double> prefix;
  void reset(int num_nodes);
  std::uint32_t next_stamp();
};

class WalkShortener {
 public:
  // `forbidden`: nodes no ant may enter (the engine's mask, which may grow between iterations).
  // `window`: the longest stretch of the walk, in nodes, replaced by one straight segment.
  WalkShortener(const Graph& graph, const std::vector<std::uint8_t>& forbidden, int window);

  // Shortens an arrived ant's walk in place (start and goal kept, never longer, still loop-free):
  // 1. loops: where a later node of the walk is a neighbour of an earlier one, the walk jumps
  //    there (the wiggles a backed-off or wandering ant leaves);
  // 2. straightening: from each anchor, the farthest node (at most `window` ahead) that the
  //    straight grid segment reaches (each step the move best aligned with the direction to the
  //    segment's end); the stretch is replaced if the segment is cheaper.
  // Costs O(walk length x log(window)) segment steps per ant in open space.
  void shorten(Ant& ant, WalkScratch& scratch) const;

 private:
  void cut_loops(std::vector<NodeId>& nodes, WalkScratch& s) const;
  void straighten(std::vector<NodeId>& nodes, WalkScratch& s) const;
  bool straight_segment(NodeId from, NodeId to, std::vector<NodeId>& segment) const;

  const Graph& g_;
  const std::vector<std::uint8_t>& forbidden_;
  int window_;
  std::vector<double> inverse_length_;  // per move of the neighbourhood
  int unit_move_[9] = {-1, -1, -1, -1, -1, -1, -1, -1, -1};  // the move (dx, dy) in [-1, 1]^2, by (dy + 1) * 3 + dx + 1
  bool eight_ = false;  // the 8-neighbourhood: straight_segment's closed form
  double inverse_diagonal_ = 0.0;  // inverse_length_ of a diagonal move
};

// The band search: a large-neighbourhood local search (Pisinger and Ropke, "Large neighborhood
// search", Handbook of Metaheuristics, 2010) whose neighbourhood is every path through the band
// of nodes within `radius` moves of a walk. The walk's corridor stays the colony's choice; within
// it the walk may take a nearby door, gap or side of an obstacle that it missed. Costs a
// breadth-first pass over the band and a Dijkstra search in it: O(walk length x radius) nodes.
class BandSearch {
 public:
  // `forbidden`: as WalkShortener's. `radius` >= 1.
  BandSearch(const Graph& graph, const std::vector<std::uint8_t>& forbidden, int radius);

  // Replaces an arrived ant's walk (start and goal kept) by the shortest path in its band if that
  // is shorter, with its grid length; returns whether it did. The band's tables are allocated at
  // the first call (20 bytes per node, of which the bands' pages are used).
  bool improve(Ant& ant);

 private:
  const Graph& g_;
  const std::vector<std::uint8_t>& forbidden_;
  int radius_;
  // Per node, the pages of the bands searched only.
  ZeroPages<std::uint32_t> stamp_;  // in the band of the current call if == current_
  std::uint32_t current_ = 0;
  ZeroPages<std::int32_t> hops_;  // valid in the band: moves from the walk
  ZeroPages<EdgeId> via_;  // valid in the band: the edge of its shortest path from the start (-1: none yet)
  ZeroPages<double> distance_;  // valid in the band: of that path
  std::vector<NodeId> queue_;
};

}  // namespace aco
