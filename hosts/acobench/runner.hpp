#pragma once
// Runs an experiment's trials in parallel into a results database, skipping trials the
// database already holds, so an interrupted run continues where it stopped.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "aco/plugin_registry.hpp"
#include "experiment.hpp"

namespace acobench {

struct RunOptions {
  std::filesystem::path database;
  int threads = 0;  // 0 = all cores; results do not depend on it
  // Called after every stored trial with (done, total); from one thread at a time.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

struct RunSummary {
  std::size_t trials = 0;   // trials of the experiment
  std::size_t skipped = 0;  // already in the database
  std::size_t ran = 0;
  std::vector<std::string> failures;  // the messages of the trials run now that threw (stored as failed)
  double seconds = 0.0;
};

RunSummary run_experiment(const Experiment& experiment, aco::PluginRegistry& registry, const RunOptions& options);

}  // namespace acobench
