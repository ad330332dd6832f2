#include "aco/planning/plan_request.hpp"

#include <algorithm>

#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "aco/planning/run_report.hpp"
#include "aco/thread_limit.hpp"

namespace aco {

PlannedRuns plan(const PlanRequest& request, PluginRegistry& registry) {
  const MemoryLimit memory(request.max_memory, request.spelling);
  // From the start: building the graph runs in parallel too, and --threads 1 means no worker
  // thread at all (a signal sent to the process then reaches the thread in the plugin's hook).
  const ThreadLimit threads(request.threads);
  const ProblemSpec& problem = request.run.problem;
  PlannedRuns planned;
  planned.run = request.run;
  planned.pipeline_source = request.pipeline_source;
  planned.registry = &registry;
  Cell start, goal;
  if (request.map) {
    if (!problem.start || !problem.goal) throw Error("a problem needs start and goal");
    planned.map = request.map;
    start = *problem.start;
    goal = *problem.goal;
    check_ends(*planned.map, start, goal, request.check_map);
  } else {
    LoadedProblem loaded = load_problem(problem, &registry, request.check_map, request.spelling);
    planned.map = std::move(loaded.map);
    start = loaded.start;
    goal = loaded.goal;
  }
  planned.graph = build_graph(*planned.map, request.run.graph);
  planned.runs = plan_runs(registry, planned.graph, planned.graph.node(start), planned.graph.node(goal), request.run,
                           request.repeat);
  return planned;
}

const PlanRun& PlannedRuns::best() const {
  return *std::min_element(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
    return a.solved() != b.solved() ? a.solved() : a.length < b.length;
  });
}

bool PlannedRuns::all_solved() const {
  return std::all_of(runs.begin(), runs.end(), [](const auto& o) { return o.solved(); });
}

std::string PlannedRuns::json() const {
  const PlanReport report{run, *registry, graph, pipeline_source};
  return runs.size() == 1 ? to_json(report, runs.front()) : to_json(report, runs);
}

std::string PlannedRuns::summary() const {
  const PlanReport report{run, *registry, graph, pipeline_source};
  return runs.size() == 1 ? aco::summary(report, runs.front()) : aco::summary(report, runs);
}

}  // namespace aco
