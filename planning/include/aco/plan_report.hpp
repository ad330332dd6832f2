#pragma once
// What acoplan prints of a run, as a library: the runs of one configuration over consecutive
// seeds, each beside the exact A* optimum, and their readable summary and JSON object (acoplan's
// --json; the Python package returns the same content).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/planning.hpp"

namespace aco {

struct PlanRun : PlanOutcome {
  std::optional<double> optimal_length;  // exact A* reference on the same graph; none if unreachable
  // The exact any-angle optimum (aco/any_angle.hpp), the yardstick of the final path's length, and
  // whether the final path runs through its corridor (aco/corridor.hpp); none on maps other than
  // flat grids, or when no path joins start and goal.
  std::optional<double> any_angle_length;
  std::optional<bool> optimal_corridor;
};

class OptimalCorridor;

// Sets a colony run's property "optimal_corridor_walked" (a run with "corridors"): 1 when any of
// its walks took the optimum's corridor, 0 when none did. With the final path's corridor, that
// tells a run that never explored the right corridor from one that explored it and left it.
// Nothing where the optimum is unknown (maps other than flat grids, no path).
void note_optimal_corridor_walked(const OptimalCorridor& corridor, PlanOutcome& run);

// `count` runs of `run` with seeds seed, seed+1, ..., each with the A* optimum, the any-angle
// optimum and its corridor.
std::vector<PlanRun> plan_runs(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal,
                               const RunSpec& run, std::int64_t count);

// What the reports say of the configuration. `pipeline_source` is the readable "preset:" line
// ("robust (the default for 2D maps ...)"); empty leaves the line out.
struct PlanReport {
  const RunSpec& run;
  PluginRegistry& registry;
  const Graph& graph;
  std::string pipeline_source;
};

// One run: its measures, the resolved configuration and the plugins' provenance, as one JSON
// object (compact, as acoplan --json prints it).
std::string to_json(const PlanReport& report, const PlanRun& run);
std::string summary(const PlanReport& report, const PlanRun& run);

// Several seeds of one configuration: every run, and mean, standard deviation, min and max of
// each measure over the solved runs.
std::string to_json(const PlanReport& report, const std::vector<PlanRun>& runs);
std::string summary(const PlanReport& report, const std::vector<PlanRun>& runs);

}  // namespace aco
