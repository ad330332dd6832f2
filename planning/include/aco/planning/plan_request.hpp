#pragma once
// One planning request, whichever front end makes it: acoplan's command line and Python's
// aco.plan() resolve their keys over the pipeline PipelineSource chose (aco/planning/presets.hpp), then
// plan() reads the map (or takes the caller's), builds the graph, plans under the memory and
// thread limits, and measures every run by its yardsticks (aco/planning/yardsticks.hpp). What comes back
// is kept whole: the map, the graph, the runs; reports and pictures are made from it.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/planning/yardsticks.hpp"

namespace aco {

struct PlanRequest {
  RunSpec run;  // the resolved keys: the problem's map file, start and goal, the pipeline
  std::shared_ptr<const Map> map;  // a map the caller made (Python's arrays); null: run.problem's file
  std::string pipeline_source;  // PipelineSource::description(): the summary's "preset:" line
  int threads = 0;  // 0 = all cores
  std::optional<std::uint64_t> max_memory;  // bytes; none: the default limit (aco/memory_limit.hpp)
  std::int64_t repeat = 1;  // runs with seeds seed, seed+1, ..., seed+repeat-1
  // A front end's own checks of the map, before its start and goal are checked (Python refuses a
  // voxel world's cell given as (x, y), which the command line reads as layer 0).
  std::function<void(const Map& map)> check_map;
  KeySpelling spelling = "--";  // how messages name keys (--max-memory, --map-format): acoplan's options
};

struct PlannedRuns {
  RunSpec run;
  std::string pipeline_source;
  PluginRegistry* registry = nullptr;
  std::shared_ptr<const Map> map;
  Graph graph;  // on *map
  std::vector<PlanRun> runs;

  const PlanRun& best() const;  // the shortest solved run, else the first: the one pictures show
  bool all_solved() const;
  // acoplan's --json (one run's object, or several runs' with their summary) and readable summary.
  std::string json() const;
  std::string summary() const;
};

// Plans the request. An unreachable goal is an unsolved run with its reason; a bad map, cell or
// memory limit throws an Error.
PlannedRuns plan(const PlanRequest& request, PluginRegistry& registry);

}  // namespace aco
