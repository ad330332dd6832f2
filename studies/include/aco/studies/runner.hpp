#pragma once
// Runs an experiment's trials into a results database, skipping trials the database already
// holds, so an interrupted run continues where it stopped. Where the trials run is an executor's
// business: threads of this process (the default), or MPI worker ranks (mpi.hpp).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "aco/engine/plugin_registry.hpp"
#include "aco/studies/experiment.hpp"
#include "aco/studies/growth.hpp"
#include "aco/studies/shards.hpp"
#include "aco/studies/trial_runner.hpp"

namespace aco::studies {

// A batch of trials, numbered 0 to count - 1 and made from their number when a lane asks for
// one: a study of any size starts at once and holds no list of its trials.
struct TrialSequence {
  std::size_t count = 0;
  // Trial number `i`, or nothing where there is none to run (the database holds it, or another
  // shard owns it). Called from several threads at once.
  std::function<std::optional<TrialOrder>(std::size_t i)> at;
};

// Runs batches of trials and hands back each record.
class TrialExecutor {
 public:
  virtual ~TrialExecutor() = default;
  // Runs every trial (their configurations are prepared in `runner`), asking for them roughly in
  // their numbers' order, and calls `finished` with each record, from one thread at a time, in any
  // order.
  virtual void run(TrialRunner& runner, const TrialSequence& trials,
                   const std::function<void(const TrialRecord&)>& finished) = 0;
};

// The trials on this process's threads (TBB); results do not depend on their number.
class ThreadExecutor : public TrialExecutor {
 public:
  explicit ThreadExecutor(int threads) : threads_(threads) {}
  void run(TrialRunner& runner, const TrialSequence& trials,
           const std::function<void(const TrialRecord&)>& finished) override;

 private:
  int threads_;
};

// What a run is about to do, known before its first trial: the experiment's size and how much of
// it the database holds already.
struct TrialPlan {
  std::size_t configurations = 0;  // the experiment's (factorial ones and null-model twins included)
  std::size_t ablation_configurations = 0;  // those of the ablation path, n(n+1)/2 for n components
  std::size_t problems = 0;
  int repetitions = 0;
  std::size_t trials = 0;  // (configurations + ablation_configurations) x problems x repetitions, or a shard's part
  std::size_t stored = 0;  // of the configurations' trials (not the ablation path's), already in the database
};

// The limits of each trial's worker process.
struct TrialLimits {
  double timeout_s = 0.0;  // 0: none
  std::uint64_t memory_bytes = 0;  // 0: none
};

struct RunOptions {
  std::filesystem::path database;
  int threads = 0;  // 0 = all cores; results do not depend on it
  // Called after every stored trial with (done, total); from one thread at a time. It may throw to
  // stop the run (the Python package does on Ctrl-C): the trials running finish and are stored, no
  // other starts, and the exception leaves run_experiment().
  std::function<void(std::size_t done, std::size_t total)> progress;
  // Called once, before the first trial runs.
  std::function<void(const TrialPlan&)> starting;
  // Only this shard's trials of the configurations (an ablation path is left to a run of the
  // merged database: its rounds need every trial of the round before).
  std::optional<Shard> shard;
  // Where the trials run; nullptr: a ThreadExecutor with `threads`.
  TrialExecutor* executor = nullptr;
  // The limits the executor enforces, recorded in the database (OMPL's timelimit and memorylimit).
  TrialLimits limits;
};

// A trial of the experiment that failed, in this run or (earlier) stored as failed by another.
struct TrialFailure {
  std::string configuration;
  FailureKind kind = FailureKind::error;
  std::string message;  // the trial's error, naming it
  bool earlier = false;
};

struct RunSummary {
  std::size_t trials = 0;  // trials of the experiment (of the shard)
  std::size_t skipped = 0;  // already in the database (stored_by_another included)
  std::size_t stored_by_another = 0;  // run here too, but another process stored it first
  std::size_t ran = 0;
  // Every failed trial of the experiment (of the shard): those run now and those stored as failed
  // before, so that running the same command again gives the same verdict.
  std::vector<TrialFailure> failures;
  double seconds = 0.0;
  bool ablation_left = false;  // a shard: the experiment's ablation path was not run
  Growth growth;  // what the experiment added to an existing database
};

// The failures counted by kind, then by configuration, with one example message each: the lines
// acobench prints at the end of a run (empty without failures).
std::vector<std::string> describe_failures(const std::vector<TrialFailure>& failures);

RunSummary run_experiment(const Experiment& experiment, aco::PluginRegistry& registry, const RunOptions& options);

}  // namespace aco::studies
