#include "aco/studies/trial_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <nlohmann/json.hpp>
#include <shared_mutex>

#include "aco/corridor.hpp"
#include "aco/error.hpp"
#include "aco/machine.hpp"
#include "aco/plugin_error.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/planning/yardsticks.hpp"
#include "aco/plugin_call.hpp"
#include "aco/simulation/batch.hpp"

namespace aco::studies {
namespace {

// [[x, y], ...], or [[x, y, z], ...] on a terrain (heights) or in a voxel world (layers).
std::string path_json(const aco::Waypoints& path, bool in_space = false) {
  const bool flat = !in_space && std::all_of(path.begin(), path.end(), [](const auto& p) { return p.z() == 0.0; });
  nlohmann::json j = nlohmann::json::array();
  for (const auto& p : path) {
    if (flat)
      j.push_back({p.x(), p.y()});
    else
      j.push_back({p.x(), p.y(), p.z()});
  }
  return j.dump();
}

// A problem's maps by terrain options, and their graphs by neighbourhood and corner rule.
// Loading checks start and goal as acoplan does (aco::load_problem).
struct PreparedProblem {
  using TerrainKey = std::tuple<double, double, double>;
  using GraphKey = std::tuple<TerrainKey, int, bool>;
  std::string name;
  aco::ProblemSpec spec;
  aco::PluginRegistry* registry = nullptr;  // the map plugins
  std::map<TerrainKey, aco::LoadedProblem> maps;
  std::map<GraphKey, aco::Graph> graphs;
  // The any-angle optimum and its corridor on the map of these terrain options, when first asked.
  std::map<TerrainKey, aco::OptimalCorridor> corridors;

