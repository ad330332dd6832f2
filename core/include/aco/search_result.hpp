#pragma once
// What every planner's search returns at its core (the colony, A*, IFWA, PSO): one best path on
// the graph and how the search got there, in the colony's terms (an iteration is a generation or
// a swarm update). Planner-specific measures go beside it (ColonyResult, PlannerResult, and a
// PlanOutcome's property map).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "aco/error.hpp"
#include "aco/graph.hpp"

namespace aco {

struct SearchResult {
  static constexpr double none = std::numeric_limits<double>::infinity();
  bool solved = false;
  std::vector<NodeId> path;  // best path found, start to goal; every consecutive pair an edge
  double length = none;  // path_length(graph, path)
  int iterations = 0;  // iterations run
  // A count, as `iterations`: the iterations run when the final length was first found, so the
  // iteration that found it is Context::iteration = best_iteration - 1; 0 if unsolved.
  int best_iteration = 0;
  std::vector<double> best_so_far;  // per iteration (none until a path is found)
  // The anytime curves, per iteration like best_so_far, for plotting quality against effort:
  // wall-clock seconds from the start of the search loop to the end of the iteration (steady
  // clock; the per-map setup before the loop, e.g. the colony's per-edge fields, not counted), and
  // the walks built by then, cumulative: candidate paths, one per ant per colony, per decoded spark
  // or particle (the initial population counting towards the first iteration), one for A*.
  std::vector<double> elapsed_s;
  std::vector<std::uint64_t> walks;

  // Sets best_iteration from the curve, once path and length are final.
  void finish() {
    if (!solved) return;
    best_iteration =
        1 + static_cast<int>(std::find(best_so_far.begin(), best_so_far.end(), length) - best_so_far.begin());
  }
};

// Started where a search loop starts; records the end of each iteration into the anytime curves.
class SearchClock {
 public:
  void record(SearchResult& result, std::uint64_t walks_so_far) const {
    result.elapsed_s.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - began_).count());
    result.walks.push_back(walks_so_far);
  }

 private:
  std::chrono::steady_clock::time_point began_ = std::chrono::steady_clock::now();
};

// The baseline planners' result (IFWA, PSO): the core and the candidate solutions they decoded.
// For them the initial population counts towards iteration 1.
struct PlannerResult : SearchResult {
  std::uint64_t evaluations = 0;  // candidate solutions decoded into walks

  // The answer for start == goal, before any search.
  static PlannerResult already_there(NodeId node) {
    PlannerResult r;
    r.solved = true;
    r.path = {node};
    r.length = 0.0;
    return r;
  }
};

// A baseline planner's first check: start and goal are nodes of the graph and free. Throws an
// Error starting with `planner` ("pso: goal (3,4) is a blocked cell").
inline void check_endpoints(const Graph& graph, NodeId start, NodeId goal, const std::string& planner) {
  for (const auto& [node, what] : {std::pair{start, "start"}, std::pair{goal, "goal"}}) {
    if (node < 0 || node >= graph.num_nodes()) throw Error(planner + ": " + what + " node is outside the map");
    if (!graph.passable(node))
      throw Error(planner + ": " + what + " " + to_string(graph.cell(node)) + " is a blocked cell");
  }
}

}  // namespace aco
