#pragma once
// One planning run as the hosts see it: a planner (the colony, or a reference planner) on a
// graph, then the smoother, with everything a result file records. acoplan and acobench share it.
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "aco/colony.hpp"
#include "aco/path.hpp"
#include "aco/pipeline.hpp"
#include "aco/run_spec.hpp"

namespace aco {

// "aco" (the colony) and the planners it is compared with: "astar" (exact reference), and the
// baselines of the papers that are not ant colonies.
std::vector<std::string> planner_names();
// A planner's own parameter table (empty for aco, whose settings are the colony's and the
// plugins', and for astar). Throws for an unknown planner.
std::span<const ParamSpec> planner_parameters(const std::string& planner);

struct PlanOutcome {
  std::uint64_t seed = 0;
  bool solved = false;
  std::string reason;  // why not solved
  NodeId start = 0;
  NodeId goal = 0;
  std::vector<NodeId> grid_path;
  double grid_length = 0.0;
  Waypoints path;  // after the smoother
  double length = 0.0;
  int turns = 0;
  int iterations = 0;      // iterations (generations) run
  int best_iteration = 0;  // first that reached the final best
  double time_ms = 0.0;
  std::uint64_t ant_steps = 0;
  std::uint64_t evaluations = 0;  // candidate solutions decoded by a baseline planner (ifwa, pso)
  std::string stopped_by;  // which rule ended the run
  std::vector<double> best_so_far;
  std::vector<double> iteration_best;
  std::vector<double> pheromone;
};

// Plans once. An unreachable goal is an unsolved outcome with its reason, not an error.
// The run's problem is not read: `graph`, `start` and `goal` are its (hosts load and check it
// with load_problem()); its colony seed seeds every planner.
PlanOutcome plan(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal, const RunSpec& run);

}  // namespace aco
