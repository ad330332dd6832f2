#include "aco/studies/runner.hpp"

#include <algorithm>
#include <chrono>
#include <map>
#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <tuple>
#include <nlohmann/json.hpp>

#include "aco/error.hpp"
#include "aco/parallel.hpp"
#include "aco/plugin_record.hpp"
#include "aco/thread_limit.hpp"
#include "aco/process/version.hpp"
#include "aco/planning/yardsticks.hpp"
#include "aco/studies/results_db.hpp"

namespace aco::studies {

void ThreadExecutor::run(TrialRunner& runner, const TrialSequence& trials,
                         const std::function<void(const TrialRecord&)>& finished) {
  const aco::ThreadLimit threads(threads_);
  std::mutex mutex;
  aco::parallel_for(tbb::blocked_range<std::size_t>(0, trials.count, 1), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const auto trial = trials.at(i);
      if (!trial) continue;
      const TrialRecord record = runner.run(*trial);
      const std::lock_guard lock(mutex);
      finished(record);
    }
  });
}

namespace {

class Runner {
 public:
  Runner(const Experiment& e, aco::PluginRegistry& registry, const RunOptions& options)
      : e_(e), registry_(registry), options_(options), trials_(e, registry), threads_(options.threads) {
    executor_ = options.executor ? options.executor : &threads_;
    // Refused before the database is made: a shard run leaves no file behind.
    tied_ = std::any_of(e.configurations.begin(), e.configurations.end(),
                        [](const Configuration& c) { return !c.time_limit_from().empty(); });
    if (tied_ && options.shard)
      throw aco::Error(std::string(kTimeLimitFrom) +
                       ": a trial's time limit is the time another configuration took on the same problem and "
                       "repetition, which another shard may run: run this experiment without --shard (in one "
                       "process or under MPI)");
    const aco::RunSpec base = e.baseline.run ? *e.baseline.run : resolve(e.baseline, e.problems, registry);
    std::vector<ProblemRecord> records;
    for (std::size_t i = 0; i < e.problems.size(); ++i) {
      const Problem& p = e.problems[i];
      // The yardsticks, once per problem, on the baseline's graph (a 16-neighbourhood
      // configuration may beat its optimum: its gap is then negative). A simulation is judged by
      // its drive, not by the planned path's any-angle optimum.
      const aco::Graph& graph = trials_.graph(static_cast<int>(i), base);
      const aco::Yardsticks y = aco::yardsticks(graph, graph.node(p.start), graph.node(p.goal),
                                                p.simulation ? nullptr : &trials_.corridor(static_cast<int>(i), base));
      nlohmann::json setup = {{"map", e.relative_to_file(p.map)},
                              {"start", cell_json(p.start)},
                              {"goal", cell_json(p.goal)},
                              {"reference", aco::describe(base.graph)}};
      if (p.bucket >= 0) setup["bucket"] = p.bucket;
      // The map's reader, when not the built-in one its ending names: the report reads it again.
      if (!p.map_format.empty()) setup["map-format"] = p.map_format;
      for (const auto& [name, value] : p.map_parameters.all()) setup["map-parameters"][name] = aco::to_string(value);
      if (p.simulation) {
        setup["simulation"] = e.relative_to_file(p.simulation->file);
        setup["variations"] = p.variations;
      }
      records.push_back({p.name, setup.dump(), y.optimal_length.value_or(-1.0), y.any_angle_length.value_or(-1.0)});
    }
    db_ = std::make_unique<ResultsDb>(options.database, e.name, e.fingerprint(registry), records);
    finished_ = db_->finished();
    failed_before_ = db_->failed();
    check_shard();
    for (const auto& r : records) optimal_.push_back(r.optimal_length);
    // The ablation's choices and the time limits of tied configurations need the results of
    // trials an earlier, interrupted run stored.
    if (e.ablation_target || tied_)
      for (const auto& t : db_->trials()) {
        if (e.ablation_target) add_score(t);
        if (tied_) measured_[{t.problem, t.config, t.repetition}] = {t.time_s, t.error};
      }
    // Where the maps are, for the report's pictures (not part of the identity: the folder may move).
    db_->set_meta("experiment_file", std::filesystem::absolute(e.file).lexically_normal().string());
    // Which acobench ran the trials, and whether it was optimised: the report warns of times
    // measured by an unoptimised build.
    db_->set_meta("host_version", aco::version_text("acobench"));
    db_->set_meta("host_build", ACO_BUILD_OPTIMISATION);
    db_->record_limits({options.limits.timeout_s, static_cast<double>(options.limits.memory_bytes) / (1 << 20),
                        e.repetitions, e.seed});
  }