  static TerrainKey terrain_key(const aco::TerrainOptions& t) { return {t.max_slope_deg, t.height_scale, t.cell_size}; }
  static GraphKey graph_key(const aco::RunSpec& run) {
    return {terrain_key(run.problem.terrain), static_cast<int>(run.graph.neighbourhood), run.graph.corner_cutting};
  }
  const aco::Map& map(const aco::TerrainOptions& terrain) {
    auto it = maps.find(terrain_key(terrain));
    if (it == maps.end()) {
      aco::ProblemSpec with = spec;
      with.terrain = terrain;
      it = maps.emplace(terrain_key(terrain), aco::load_problem(with, registry)).first;
    }
    return *it->second.map;
  }
  const aco::OptimalCorridor& corridor(const aco::TerrainOptions& terrain, aco::Cell start, aco::Cell goal) {
    auto it = corridors.find(terrain_key(terrain));
    if (it == corridors.end()) it = corridors.try_emplace(terrain_key(terrain), map(terrain), start, goal).first;
    return it->second;
  }
  // Errors (a map that does not load, a blocked start with these terrain options) name the problem.
  const aco::Graph& graph(const aco::RunSpec& run) {
    auto it = graphs.find(graph_key(run));
    if (it != graphs.end()) return it->second;
    try {
      return graphs.emplace(graph_key(run), aco::build_graph(map(run.problem.terrain), run.graph)).first->second;
    } catch (const aco::Error& error) {
      throw aco::Error("problem '" + name + "': " + error.what());
    }
  }
};

}  // namespace

// add_config() may prepare a configuration (on an MPI worker) while trials of others run: it
// writes under the lock, a trial looks up its configuration and graph under it.
struct TrialRunner::Problems {
  std::vector<PreparedProblem> list;
  std::shared_mutex mutex;
};

struct TrialRunner::Prepared {
  Configuration config;
  aco::RunSpec run;
  std::map<int, aco::simulation::Scenario>
      scenarios;  // per simulation problem: its scenario with this configuration's keys
};

TrialRunner::TrialRunner(const Experiment& experiment, aco::PluginRegistry& registry)
    : experiment_(experiment), registry_(registry), problems_(std::make_unique<Problems>()) {
  for (const Problem& p : experiment.problems) {
    PreparedProblem prepared;
    prepared.name = p.name;
    prepared.spec.map = p.map;
    prepared.spec.map_format = p.map_format;
    prepared.spec.map_parameters = p.map_parameters;
    prepared.registry = &registry;
    prepared.spec.start = p.start;
    prepared.spec.goal = p.goal;
    problems_->list.push_back(std::move(prepared));
  }
}

TrialRunner::~TrialRunner() = default;

void TrialRunner::add_config(int id, const Configuration& c) {
  const std::unique_lock lock(problems_->mutex);
  if (configs_.contains(id)) return;
  auto prepared = std::make_unique<Prepared>();
  prepared->config = c;
  prepared->run = c.run ? *c.run : resolve(c, experiment_.problems, registry_);
  try {
    for (std::size_t p = 0; p < problems_->list.size(); ++p) {
      if (const auto& scenario = experiment_.problems[p].simulation) {
        try {
          prepared->scenarios.emplace(static_cast<int>(p),
                                      aco::simulation::with_run_keys(*scenario, run_keys(c), registry_));
        } catch (const aco::Error& error) {
          throw aco::Error("problem '" + problems_->list[p].name + "': " + error.what());
        }
      } else {
        problems_->list[p].graph(prepared->run);
      }
    }
  } catch (const aco::Error& error) {
    throw aco::Error("configuration '" + c.name + "', " + error.what());
  }
  configs_.emplace(id, std::move(prepared));
}

const Configuration& TrialRunner::config(int id) const {
  const std::shared_lock lock(problems_->mutex);
  return configs_.at(id)->config;
}

const aco::Graph& TrialRunner::graph(int problem, const aco::RunSpec& run) {
  const std::unique_lock lock(problems_->mutex);
  return problems_->list.at(static_cast<std::size_t>(problem)).graph(run);
}

const aco::OptimalCorridor& TrialRunner::corridor(int problem, const aco::RunSpec& run) {
  const std::unique_lock lock(problems_->mutex);
  const Problem& p = experiment_.problems[static_cast<std::size_t>(problem)];
  return problems_->list.at(static_cast<std::size_t>(problem)).corridor(run.problem.terrain, p.start, p.goal);
}

TrialRecord TrialRunner::run(const TrialOrder& t) {
  TrialRecord r = [&] {
    try {
      return experiment_.problems[t.problem].simulation ? simulate(t) : plan(t);
    } catch (const aco::OutOfMemoryError& e) {
      return failed(t, FailureKind::out_of_memory, e.what());
    } catch (const std::bad_alloc&) {
      return failed(t, FailureKind::out_of_memory, "out of memory (std::bad_alloc)");
    } catch (const aco::InvalidValueError& e) {
      return failed(t, FailureKind::invalid_value, e.what());
    } catch (const aco::PluginError& e) {
      return failed(t, FailureKind::plugin_error, e.what());
    } catch (...) {
      return failed(t, FailureKind::error, aco::describe_current_exception());
    }
  }();
  r.peak_memory_mib = peak_memory_mib();
  return r;
}

TrialRecord TrialRunner::failed(const TrialOrder& t, FailureKind kind, const std::string& reason) const {
  TrialRecord r;
  r.problem = t.problem;
  r.config = t.config;
  r.repetition = t.repetition;
  r.seed = trial_seed(experiment_.seed, experiment_.problems[t.problem].name, t.repetition);
  // stopped_by keeps the four values the report's table of failures counts.
  const bool threw =
      kind == FailureKind::plugin_error || kind == FailureKind::invalid_value || kind == FailureKind::error;
  r.stopped_by = to_string(threw ? FailureKind::error : kind);
  r.failure = kind;
  r.path_json = "[]";
  r.error = "configuration '" + config(t.config).name + "', problem '" + experiment_.problems[t.problem].name +
            "', repetition " + std::to_string(t.repetition) + ": " + reason;
  return r;
}

TrialRecord TrialRunner::plan(const TrialOrder& t) {
  const Problem& problem = experiment_.problems[t.problem];
  const aco::Graph* graph = nullptr;
  aco::RunSpec run;
  {
    const std::shared_lock lock(problems_->mutex);
    run = configs_.at(t.config)->run;
    graph = &problems_->list[t.problem].graphs.at(PreparedProblem::graph_key(run));
  }
  run.colony.seed = trial_seed(experiment_.seed, problem.name, t.repetition);
  if (t.time_limit_s > 0.0) run.planner_parameters.set("time_limit", t.time_limit_s);
  aco::PlanOutcome o = aco::plan(registry_, *graph, graph->node(problem.start), graph->node(problem.goal), run);
  TrialRecord r;
  r.problem = t.problem;
  r.config = t.config;
  r.repetition = t.repetition;
  r.seed = o.seed;
  r.solved = o.solved();
  r.length = o.length;
  r.grid_length = o.search.length;
  if (r.solved || o.properties.count("corridors"))
    r.optimal_corridor = aco::judge_corridor(corridor(t.problem, run), o);
  r.turns = o.turns;
  r.iterations = o.search.iterations;
  r.best_iteration = o.search.best_iteration;
  r.time_s = o.time_ms / 1000.0;
  r.ant_steps = static_cast<std::uint64_t>(o.count("ant_steps"));
  r.stopped_by = o.text("stopped_by");
  r.path_json = path_json(o.path, graph->volumetric);
  r.best_so_far = o.search.best_so_far;
  r.elapsed_s = o.search.elapsed_s;
  r.walks = o.search.walks;
  r.properties = o.properties;
  // So that the report can check that both sides of an equal-time pair had the same time.
  if (t.time_limit_s > 0.0) r.properties["time_limit"] = t.time_limit_s;
  return r;
}

// A simulation trial: the robot driven through the scenario (or the trial's variation of it)
// with the configuration's run; the colony's seed is the trial's. length is the distance
// driven, path the trajectory.
TrialRecord TrialRunner::simulate(const TrialOrder& t) {
  const Problem& problem = experiment_.problems[t.problem];
  const std::uint64_t seed = trial_seed(experiment_.seed, problem.name, t.repetition);
  const auto began = std::chrono::steady_clock::now();
  // Variations are drawn on the scenario as written, so every configuration meets the same ones.
  aco::simulation::Scenario scenario =
      problem.variations ? aco::simulation::variations(*problem.simulation, 1, seed, registry_).front()
                         : *problem.simulation;
  {
    const std::shared_lock lock(problems_->mutex);
    const aco::simulation::Scenario& configured = configs_.at(t.config)->scenarios.at(t.problem);
    scenario.keys = configured.keys;
    scenario.run = configured.run;
  }
  scenario.run.colony.seed = seed;
  const aco::simulation::SimulationResult sim = aco::simulation::simulate(scenario, registry_);
  TrialRecord r;
  r.problem = t.problem;
  r.config = t.config;
  r.repetition = t.repetition;
  r.seed = seed;
  r.solved = sim.reached;
  r.length = r.grid_length = sim.distance;
  r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  r.stopped_by = sim.outcome;
  aco::Waypoints trajectory;
  const std::size_t every = std::max<std::size_t>(1, sim.frames.size() / 500);  // at most ~500 points
  for (std::size_t i = 0; i < sim.frames.size(); i += every)
    trajectory.emplace_back(sim.frames[i].robot.x, sim.frames[i].robot.y, 0.0);
  trajectory.emplace_back(sim.frames.back().robot.x, sim.frames.back().robot.y, 0.0);
  r.path_json = path_json(trajectory);
  r.simulation = SimulationRecord{sim.outcome,
                                  sim.reached ? sim.time : std::nan(""),
                                  sim.collisions,
                                  sim.replans,
                                  std::isfinite(sim.min_clearance) ? sim.min_clearance : std::nan(""),
                                  sim.steps};
  return r;
}

std::string settings_json(const Configuration& config, const aco::RunSpec& run, const aco::PluginRegistry& registry) {
  nlohmann::json j;
  j["keys"] = config.keys;
  j["run"] = nlohmann::ordered_json::parse(run_json(config, run));
  // Name, version and hash of each slot's binary; not its file (a moved build is the same), nor its
  // build, which its hash implies (and databases stored before it was recorded must match).
  j["plugins"] = nlohmann::ordered_json::parse(aco::plugins_json(run, registry));
  for (auto& plugin : j["plugins"]) plugin.erase("file"), plugin.erase("build");
  return j.dump();
}

}  // namespace aco::studies
