#include "aco/planning/planning.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include "aco/astar.hpp"
#include "aco/engine/colony.hpp"
#include "aco/plugin_error.hpp"
#include "aco/error.hpp"
#include "aco/path.hpp"
#include "aco/engine/plugin_guard.hpp"
#include "ifwa/fireworks.hpp"
#include "pso/pso.hpp"
#ifdef ACO_WITH_OMPL
#include "ompl/ompl_planner.hpp"
#endif

namespace aco {
namespace {

std::span<const ParamSpec> no_parameters() { return {}; }

void run_aco(const PlanContext& c, PlanOutcome& o) {
  ColonySettings settings = c.run.colony;
  settings.search_began = c.began;
  ColonyResult colony =
      run_pipeline(c.registry, c.run.pipeline, c.pipeline, c.graph, c.start, c.goal, settings, &c.figures);
  o.properties["ant_steps"] = static_cast<std::int64_t>(colony.ant_steps);
  o.properties["stopped_by"] = std::string(to_string(colony.stopped_by));
  if (!c.graph.volumetric) o.properties["corridors"] = static_cast<std::int64_t>(colony.corridors.size());
  if (colony.coarse) {  // coarse to fine: the coarse colony's path, in the coarse map's steps
    o.properties["coarse.length"] = colony.coarse->solved ? colony.coarse->length : -1.0;
    o.properties["coarse.corridor"] = std::string(colony.walked_coarse_corridor ? "walked" : "not used");
  }
  if (c.run.colony.restart_after > 0 || c.run.colony.colonies > 1)
    o.properties["restarts"] = static_cast<std::int64_t>(colony.restarts);
  o.corridors = std::move(colony.corridors);
  o.iteration_best = std::move(colony.iteration_best);
  o.pheromone = std::move(colony.pheromone);
  o.pheromone_edges = std::move(colony.pheromone_edges);
  o.search = std::move(static_cast<SearchResult&>(colony));
  if (!o.search.solved && colony.stopped_by == StopReason::time)
    o.reason = "the time limit (" + to_string(ParamValue(c.run.colony.time_limit)) +
               " s) ended the search in iteration " + std::to_string(o.search.iterations) +
               ", before any ant reached the goal (give it more time)";
  else if (!o.search.solved)
    o.reason = "no ant reached the goal in " + std::to_string(o.search.iterations) +
               " iterations (try more ants or iterations, or another deadlock policy)";
}

// One iteration building one path, so that A* has anytime curves like every planner.
void run_astar(const PlanContext& c, PlanOutcome& o) {
  const SearchClock clock;
  o.search.path = astar(c.graph, c.start, c.goal)->nodes;
  o.search.solved = true;
  o.search.length = path_length(c.graph, o.search.path);
  o.search.iterations = 1;
  o.search.best_so_far = {o.search.length};
  clock.record(o.search, 1);
  o.search.finish();
}

// IFWA and PSO: their own settings, the run's seed.
template <class Settings, class Result>
void run_baseline(const PlanContext& c, PlanOutcome& o, Settings settings,
                  Result (*search)(const Graph&, NodeId, NodeId, const Settings&)) {
  settings.seed = c.run.colony.seed;
  PlannerResult result = search(c.graph, c.start, c.goal, settings);
  o.properties["evaluations"] = static_cast<std::int64_t>(result.evaluations);
  o.search = std::move(static_cast<SearchResult&>(result));
  if (!o.search.solved)
    o.reason = "no feasible path found in " + std::to_string(o.search.iterations) +
               " iterations (try more iterations or particles)";
}

void run_ifwa(const PlanContext& c, PlanOutcome& o) {
  run_baseline(c, o, fireworks_settings(c.run.planner_parameters), run_fireworks);
}
void run_pso(const PlanContext& c, PlanOutcome& o) {
  run_baseline(c, o, pso_settings(c.run.planner_parameters), aco::run_pso);
}

#ifdef ACO_WITH_OMPL
// OMPL's planners: a continuous path, the run's seed as far as OMPL takes one (ompl_planner.hpp).
void run_ompl(const PlanContext& c, PlanOutcome& o) {
  OmplSettings settings = ompl_settings(c.run.planner_parameters);
  settings.seed = c.run.colony.seed;
  OmplResult result = aco::run_ompl(c.graph, c.start, c.goal, settings);
  o.properties["ompl.graph_states"] = result.graph_states;
  o.properties["ompl.motion_checks"] = result.motion_checks;
  o.properties["ompl.solve_time"] = result.solve_time_s;
  o.properties["ompl.simplification_time"] = result.simplification_time_s;
  o.properties["ompl.status"] = result.status;
  o.search.solved = result.solved;
  o.search.length = result.length;  // for finish(); plan() leaves NaN, there being no grid path
  o.search.iterations = static_cast<int>(result.best_so_far.size());
  o.search.best_so_far = std::move(result.best_so_far);
  o.search.elapsed_s = std::move(result.elapsed_s);
  o.search.walks = std::move(result.walks);
  o.search.finish();
  o.path = std::move(result.path);
  o.reason = std::move(result.reason);
}
#endif

const Planner kPlanners[] = {
    {"aco", "the colony", no_parameters, nullptr, run_aco, false, /*volumetric=*/true},
    {"astar", "exact shortest path on the same graph (reference)", no_parameters, nullptr, run_astar, false,
     /*volumetric=*/true},
    {"ifwa", "improved fireworks (paper 004)", fireworks_parameters,
     [](const ParameterValues& v) { fireworks_settings(v); }, run_ifwa},
    {"pso", "particle swarm over waypoints (paper 000's baseline)", pso_parameters, nullptr, run_pso},
#ifdef ACO_WITH_OMPL
    {"ompl", "OMPL's sampling planners in the plane (RRT-Connect, RRT*, BIT*, ...): a continuous path", ompl_parameters,
     [](const ParameterValues& v) { ompl_settings(v); }, run_ompl, /*continuous=*/true},
#endif
};

}  // namespace

std::int64_t PlanOutcome::count(const std::string& property) const {
  const auto it = properties.find(property);
  return it == properties.end() ? 0 : std::get<std::int64_t>(it->second);
}

std::string PlanOutcome::text(const std::string& property) const {
  const auto it = properties.find(property);
  return it == properties.end() ? "" : std::get<std::string>(it->second);
}

std::span<const Planner> planners() { return kPlanners; }

const Planner& find_planner(const std::string& name) {
  for (const Planner& p : kPlanners)
    if (name == p.name) return p;
  std::string known;
  for (const Planner& p : kPlanners) known += (known.empty() ? "" : ", ") + std::string(p.name);
  throw Error("unknown planner '" + name + "' (planners: " + known + ")");
}

std::vector<std::string> planner_names() {
  std::vector<std::string> names;
  for (const Planner& p : kPlanners) names.push_back(p.name);
  return names;
}

std::vector<std::string> planners_with_parameters() {
  std::vector<std::string> names;
  for (const Planner& p : kPlanners)
    if (!p.parameters().empty()) names.push_back(p.name);
  return names;
}

std::span<const ParamSpec> planner_parameters(const std::string& planner) { return find_planner(planner).parameters(); }

namespace {

// A voxel world is planned only by what says it can (Strategy::supports_voxel_worlds()): a plugin
// written for grids would read a voxel's neighbours as a grid's and plan wrong without a word.
void check_volumetric(const Graph& graph, const Planner& planner, const RunSpec& run, const PipelinePlugins& pipeline) {
  if (!graph.volumetric) return;
  const std::string world = graph.map->name() + " is a voxel world";
  if (!planner.volumetric)
    throw Error("planner '" + std::string(planner.name) + "' plans on 2D maps only; " + world +
                " (planners for voxel worlds: aco, astar)");
  const auto refuse = [&](const Strategy* plugin, const char* slot) {
    if (plugin != nullptr && !plugin->supports_voxel_worlds())
      throw Error(describe_plugin(*plugin, slot) + " does not plan in 3D; " + world +
                  " (docs/voxel-worlds.md lists the plugins that do)");
  };
  if (run.planner == "aco") {
    refuse(pipeline.init.get(), "init");
    refuse(pipeline.heuristic.get(), "heuristic");
    refuse(pipeline.update.get(), "update");
    refuse(pipeline.deadlock.get(), "deadlock");
  }
  refuse(pipeline.smoother.get(), "smoother");
}

}  // namespace

PlanOutcome plan(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal, const RunSpec& run) {
  const Planner& planner = find_planner(run.planner);
  const PipelinePlugins pipeline = instantiate(registry, run.pipeline);
  check_volumetric(graph, planner, run, pipeline);
  FigureSink figures;
  PlanOutcome o;
  o.seed = run.colony.seed;
  o.start = start;
  o.goal = goal;
  const auto began = std::chrono::steady_clock::now();
  if (!reachable(graph, start, goal)) {
    o.reason = "goal " + to_string(graph.cell(goal)) + " is not reachable from start " + to_string(graph.cell(start)) +
               " (" + describe(graph.options) + ")";
  } else {
    planner.run({registry, graph, start, goal, run, pipeline, figures, began}, o);
  }
  if (o.search.solved) {
    if (planner.continuous) {
      // The planner's own path, as it is: no grid path to measure or smooth.
      o.search.length = std::numeric_limits<double>::quiet_NaN();
      if (const std::string problem = waypoint_problem(graph, start, goal, o.path); !problem.empty())
        throw Error("planner '" + std::string(planner.name) + "' returned a bad path: " + problem);
    } else {
      Context context;
      context.graph = &graph;
      context.start = start;
      context.goal = goal;
      context.seed = run.colony.seed;
      context.figures = &figures;
      if (run.colony.time_limit > 0)
        context.deadline = began + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                       std::chrono::duration<double>(run.colony.time_limit));
      o.search.length = path_length(graph, o.search.path);
      pipeline.smoother->begin_run(context);
      o.path = pipeline.smoother->smooth(context, o.search.path);
      if (const std::string problem = waypoint_problem(graph, start, goal, o.path); !problem.empty())
        throw InvalidValueError(
            describe_plugin(*pipeline.smoother, "smoother") + " returned bad waypoints in smooth(): " + problem +
            " (waypoints must be finite and on free cells, from the start's position to the goal's)");
    }
    o.length = polyline_length(o.path);
    o.turns = count_turns(o.path, graph.volumetric);
  }
  o.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
  o.properties.merge(figures.figures());
  return o;
}

}  // namespace aco