  RunSummary run() {
    const auto began = std::chrono::steady_clock::now();
    RunSummary summary;
    summary.growth = db_->growth();
    std::vector<int> fixed, untied, tied;
    for (const auto& c : e_.configurations) {
      fixed.push_back(add(c));
      (c.time_limit_from().empty() ? untied : tied).push_back(fixed.back());
    }
    std::vector<std::vector<std::string>> components;
    if (e_.ablation_target && !options_.shard) components = ablation_components(e_.baseline, *e_.ablation_target);
    // The local planner drives simulations only: flipping it in planning trials would spend a
    // round on a change that changes nothing (a paper's preset names its local planner).
    const bool simulations =
        std::any_of(e_.problems.begin(), e_.problems.end(), [](const Problem& p) { return p.simulation != nullptr; });
    if (!simulations)
      std::erase_if(components, [](const std::vector<std::string>& c) {
        return c.front() == "local" || c.front().rfind("local.", 0) == 0;
      });
    summary.ablation_left = e_.ablation_target && options_.shard;
    const std::size_t n = components.size();
    total_ = count_trials(fixed.size() + n * (n + 1) / 2);
    if (options_.shard) total_ = shard_size(*options_.shard, total_);
    summary.trials = total_;
    if (options_.starting)
      options_.starting({fixed.size(), n * (n + 1) / 2, e_.problems.size(), e_.repetitions, total_, stored(fixed)});

    // The configurations a time-limit-from names first: their trials' times are the others' limits.
    run_trials(untied, summary);
    run_trials(tied, summary);
    // Fawcett and Hoos's ablation path: from the baseline, flip each remaining component in
    // turn, keep the best flip, repeat until the configuration is the target.
    Configuration current = e_.baseline;
    std::vector<std::string> path{current.name};
    for (int round = 1; !components.empty(); ++round) {
      std::vector<int> candidates;
      for (const auto& component : components) {
        Configuration c = flip(current, *e_.ablation_target, component);
        c.name = "ablation " + std::to_string(round) + ": " + label(component, *e_.ablation_target);
        candidates.push_back(add(c));
      }
      run_trials(candidates, summary);
      const auto best =
          std::min_element(candidates.begin(), candidates.end(), [this](int a, int b) { return score(a) < score(b); }) -
          candidates.begin();
      current = trials_.config(candidates[best]);
      path.push_back(current.name);
      components.erase(components.begin() + best);
    }
    if (e_.ablation_target && !options_.shard) db_->set_meta("ablation_path", nlohmann::json(path).dump());
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return summary;
  }

 private:
  // A shard's database holds that shard only; any other run of it is refused, so a merge finds
  // each trial where the shard's number says.
  void check_shard() {
    const std::string wanted = options_.shard ? to_string(*options_.shard) : "";
    const auto stored = db_->find_meta("shard");
    if (!stored && finished_.empty()) {
      if (options_.shard) db_->set_meta("shard", wanted);
      return;
    }
    if (stored.value_or("") == wanted) return;
    const std::string file = options_.database.string();
    if (!stored)
      throw aco::Error(file + " holds trials of a run without --shard; shard " + wanted +
                       " writes its own database (give another --db)");
    throw aco::Error(file + " holds shard " + *stored + " of the experiment; run it with --shard " + *stored +
                     (options_.shard ? ", give shard " + wanted + " its own --db," : "") +
                     " or merge it (acobench merge)");
  }

