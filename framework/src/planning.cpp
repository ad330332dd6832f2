#include "aco/planning.hpp"

#include <chrono>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/fireworks.hpp"
#include "aco/pso.hpp"

namespace aco {

std::vector<std::string> planner_names() { return {"aco", "astar", "ifwa", "pso"}; }

std::span<const ParamSpec> planner_parameters(const std::string& planner) {
  if (planner == "aco" || planner == "astar") return {};
  if (planner == "ifwa") return fireworks_parameters();
  if (planner == "pso") return pso_parameters();
  throw Error("unknown planner '" + planner + "'");
}

namespace {

// A baseline planner's search, with the run's seed.
PlannerResult run_baseline(const RunSpec& request, const Graph& graph, NodeId start, NodeId goal) {
  if (request.planner == "ifwa") {
    FireworksSettings s = fireworks_settings(request.planner_parameters);
    s.seed = request.colony.seed;
    return run_fireworks(graph, start, goal, s);
  }
  PsoSettings s = pso_settings(request.planner_parameters);
  s.seed = request.colony.seed;
  return run_pso(graph, start, goal, s);
}

}  // namespace

PlanOutcome plan(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal, const RunSpec& request) {
  const LoadedPipeline pipeline = instantiate(registry, request.pipeline);
  PlanOutcome o;
  o.seed = request.colony.seed;
  o.start = start;
  o.goal = goal;
  const auto began = std::chrono::steady_clock::now();
  if (!reachable(graph, start, goal)) {
    o.reason = "goal " + to_string(graph.cell(goal)) + " is not reachable from start " + to_string(graph.cell(start)) +
               " (" + describe(graph.options) + ")";
  } else if (request.planner == "astar") {
    o.solved = true;
    o.grid_path = astar(graph, start, goal)->nodes;
  } else if (request.planner == "ifwa" || request.planner == "pso") {
    PlannerResult baseline = run_baseline(request, graph, start, goal);
    o.solved = baseline.solved;
    o.grid_path = std::move(baseline.path);
    o.iterations = baseline.iterations;
    o.best_iteration = baseline.best_iteration;
    o.evaluations = baseline.evaluations;
    o.best_so_far = std::move(baseline.best_so_far);
    if (!o.solved)
      o.reason = "no feasible path found in " + std::to_string(o.iterations) + " iterations (try more iterations or particles)";
  } else if (request.planner == "aco") {
    ColonyResult colony = run_colony(registry, request.pipeline, pipeline, graph, start, goal, request.colony);
    o.solved = colony.solved;
    o.grid_path = std::move(colony.path);
    o.iterations = colony.iterations;
    o.best_iteration = colony.best_iteration;
    o.ant_steps = colony.ant_steps;
    o.stopped_by = colony.stopped_by;
    o.best_so_far = std::move(colony.best_so_far);
    o.iteration_best = std::move(colony.iteration_best);
    o.pheromone = std::move(colony.pheromone);
    if (!o.solved)
      o.reason = "no ant reached the goal in " + std::to_string(o.iterations) +
                 " iterations (try more ants or iterations, or another deadlock policy)";
  } else {
    throw Error("unknown planner '" + request.planner + "'");
  }
  if (o.solved) {
    Context context;
    context.graph = &graph;
    context.start = start;
    context.goal = goal;
    context.seed = request.colony.seed;
    o.grid_length = path_length(graph, o.grid_path);
    o.path = pipeline.smoother->smooth(context, o.grid_path);
    if (o.path.empty() || o.path.front() != graph.positions[start] || o.path.back() != graph.positions[goal])
      throw Error("the smoother plugin '" + request.pipeline.at("smoother").plugin +
                  "' returned a path that does not run from start to goal");
    o.length = polyline_length(o.path);
    o.turns = count_turns(o.path);
  }
  o.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
  return o;
}

}  // namespace aco
