#include "aco/planning/yardsticks.hpp"

#include "aco/astar.hpp"

namespace aco {

Yardsticks yardsticks(const Graph& graph, NodeId start, NodeId goal, const OptimalCorridor* corridor) {
  Yardsticks y;
  if (const auto optimal = astar(graph, start, goal)) y.optimal_length = optimal->length;
  if (corridor && corridor->optimum()) y.any_angle_length = corridor->optimum()->length;
  return y;
}

double relative_gap(double length, double optimal) {
  return length == optimal ? 0.0 : length / optimal - 1.0;  // start = goal: 0 over 0 is no gap
}
double gap_percent(double length, double optimal) { return 100.0 * relative_gap(length, optimal); }

std::optional<bool> judge_corridor(const OptimalCorridor& corridor, PlanOutcome& run) {
  if (run.properties.count("corridors"))
    if (const auto walked = corridor.among(run.corridors))
      run.properties["optimal_corridor_walked"] = std::int64_t{*walked ? 1 : 0};
  return run.solved() ? corridor.contains(run.path) : std::nullopt;
}

std::vector<PlanRun> plan_runs(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal,
                               const RunSpec& run, std::int64_t count, bool whole_map) {
  RunSpec seeded = run;
  std::vector<PlanRun> runs;
  for (std::int64_t i = 0; i < count; ++i, ++seeded.colony.seed) {
    PlanRun o;
    static_cast<PlanOutcome&>(o) = plan(registry, graph, start, goal, seeded);
    runs.push_back(std::move(o));
  }
  const OptimalCorridor corridor(*graph.map, graph.cell(start), graph.cell(goal));
  const Yardsticks measures = whole_map ? yardsticks(graph, start, goal, &corridor) : Yardsticks{};
  for (auto& o : runs) {
    o.optimal_length = measures.optimal_length;
    o.any_angle_length = measures.any_angle_length;
    o.optimal_corridor = judge_corridor(corridor, o);
  }
  return runs;
}

}  // namespace aco