  // Its database id, the configuration prepared for trials.
  int add(const Configuration& c) {
    Configuration resolved = c;
    if (!resolved.run) resolved.run = resolve(c, e_.problems, registry_);
    const int id = db_->add_config(
        {c.name, settings_json(c, *resolved.run, registry_), aco::plugins_json(*resolved.run, registry_)});
    trials_.add_config(id, resolved);
    order_.push_back(id);
    ids_[c.name] = id;
    return id;
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
  std::pair<int, double> score(int config) const {
    int failures = 0;
    double relative = 0.0;
    for (const auto& [trial, result] : scores_.at(config)) {
      if (!result.first)
        ++failures;
      else
        relative += result.second;
    }
    return {failures, relative};
  }

  // The experiment's trials of `configurations`, refused where they cannot be numbered.
  std::size_t count_trials(std::size_t configurations) const {
    std::size_t count = 0;
    if (__builtin_mul_overflow(configurations, e_.problems.size(), &count) ||
        __builtin_mul_overflow(count, static_cast<std::size_t>(e_.repetitions), &count))
      throw aco::Error(e_.name + ": " + std::to_string(configurations) + " configurations x " +
                       std::to_string(e_.problems.size()) + " problems x " + std::to_string(e_.repetitions) +
                       " repetitions are more trials than a 64-bit number counts: make the experiment smaller");
    return count;
  }

  // A shard runs only the trials whose number it owns. The number counts the configuration's
  // place in the experiment, not its id: a shard's trials are the same whatever its database held.
  bool owns(int config, int problem, int repetition) const {
    if (!options_.shard) return true;
    const auto position = static_cast<std::size_t>(std::find(order_.begin(), order_.end(), config) - order_.begin());
    return options_.shard->owns(trial_index(position, problem, repetition));
  }

  bool is_stored(int problem, int config, int repetition) const {
    return std::binary_search(finished_.begin(), finished_.end(), std::tuple{problem, config, repetition});
  }

  // Calls visit(problem, config, repetition) for each trial of `configs` the database holds and
  // this run owns.
  template <class Visit>
  void for_each_stored(const std::vector<int>& configs, Visit visit) const {
    for (const auto& [p, c, r] : finished_)
      if (r < e_.repetitions && std::find(configs.begin(), configs.end(), c) != configs.end() && owns(c, p, r))
        visit(p, c, r);
  }

  std::size_t stored(const std::vector<int>& configs) const {
    std::size_t count = 0;
    for_each_stored(configs, [&](int, int, int) { ++count; });
    return count;
  }

  // Trial number `i` of `configs`: configuration by configuration, problem by problem,
  // repetition by repetition.
  TrialOrder numbered(const std::vector<int>& configs, std::size_t i) const {
    const auto repetitions = static_cast<std::size_t>(e_.repetitions);
    const std::size_t per_config = e_.problems.size() * repetitions;
    return {static_cast<int>(i % per_config / repetitions), configs[i / per_config], static_cast<int>(i % repetitions)};
  }

  void run_trials(const std::vector<int>& configs, RunSummary& summary) {
    const auto finished = [&](const TrialRecord& record) {
      ++done_;
      // Another acobench running the experiment into the same file may have stored it first.
      if (db_->store(record, ResultsDb::IfStored::skip)) {
        if (e_.ablation_target) add_score(record);
        if (tied_) measured_[{record.problem, record.config, record.repetition}] = {record.time_s, record.error};
        ++summary.ran;
        if (!record.error.empty())
          summary.failures.push_back({trials_.config(record.config).name, record.failure, record.error, false});
      } else {
        ++summary.skipped;
        ++summary.stored_by_another;
      }
      if (options_.progress) options_.progress(done_, total_);
    };
    for_each_stored(configs, [&](int p, int c, int r) {
      ++summary.skipped;
      ++done_;
      if (const auto failed = failed_before_.find({p, c, r}); failed != failed_before_.end())
        summary.failures.push_back({trials_.config(c).name, failed->second.first, failed->second.second, true});
    });
    const std::size_t count = count_trials(configs.size());
    TrialSequence sequence{
        count, [&](std::size_t i) -> std::optional<TrialOrder> {
          const TrialOrder t = numbered(configs, i);
          if (!owns(t.config, t.problem, t.repetition) || is_stored(t.problem, t.config, t.repetition))
            return std::nullopt;
          return t;
        }};
    // A configuration whose time limit is another's measured time: its trials are listed, each
    // with its limit (such studies are OMPL comparisons, and keep every time in memory anyway).
    std::vector<TrialOrder> listed, untimed;
    const bool tied = std::any_of(configs.begin(), configs.end(),
                                  [&](int c) { return !trials_.config(c).time_limit_from().empty(); });
    for (std::size_t i = 0; tied && i < count; ++i) {
      const auto numbered_trial = sequence.at(i);
      if (!numbered_trial) continue;
      TrialOrder trial = *numbered_trial;
      const auto [p, c, r] = std::tuple{trial.problem, trial.config, trial.repetition};
      if (const std::string from = trials_.config(c).time_limit_from(); !from.empty()) {
        const auto it = measured_.find({p, ids_.at(from), r});
        if (it == measured_.end())
          throw aco::Error("configuration '" + trials_.config(c).name + "', problem '" + e_.problems[p].name +
                           "', repetition " + std::to_string(r) + ": the trial of '" + from +
                           "' whose time is its time limit is not in the database");
        trial.time_limit_s = it->second.first;
        // Stored as failed rather than run with some other limit, and not retried on resuming:
        // the colony trial it depends on is not retried either.
        if (!it->second.second.empty() || !(trial.time_limit_s > 0.0)) {
          untimed.push_back(trial);
          continue;
        }
      }
      listed.push_back(trial);
    }
    if (tied) sequence = {listed.size(), [&](std::size_t i) { return std::optional<TrialOrder>(listed[i]); }};
    if (options_.progress) options_.progress(done_, total_);
    for (const TrialOrder& trial : untimed) {
      const std::string& from = trials_.config(trial.config).time_limit_from();
      const std::string& error = measured_.at({trial.problem, ids_.at(from), trial.repetition}).second;
      finished(trials_.failed(trial, FailureKind::error,
                              "not run: its time limit (" + std::string(kTimeLimitFrom) + ") is the time of '" + from +
                                  "' on the same problem and repetition, and that trial " +
                                  (error.empty() ? "measured no time" : "failed: " + error)));
    }
    executor_->run(trials_, sequence, finished);
  }

  // A trial's place in the order shards split the configurations' trials.
  std::size_t trial_index(std::size_t config_position, int problem, int repetition) const {
    return fixed_trial_index(config_position, static_cast<std::size_t>(problem), static_cast<std::size_t>(repetition),
                             e_.problems.size(), static_cast<std::size_t>(e_.repetitions));
  }

  // Keyed by (problem, repetition), so score() sums in the same order whatever order the
  // trials finished in.
  void add_score(const TrialRecord& t) {
    const double optimal = optimal_[t.problem];
    scores_[t.config][{t.problem, t.repetition}] = {t.solved, optimal > 0 ? t.length / optimal : t.length};
  }

  const Experiment& e_;
  aco::PluginRegistry& registry_;
  RunOptions options_;
  TrialRunner trials_;
  ThreadExecutor threads_;
  TrialExecutor* executor_ = nullptr;
  std::unique_ptr<ResultsDb> db_;
  std::vector<int> order_;  // configuration ids in the order they were added
  std::map<std::string, int> ids_;  // by name
  bool tied_ = false;  // a configuration's time limit is another's time (time-limit-from)
  // (time, error) of every trial stored, by (problem, config id, repetition), when tied_: a
  // time-limit-from's times.
  std::map<std::tuple<int, int, int>, std::pair<double, std::string>> measured_;
  std::vector<std::tuple<int, int, int>> finished_;  // sorted (ResultsDb::finished())
  std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> failed_before_;
  std::vector<double> optimal_;  // per problem; < 0 unknown
  // Per configuration id: (solved, length / optimum) of each (problem, repetition).
  std::map<int, std::map<std::pair<int, int>, std::pair<bool, double>>> scores_;
  std::size_t done_ = 0;
  std::size_t total_ = 0;
};

}  // namespace

std::vector<std::string> describe_failures(const std::vector<TrialFailure>& failures) {
  // kind -> configuration -> (count, the first message)
  std::map<FailureKind, std::map<std::string, std::pair<std::size_t, std::string>>> by_kind;
  for (const auto& f : failures) {
    // The smallest message, not the first to arrive: the same lines whatever the trials' order.
    auto& [count, example] = by_kind[f.kind][f.configuration];
    if (count++ == 0 || f.message < example) example = f.message;
  }
  const auto shortened = [](const std::string& text) { return text.size() > 500 ? text.substr(0, 497) + "..." : text; };
  std::vector<std::string> lines;
  for (const auto& [kind, configurations] : by_kind) {
    std::size_t total = 0;
    for (const auto& [name, counted] : configurations) total += counted.first;
    lines.push_back(describe_failure(kind) + ": " + std::to_string(total));
    // The line names the configuration: the example starts at the problem.
    for (const auto& [name, counted] : configurations) {
      const std::string named = "configuration '" + name + "', ";
      const std::string& example = counted.second;
      lines.push_back("  '" + name + "': " + std::to_string(counted.first) + ", e.g. " +
                      shortened(example.rfind(named, 0) == 0 ? example.substr(named.size()) : example));
    }
  }
  return lines;
}

RunSummary run_experiment(const Experiment& experiment, aco::PluginRegistry& registry, const RunOptions& options) {
  return Runner(experiment, registry, options).run();
}

}  // namespace aco::studies
