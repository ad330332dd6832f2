#pragma once
// What acoplan prints of its runs, as a library: the readable summary and the JSON object
// (acoplan's --json; the Python package returns the same content) of the runs of one configuration
// over consecutive seeds, each beside its yardsticks (aco/planning/yardsticks.hpp).
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/planning/planning.hpp"
#include "aco/planning/yardsticks.hpp"

namespace aco {

// What the reports say of the configuration. `pipeline_source` is the readable "preset:" line
// ("robust (the default for 2D maps ...)"); empty leaves the line out.
struct PlanReport {
  const RunSpec& run;
  PluginRegistry& registry;
  const Graph& graph;
  std::string pipeline_source;
};

// One run: its measures, the resolved configuration and the plugins' provenance, as one JSON
// object (compact, as acoplan --json prints it); run_record() is the same object as a value
// (Python's aco.Result holds it as a dict).
std::string to_json(const PlanReport& report, const PlanRun& run);
nlohmann::json run_record(const PlanReport& report, const PlanRun& run);
std::string summary(const PlanReport& report, const PlanRun& run);

// Several seeds of one configuration: every run, and mean, standard deviation, min and max of
// each measure over the solved runs.
std::string to_json(const PlanReport& report, const std::vector<PlanRun>& runs);
std::string summary(const PlanReport& report, const std::vector<PlanRun>& runs);

}  // namespace aco
