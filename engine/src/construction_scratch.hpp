#pragma once
// The per-thread buffers an ant's walk is built in (colony_walks.hpp): which nodes it may enter,
// its candidates and their weights, and the local search's tables.
#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "aco/engine/local_search.hpp"
#include "aco/engine/zero_pages.hpp"
#include "aco/graph.hpp"

namespace aco::colony_detail {

// Per-thread construction buffers. `marks` says per node whether the current ant may enter it,
// in one read per candidate: a node the ant entered holds 2 x its stamp + 1 while it lies on the
// walk and 2 x its stamp once the ant backed off it (still tabu; the bidirectional search joins
// two ants where their walks meet, so it needs the difference), and a forbidden node (dead-end
// filling, a deadlock policy) holds kForbidden, above every stamp. Stamps grow from ant to ant,
// and the marks are cleared only when they run out. One byte per node: the marks of a thread's
// ant are read for every candidate, and at 2048x2048 four megabytes stay in cache where
// sixteen did not (the clearing, every 126 walks, costs a few microseconds per walk).
struct Scratch {
  using MarkT = std::uint8_t;
  static constexpr MarkT kForbidden = 0xFF;
  static constexpr std::uint32_t kLastStamp = 0x7E;  // 2 x stamp + 1 stays below kForbidden
  // Only nodes an edge leads to are marked forbidden: no ant can stand on another. So on a
  // corridor's graph (coarse to fine) the marks' pages are the corridor's (ZeroPages).
  Scratch(const Graph& graph, const std::vector<std::uint8_t>& forbidden, int max_degree)
      : marks(forbidden.size()), candidates(max_degree), weights(max_degree), factors(max_degree) {
    for (NodeId n = 0; n < graph.num_nodes(); ++n)
      if (forbidden[static_cast<std::size_t>(n)] && graph.degree(n) > 0)
        marks[static_cast<std::size_t>(n)] = kForbidden;
  }
  std::uint32_t next_stamp() {
    if (++stamp > kLastStamp) {
      clear_walks();
      stamp = 1;
    }
    return stamp;
  }
  // Every mark but kForbidden back to 0. Eight marks of 0 (a page no walk wrote, most of a large
  // map's) are read as one word and left unwritten.
  void clear_walks() {
    MarkT* const first = marks.begin();
    const std::size_t size = marks.size();
    std::size_t i = 0;
    for (; i + 8 <= size; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, first + i, sizeof word);
      if (word == 0) continue;
      for (std::size_t k = i; k < i + 8; ++k) first[k] = first[k] == kForbidden ? kForbidden : MarkT{0};
    }
    for (; i < size; ++i) first[i] = first[i] == kForbidden ? kForbidden : MarkT{0};
  }
  bool walked(NodeId n) const { return marks[n] == 2 * stamp + 1; }
  void enter(NodeId n) { marks[n] = static_cast<MarkT>(2 * stamp + 1); }
  void leave(NodeId n) { marks[n] = static_cast<MarkT>(2 * stamp); }
  void forbid(NodeId n, bool forbidden) { marks[n] = forbidden ? kForbidden : MarkT{0}; }
  ZeroPages<MarkT> marks;
  std::uint32_t stamp = 0;
  std::vector<EdgeId> candidates;
  std::vector<double> weights;
  std::vector<double> factors;
  WalkScratch walk;
};

using ScratchPool = tbb::enumerable_thread_specific<Scratch>;

}  // namespace aco::colony_detail
