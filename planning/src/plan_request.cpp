#include "aco/planning/plan_request.hpp"

#include <algorithm>
#include <chrono>

#include "aco/engine/coarse_to_fine.hpp"
#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "aco/planning/run_report.hpp"
#include "aco/thread_limit.hpp"

namespace aco {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point began) { return std::chrono::duration<double>(Clock::now() - began).count(); }

// A voxel world of millions of voxels (coarsens_world()) is planned in a corridor chosen before
// its graph is built: the whole graph of Warframe's DB1 (49 million voxels, 1.27 billion edges)
// would need 27 GiB. The world in blocks of `coarse-to-fine` voxels a side is planned by the
// request's pipeline with half the time left (as a 2D map's coarse level in run_colony()), in its
// own corridor while it is that large; the graph then holds the voxels within two blocks of the
// coarse path (in blocks of 2, four voxels either side, as a 2D map's one block of 4 cells), or
// four or eight blocks where two did not join start and goal. Where start or goal
// sits in a nook whose blocks are closed, the blocks around it are opened, one and two deep. The
// whole world's graph is built only where no corridor joins start and goal, or where the coarse
// colony found no path with no time limit to blame.
struct WorldGraph {
  Graph graph;
  std::optional<PlanOutcome> coarse;  // the coarse colony's run, where one was made
  bool corridor = false;  // the graph is the coarse path's corridor
};

// A coarse colony stopped by the time limit before it found a path.
bool out_of_time(const WorldGraph& world, const RunSpec& run) {
  return world.coarse && !world.coarse->solved() && run.colony.time_limit > 0;
}

WorldGraph world_graph(PluginRegistry& registry, const Map& map, Cell start, Cell goal, const RunSpec& run,
                       Clock::time_point began) {
  const int block = run.colony.coarse_to_fine;
  WorldGraph world;
  if (run.planner == "aco" && block > 1 && coarsens_world(map))
    for (int opened = 0; opened <= 2; ++opened) {
      const std::optional<CoarseMap> blocks = coarse_map(map, start, goal, block, opened);
      if (!blocks) break;
      RunSpec level = run;
      level.colony.explorers = run.colony.coarse_explorers;
      const auto level_began = Clock::now();
      if (run.colony.time_limit > 0)
        level.colony.time_limit = std::max((run.colony.time_limit - seconds_since(began)) / 2, 1e-3);
      WorldGraph coarser = world_graph(registry, *blocks->map, blocks->start, blocks->goal, level, level_began);
      const Graph& coarse = coarser.graph;
      if (out_of_time(coarser, run)) world.coarse = std::move(coarser.coarse);
      coarser.coarse.reset();
      const NodeId from = coarse.node(blocks->start), to = coarse.node(blocks->goal);
      if (!world.coarse && !reachable(coarse, from, to)) continue;
      if (run.colony.time_limit > 0)
        level.colony.time_limit = std::max(level.colony.time_limit - seconds_since(level_began), 1e-3);
      if (!world.coarse) {
        world.coarse = plan(registry, coarse, from, to, level);
        // Its path is what the level below uses: its per-edge fields' memory goes now.
        world.coarse->pheromone = {};
        world.coarse->pheromone_edges = {};
      }
      if (out_of_time(world, run)) {
        // The whole world would take longer still: no graph edges, the coarse colony's reason.
        const std::vector<std::uint8_t> every_voxel(std::size_t(map.width()) * map.height() * map.depth(), 1);
        world.graph = build_graph(map, run.graph, every_voxel);
        return world;
      }
      for (int radius = 2; world.coarse->solved() && radius <= 8; radius *= 2) {
        world.graph = {};
        world.graph =
            build_graph(map, run.graph, coarse_corridor(map, coarse, world.coarse->search.path, block, radius));
        world.corridor = reachable(world.graph, world.graph.node(start), world.graph.node(goal));
        if (world.corridor) return world;
      }
      break;
    }
  world.graph = {};  // a corridor's graph that did not join start and goal: gone before the whole one is made
  world.graph = build_graph(map, run.graph);
  return world;
}

}  // namespace

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
  const auto began = Clock::now();
  WorldGraph world = world_graph(registry, *planned.map, start, goal, request.run, began);
  planned.graph = std::move(world.graph);
  const NodeId from = planned.graph.node(start), to = planned.graph.node(goal);
  // No corridor, and no coarse colony out of time: the whole world's graph (world_graph() built it).
  if (!world.corridor && !out_of_time(world, request.run)) {
    planned.runs = plan_runs(registry, planned.graph, from, to, request.run, request.repeat);
    return planned;
  }
  // In the corridor: the time limit left, and the coarse levels counted in each run's time. Out
  // of time at a coarse level: the runs say so.
  const double spent_s = seconds_since(began);
  if (world.corridor) {
    RunSpec fine = request.run;
    if (fine.colony.time_limit > 0) fine.colony.time_limit = std::max(fine.colony.time_limit - spent_s, 1e-3);
    planned.runs = plan_runs(registry, planned.graph, from, to, fine, request.repeat, /*whole_map=*/false);
  } else {
    for (std::int64_t i = 0; i < request.repeat; ++i) {
      PlanRun& run = planned.runs.emplace_back();
      run.seed = request.run.colony.seed + static_cast<std::uint64_t>(i);
      run.start = from;
      run.goal = to;
      run.reason = "the time limit (" + to_string(ParamValue(request.run.colony.time_limit)) +
                   " s) ran out before the colony on the world in blocks of " +
                   std::to_string(request.run.colony.coarse_to_fine) +
                   " voxels a side (coarse to fine) found a path (give it more time)";
    }
  }
  for (PlanRun& run : planned.runs) {
    run.time_ms += 1000.0 * spent_s;
    run.properties["coarse.length"] = world.coarse->solved() ? world.coarse->search.length : -1.0;
    run.properties["coarse.corridor"] = std::string(world.corridor ? "walked" : "not used");
  }
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
