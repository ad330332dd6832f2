#pragma once
// What runs one trial of an experiment: its problems' maps and graphs, its configurations
// resolved, and the trial itself. The process that stores results and every MPI worker rank
// hold one each; a trial gives the same record in any of them.
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "aco/corridor.hpp"
#include "aco/graph.hpp"
#include "aco/planning/planning.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/studies/experiment.hpp"
#include "aco/studies/trial_record.hpp"

namespace aco::studies {

// A trial: a problem (index into the experiment's), a configuration (its database id) and a
// repetition.
struct TrialOrder {
  int problem = 0;
  int config = 0;
  int repetition = 0;
  // > 0: the OMPL run's time limit instead of the configuration's ompl.time_limit, the time its
  // time-limit-from trial measured (recorded as the trial's property time_limit).
  double time_limit_s = 0.0;
};

class TrialRunner {
 public:
  TrialRunner(const Experiment& experiment, aco::PluginRegistry& registry);
  ~TrialRunner();
  TrialRunner(const TrialRunner&) = delete;
  TrialRunner& operator=(const TrialRunner&) = delete;

  // Prepares a configuration under its database id: resolved (unless the file resolved it),
  // every graph and scenario its trials need built. Errors name the configuration and problem.
  void add_config(int id, const Configuration& config);
  const Configuration& config(int id) const;

  // The graph of a problem with a run's terrain and graph options (built on first use).
  const aco::Graph& graph(int problem, const aco::RunSpec& run);
  // The problem's exact any-angle optimum and its corridor on the map of a run's terrain options
  // (made on first use; empty on maps other than flat grids).
  const aco::OptimalCorridor& corridor(int problem, const aco::RunSpec& run);

  // Runs one trial of a prepared configuration. Whatever the trial throws (a plugin's failure,
  // or the host's) comes back as a failed record with the message naming the trial. Its
  // peak_memory_mib is this process's aco::peak_memory_mib() (aco/machine.hpp) at its end.
  TrialRecord run(const TrialOrder& trial);
  // The record of a trial that failed: `kind` is its failure (aco/process/failure_kind.hpp), `reason` its
  // error after the trial's name.
  TrialRecord failed(const TrialOrder& trial, FailureKind kind, const std::string& reason) const;

 private:
  struct Problems;
  struct Prepared;
  TrialRecord plan(const TrialOrder& trial);
  TrialRecord simulate(const TrialOrder& trial);

  const Experiment& experiment_;
  aco::PluginRegistry& registry_;
  std::unique_ptr<Problems> problems_;
  std::map<int, std::unique_ptr<Prepared>> configs_;
};

// The configuration as the database stores it: the keys as written, the resolved run (every
// key, the same names as acoplan's --json) and each slot's plugin binary.
std::string settings_json(const Configuration& config, const aco::RunSpec& run, const aco::PluginRegistry& registry);

}  // namespace aco::studies
