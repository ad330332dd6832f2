#pragma once
// Trials in worker processes (aco/process/worker_process.hpp): a plugin that crashes, hangs or fills
// the memory costs its own trial, which is stored as failed with the reason, and the study goes
// on. One persistent worker per lane; each loads the experiment once and is told a
// configuration's keys the first time it runs one of its trials.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aco/process/worker_process.hpp"
#include "aco/studies/runner.hpp"

namespace aco::studies {

// How a worker is started: `acobench worker EXPERIMENT [--plugin-dir DIR]... [--max-memory
// BYTES]`, from the experiment file, plugin folders and --max-memory of this process (a worker
// builds the graphs its trials need, so it must refuse and admit the maps this process does).
std::vector<std::string> worker_command(const Experiment& experiment, const std::vector<std::string>& plugin_dirs,
                                        std::optional<std::uint64_t> max_memory);

// A worker process per lane.
class TrialWorkers {
 public:
  TrialWorkers(int lanes, std::vector<std::string> command, TrialLimits limits, std::string fingerprint);
  ~TrialWorkers();
  int lanes() const { return static_cast<int>(lanes_.size()); }
  const TrialLimits& limits() const { return limits_; }  // each lane's
  // Runs a trial in the lane's worker (one caller per lane at a time). A crash, time-out or
  // memory overrun comes back as a failed record ("crashed", "timed out", "out of memory") naming
  // the plugin hook the worker was in; a worker that cannot start is an aco::Error.
  TrialRecord run(int lane, const TrialRunner& runner, const TrialOrder& trial);

 private:
  struct Lane;
  std::vector<std::unique_ptr<Lane>> lanes_;
  TrialLimits limits_;
  std::string fingerprint_;
};

// The executor of `acobench run` without --in-process: the trials on `workers`' lanes.
class WorkerExecutor : public TrialExecutor {
 public:
  explicit WorkerExecutor(TrialWorkers& workers) : workers_(workers) {}
  void run(TrialRunner& runner, const TrialSequence& trials,
           const std::function<void(const TrialRecord&)>& finished) override;

 private:
  TrialWorkers& workers_;
};

// `acobench worker`: serves the trials a TrialWorkers sends until it closes the socket.
void serve_trials_as_worker(const Experiment& experiment, aco::PluginRegistry& registry);

}  // namespace aco::studies
