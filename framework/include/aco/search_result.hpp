#pragma once
// What every planner's search returns at its core (the colony, A*, IFWA, PSO): one best path on
// the graph and how the search got there, in the colony's terms (an iteration is a generation or
// a swarm update). Planner-specific measures go beside it (ColonyResult, PlannerResult, and a
// PlanOutcome's property map).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "aco/graph.hpp"

namespace aco {

struct SearchResult {
  static constexpr double none = std::numeric_limits<double>::infinity();
  bool solved = false;
  std::vector<NodeId> path;  // best path found, start to goal; every consecutive pair an edge
  double length = none;      // path_length(graph, path)
  int iterations = 0;        // iterations run
  int best_iteration = 0;    // first iteration (1-based) whose best had the final length; 0 if unsolved
  std::vector<double> best_so_far;  // per iteration (none until a path is found)

  // Sets best_iteration from the curve, once path and length are final.
  void finish() {
    if (!solved) return;
    best_iteration = 1 + static_cast<int>(std::find(best_so_far.begin(), best_so_far.end(), length) - best_so_far.begin());
  }
};

// The baseline planners' result (IFWA, PSO): the core and the candidate solutions they decoded.
// For them the initial population counts towards iteration 1.
struct PlannerResult : SearchResult {
  std::uint64_t evaluations = 0;  // candidate solutions decoded into walks
};

}  // namespace aco
