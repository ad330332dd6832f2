#include "runner.hpp"


#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/map_io.hpp"
#include "aco/parallel.hpp"
#include "aco/planning.hpp"
#include "aco/plugin_guard.hpp"
#include "aco/thread_limit.hpp"
#include "acosim/batch.hpp"
#include "results_db.hpp"

namespace acobench {
namespace {

// A problem's maps by terrain options, and their graphs by neighbourhood and corner rule (built
// before the trials run). Loading checks start and goal as acoplan does (aco::load_problem).
struct PreparedProblem {
  using TerrainKey = std::tuple<double, double, double>;
  using GraphKey = std::tuple<TerrainKey, int, bool>;
  std::string name;
  aco::ProblemSpec spec;
  std::map<TerrainKey, aco::LoadedProblem> maps;
  std::map<GraphKey, aco::Graph> graphs;

  static TerrainKey terrain_key(const aco::TerrainOptions& t) { return {t.max_slope_deg, t.height_scale, t.cell_size}; }
  static GraphKey graph_key(const aco::RunSpec& run) {
    return {terrain_key(run.problem.terrain), static_cast<int>(run.graph.neighbourhood), run.graph.corner_cutting};
  }
  const aco::Map& map(const aco::TerrainOptions& terrain) {
    auto it = maps.find(terrain_key(terrain));
    if (it == maps.end()) {
      aco::ProblemSpec with = spec;
      with.terrain = terrain;
      it = maps.emplace(terrain_key(terrain), aco::load_problem(with)).first;
    }
    return *it->second.map;
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

struct PreparedConfig {
  int id = 0;  // in the database
  Configuration config;
  aco::RunSpec run;
  std::map<int, acosim::Scenario> scenarios;  // per simulation problem: its scenario with this configuration's keys
};

struct Trial {
  int problem = 0;
  const PreparedConfig* config = nullptr;
  int repetition = 0;
};

std::string path_json(const aco::Waypoints& path) {
  const bool flat = std::all_of(path.begin(), path.end(), [](const auto& p) { return p.z() == 0.0; });
  nlohmann::json j = nlohmann::json::array();
  for (const auto& p : path) {
    if (flat) j.push_back({p.x(), p.y()});
    else j.push_back({p.x(), p.y(), p.z()});
  }
  return j.dump();
}

// The configuration as the database stores it: the keys as written, and the resolved run (every
// key, the same names as acoplan's --json and --print-config).
std::string settings_json(const PreparedConfig& c, const aco::PluginRegistry& registry) {
  nlohmann::json j;
  j["keys"] = c.config.keys;
  j["run"] = nlohmann::ordered_json::parse(aco::to_json(c.run));
  // Name, version and hash of each slot's binary; not its file: a moved build is the same.
  j["plugins"] = nlohmann::ordered_json::parse(aco::plugins_json(c.run, registry));
  for (auto& plugin : j["plugins"]) plugin.erase("file");
  return j.dump();
}

class Runner {
 public:
  Runner(const Experiment& e, aco::PluginRegistry& registry, const RunOptions& options)
      : e_(e), registry_(registry), options_(options) {
    const aco::RunSpec base = e.baseline.run ? *e.baseline.run : resolve(e.baseline, e.problems, registry);
    std::vector<ProblemRecord> records;
    for (const Problem& p : e.problems) {
      PreparedProblem prepared;
      prepared.name = p.name;
      prepared.spec.map = p.map;
      prepared.spec.start = p.start;
      prepared.spec.goal = p.goal;
      // The optimal length, once per problem, on the baseline's graph (a 16-neighbourhood
      // configuration may beat it: its gap is then negative).
      const aco::Graph& graph = prepared.graph(base);
      const auto optimal = aco::astar(graph, graph.node(p.start), graph.node(p.goal));
      nlohmann::json setup = {{"map", e.relative_to_file(p.map)},
                              {"start", {p.start.x, p.start.y}},
                              {"goal", {p.goal.x, p.goal.y}},
                              {"reference", aco::describe(base.graph)}};
      if (p.bucket >= 0) setup["bucket"] = p.bucket;
      if (p.simulation) {
        setup["simulation"] = e.relative_to_file(p.simulation->file);
        setup["variations"] = p.variations;
      }
      records.push_back({p.name, setup.dump(), optimal ? optimal->length : -1.0});
      problems_.push_back(std::move(prepared));
    }
    db_ = std::make_unique<ResultsDb>(options.database, e.name, e.fingerprint(registry), records);
    finished_ = db_->finished();
    for (const auto& r : records) optimal_.push_back(r.optimal_length);
    // The ablation's choices need the results of trials an earlier, interrupted run stored.
    if (e.ablation_target)
      for (const auto& t : db_->trials()) add_score(t);
    // Where the maps are, for the report's pictures (not part of the identity: the folder may move).
    db_->set_meta("experiment_file", std::filesystem::absolute(e.file).lexically_normal().string());
  }

  RunSummary run() {
    const auto began = std::chrono::steady_clock::now();
    RunSummary summary;
    std::vector<const PreparedConfig*> fixed;
    for (const auto& c : e_.configurations) fixed.push_back(&add(c));
    std::vector<std::vector<std::string>> components;
    if (e_.ablation_target) components = ablation_components(e_.baseline, *e_.ablation_target);
    const std::size_t n = components.size();
    total_ = (fixed.size() + n * (n + 1) / 2) * e_.problems.size() * e_.repetitions;
    summary.trials = total_;

    run_trials(fixed, summary);
    // Fawcett and Hoos's ablation path: from the baseline, flip each remaining component in
    // turn, keep the best flip, repeat until the configuration is the target.
    Configuration current = e_.baseline;
    std::vector<std::string> path{current.name};
    for (int round = 1; !components.empty(); ++round) {
      std::vector<const PreparedConfig*> candidates;
      for (const auto& component : components) {
        Configuration c = flip(current, *e_.ablation_target, component);
        c.name = "ablation " + std::to_string(round) + ": " + label(component, *e_.ablation_target);
        candidates.push_back(&add(c));
      }
      run_trials(candidates, summary);
      const auto best = std::min_element(candidates.begin(), candidates.end(), [this](auto* a, auto* b) {
        return score(*a) < score(*b);
      }) - candidates.begin();
      current = candidates[best]->config;
      path.push_back(current.name);
      components.erase(components.begin() + best);
    }
    if (e_.ablation_target) db_->set_meta("ablation_path", nlohmann::json(path).dump());
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return summary;
  }

 private:
  const PreparedConfig& add(const Configuration& c) {
    auto prepared = std::make_unique<PreparedConfig>();
    prepared->config = c;
    prepared->run = c.run ? *c.run : resolve(c, e_.problems, registry_);
    prepared->id = db_->add_config({c.name, settings_json(*prepared, registry_)});
    try {
      for (std::size_t p = 0; p < problems_.size(); ++p) {
        if (const auto& scenario = e_.problems[p].simulation) {
          try {
            prepared->scenarios.emplace(static_cast<int>(p), acosim::with_run_keys(*scenario, c, registry_));
          } catch (const aco::Error& error) {
            throw aco::Error("problem '" + problems_[p].name + "': " + error.what());
          }
        } else {
          problems_[p].graph(prepared->run);
        }
      }
    } catch (const aco::Error& error) {
      throw aco::Error("configuration '" + c.name + "', " + error.what());
    }
    configs_.push_back(std::move(prepared));
    return *configs_.back();
  }

  static std::string label(const std::vector<std::string>& component, const Configuration& target) {
    std::string text;
    for (const auto& k : component) {
      if (!text.empty()) text += " ";
      text += k + "=" + (target.keys.count(k) ? target.keys.at(k) : "default");
    }
    return text;
  }

  // Lower is better: failures first, then the mean over problems of the mean length relative
  // to the optimum.
  std::pair<int, double> score(const PreparedConfig& c) const {
    int failures = 0;
    double relative = 0.0;
    for (const auto& [trial, result] : scores_.at(c.id)) {
      if (!result.first) ++failures;
      else relative += result.second;
    }
    return {failures, relative};
  }

  void run_trials(const std::vector<const PreparedConfig*>& configs, RunSummary& summary) {
    std::vector<Trial> trials;
    for (const auto* c : configs)
      for (int p = 0; p < static_cast<int>(e_.problems.size()); ++p)
        for (int r = 0; r < e_.repetitions; ++r) {
          if (finished_.count({p, c->id, r})) {
            ++summary.skipped;
            ++done_;
            continue;
          }
          trials.push_back({p, c, r});
        }
    if (options_.progress) options_.progress(done_, total_);
    const aco::ThreadLimit threads(options_.threads);
    aco::parallel_for(tbb::blocked_range<std::size_t>(0, trials.size(), 1), [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const TrialRecord record = guarded_trial(trials[i]);
        db_->store(record);
        const std::lock_guard lock(progress_mutex_);
        if (e_.ablation_target) add_score(record);
        ++done_;
        ++summary.ran;
        if (!record.error.empty()) summary.failures.push_back(record.error);
        if (options_.progress) options_.progress(done_, total_);
      }
    });
  }

  // Keyed by (problem, repetition), so score() sums in the same order whatever order the
  // trials finished in.
  void add_score(const TrialRecord& t) {
    const double optimal = optimal_[t.problem];
    scores_[t.config][{t.problem, t.repetition}] = {t.solved, optimal > 0 ? t.length / optimal : t.length};
  }

  // A trial that throws (a plugin's failure, or the host's) is stored as failed with the
  // message, and the experiment goes on, as OMPL's benchmark records crashed runs.
  TrialRecord guarded_trial(const Trial& t) {
    try {
      return run_trial(t);
    } catch (...) {
      TrialRecord r;
      r.problem = t.problem;
      r.config = t.config->id;
      r.repetition = t.repetition;
      r.seed = trial_seed(e_.seed, e_.problems[t.problem].name, t.repetition);
      r.stopped_by = "error";
      r.path_json = "[]";
      r.error = "configuration '" + t.config->config.name + "', problem '" + e_.problems[t.problem].name + "', repetition " +
                std::to_string(t.repetition) + ": " + aco::describe_current_exception();
      return r;
    }
  }

  TrialRecord run_trial(const Trial& t) {
    const Problem& problem = e_.problems[t.problem];
    if (problem.simulation) return run_simulation(t);
    aco::RunSpec run = t.config->run;
    const aco::Graph& graph = problems_[t.problem].graphs.at(PreparedProblem::graph_key(run));
    run.colony.seed = trial_seed(e_.seed, problem.name, t.repetition);
    const aco::PlanOutcome o = aco::plan(registry_, graph, graph.node(problem.start), graph.node(problem.goal), run);
    TrialRecord r;
    r.problem = t.problem;
    r.config = t.config->id;
    r.repetition = t.repetition;
    r.seed = o.seed;
    r.solved = o.solved();
    r.length = o.length;
    r.grid_length = o.search.length;
    r.turns = o.turns;
    r.iterations = o.search.iterations;
    r.best_iteration = o.search.best_iteration;
    r.time_s = o.time_ms / 1000.0;
    r.ant_steps = static_cast<std::uint64_t>(o.count("ant_steps"));
    r.stopped_by = o.text("stopped_by");
    r.path_json = path_json(o.path);
    r.best_so_far = o.search.best_so_far;
    return r;
  }

  // A simulation trial: the robot driven through the scenario (or the trial's variation of it)
  // with the configuration's run; the colony's seed is the trial's. length is the distance
  // driven, path the trajectory.
  TrialRecord run_simulation(const Trial& t) {
    const Problem& problem = e_.problems[t.problem];
    const std::uint64_t seed = trial_seed(e_.seed, problem.name, t.repetition);
    const auto began = std::chrono::steady_clock::now();
    // Variations are drawn on the scenario as written, so every configuration meets the same ones.
    acosim::Scenario scenario = problem.variations ? acosim::variations(*problem.simulation, 1, seed, registry_).front()
                                                   : *problem.simulation;
    const acosim::Scenario& configured = t.config->scenarios.at(t.problem);
    scenario.keys = configured.keys;
    scenario.run = configured.run;
    scenario.run.colony.seed = seed;
    const acosim::SimulationResult sim = acosim::simulate(scenario, registry_);
    TrialRecord r;
    r.problem = t.problem;
    r.config = t.config->id;
    r.repetition = t.repetition;
    r.seed = seed;
    r.solved = sim.reached;
    r.length = r.grid_length = sim.distance;
    r.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    r.stopped_by = sim.outcome;
    aco::Waypoints trajectory;
    const std::size_t every = std::max<std::size_t>(1, sim.frames.size() / 500);  // at most ~500 points
    for (std::size_t i = 0; i < sim.frames.size(); i += every) trajectory.emplace_back(sim.frames[i].robot.x, sim.frames[i].robot.y, 0.0);
    trajectory.emplace_back(sim.frames.back().robot.x, sim.frames.back().robot.y, 0.0);
    r.path_json = path_json(trajectory);
    r.simulation = SimulationRecord{sim.outcome, sim.reached ? sim.time : std::nan(""), sim.collisions, sim.replans,
                                    std::isfinite(sim.min_clearance) ? sim.min_clearance : std::nan(""), sim.steps};
    return r;
  }

  const Experiment& e_;
  aco::PluginRegistry& registry_;
  RunOptions options_;
  std::vector<PreparedProblem> problems_;
  std::vector<std::unique_ptr<PreparedConfig>> configs_;
  std::unique_ptr<ResultsDb> db_;
  std::set<std::tuple<int, int, int>> finished_;
  std::vector<double> optimal_;  // per problem; < 0 unknown
  // Per configuration id: (solved, length / optimum) of each (problem, repetition).
  std::map<int, std::map<std::pair<int, int>, std::pair<bool, double>>> scores_;
  std::mutex progress_mutex_;
  std::size_t done_ = 0;
  std::size_t total_ = 0;
};

}  // namespace

RunSummary run_experiment(const Experiment& experiment, aco::PluginRegistry& registry, const RunOptions& options) {
  return Runner(experiment, registry, options).run();
}

}  // namespace acobench
