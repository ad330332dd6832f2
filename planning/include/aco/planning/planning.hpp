#pragma once
// One planning run as the hosts see it: a planner (the colony, or one it is compared with) on a
// graph, then the smoother, with everything a result file records. acoplan and acobench share it.
//
// Planners are a table (as OMPL's planners are classes behind one interface): a name, a
// parameter table, a check of its values, and a run function. A new planner is one more row in
// planning.cpp; hosts, the irace dump and the run keys ("<planner>.<parameter>") iterate it.
#include <chrono>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "aco/figures.hpp"
#include "aco/path.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/search_result.hpp"

namespace aco {

struct PlanOutcome {
  std::uint64_t seed = 0;
  NodeId start = 0;
  NodeId goal = 0;
  // The planner's best grid path, its length, iterations and curve. A continuous planner (ompl)
  // has no grid path: `search.path` is empty and `search.length` NaN; its curve is in path lengths.
  SearchResult search;
  std::string reason;  // why not solved
  Waypoints path;  // after the smoother; a continuous planner's own path
  double length = 0.0;  // of `path`
  int turns = 0;
  double time_ms = 0.0;
  // Planner-specific measures (OMPL's run properties): "ant_steps", "stopped_by" and "corridors"
  // (aco; with the optimum's corridor known, "optimal_corridor_walked", set by plan_runs() and
  // acobench: 1 if any walk took it, whether or not the best path stayed there),
  // "evaluations" (ifwa, pso: candidate solutions decoded into walks); and the figures the run's
  // plugins recorded (Context::record(), add()) as "<slot>/<plugin>.<name>", an integer (a count)
  // or a real. Hosts write them all alike: acoplan's --json, acobench's database and runs.csv.
  std::map<std::string, ParamValue> properties;
  std::vector<double> iteration_best;  // aco: per iteration, for pictures
  std::vector<double> pheromone;  // aco: final tau per edge, for pictures
  std::vector<EdgeId> pheromone_edges;  // aco, coarse to fine: each value's edge (ColonyResult's)
  std::vector<std::uint64_t> corridors;  // aco: the corridors its walks took (ColonyResult::corridors)

  bool solved() const { return search.solved; }
  std::int64_t count(const std::string& property) const;  // an integer property, 0 if absent
  std::string text(const std::string& property) const;  // a text property, "" if absent
};

// What a planner's run function gets. `pipeline` is the run's plugins, instantiated (the
// colony uses them all; every planner's path goes through the smoother afterwards).
struct PlanContext {
  PluginRegistry& registry;
  const Graph& graph;
  NodeId start;
  NodeId goal;
  const RunSpec& run;
  const PipelinePlugins& pipeline;
  FigureSink& figures;  // where the plugins' figures go (plan() adds them to the properties)
  std::chrono::steady_clock::time_point began;  // the search's start, which a time limit counts from
};

struct Planner {
  const char* name;
  const char* help;
  std::span<const ParamSpec> (*parameters)();  // its own table, "<name>.<parameter>" keys; may be empty
  void (*check)(const ParameterValues& values);  // values that are wrong together (Error); may be null
  // Fills outcome.search (path, length, iterations, curve) and its properties; the goal is reachable.
  // A continuous planner fills outcome.path instead of search.path (and search.length).
  void (*run)(const PlanContext& context, PlanOutcome& outcome);
  // Plans in the plane, not on the graph: its path is a polyline at any angles, which plan() takes
  // as it is (checked, measured; no smoother, which resolve_run() refuses for it) with no grid path.
  bool continuous = false;
  // Plans in voxel worlds too (the 6-, 18- and 26-neighbourhoods); others are refused there.
  bool volumetric = false;
};

// aco (the colony), astar (exact reference), ifwa (paper 004), pso (paper 000's baseline), and
// ompl (OMPL's sampling planners, continuous) where the build found OMPL.
std::span<const Planner> planners();
const Planner& find_planner(const std::string& name);  // Error naming the planners for an unknown name
std::vector<std::string> planner_names();
std::vector<std::string> planners_with_parameters();  // those with keys "<planner>.<parameter>"
std::span<const ParamSpec> planner_parameters(const std::string& planner);

// Plans once. An unreachable goal is an unsolved outcome with its reason, not an error. The
// run's problem is not read: `graph`, `start` and `goal` are its (load_problem()); its colony
// seed seeds every planner.
PlanOutcome plan(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal, const RunSpec& run);

}  // namespace aco
