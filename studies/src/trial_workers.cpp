#include "aco/studies/trial_workers.hpp"

#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>

#include "aco/error.hpp"
#include "aco/machine.hpp"
#include "aco/thread_limit.hpp"
#include "aco/studies/provenance.hpp"
#include "trial_messages.hpp"

namespace aco::studies {

using nlohmann::json;

// Request: {"fingerprint": ... (a fresh worker's first), "configs": [{id, name, keys}...] (those
// it has not been told yet), "trial": [problem, config, repetition(, time limit)]}. Reply: the record.
struct TrialWorkers::Lane {
  aco::WorkerProcess process;
  std::set<int> known;  // configuration ids this worker was told
};

std::vector<std::string> worker_command(const Experiment& experiment, const std::vector<std::string>& plugin_dirs,
                                        std::optional<std::uint64_t> max_memory) {
  std::vector<std::string> command{aco::this_program(), "worker", std::filesystem::absolute(experiment.file).string()};
  for (const auto& dir : plugin_dirs) {
    command.push_back("--plugin-dir");
    command.push_back(std::filesystem::absolute(dir).string());
  }
  if (max_memory) {
    command.push_back("--max-memory");
    command.push_back(std::to_string(*max_memory));
  }
  return command;
}

TrialWorkers::TrialWorkers(int lanes, std::vector<std::string> command, TrialLimits limits, std::string fingerprint)
    : limits_(limits), fingerprint_(std::move(fingerprint)) {
  for (int i = 0; i < std::max(1, lanes); ++i)
    lanes_.push_back(std::unique_ptr<Lane>(new Lane{aco::WorkerProcess(command), {}}));
}

TrialWorkers::~TrialWorkers() = default;

TrialRecord TrialWorkers::run(int lane_index, const TrialRunner& runner, const TrialOrder& t) {
  Lane& lane = *lanes_.at(static_cast<std::size_t>(lane_index));
  for (int attempt = 0;; ++attempt) {
    json request = {{"configs", json::array()}, {"trial", order_json(t)}};
    if (lane.process.start()) {
      lane.known.clear();
      request["fingerprint"] = fingerprint_;
    }
    if (lane.known.insert(t.config).second)
      request["configs"].push_back(config_json(t.config, runner.config(t.config)));
    const std::vector<std::uint8_t> cbor = json::to_cbor(request);
    const aco::WorkerReply reply =
        lane.process.request(std::string(cbor.begin(), cbor.end()), {limits_.timeout_s, limits_.memory_bytes});
    // A worker killed while it waited ran nothing of the trial: a fresh one runs it, once.
    if (!reply.delivered && attempt == 0) continue;
    if (reply.failure_kind == FailureKind::none) return record_from(json::from_cbor(reply.bytes));
    return runner.failed(t, reply.failure_kind, reply.failure);
  }
}

void WorkerExecutor::run(TrialRunner& runner, const TrialSequence& trials,
                         const std::function<void(const TrialRecord&)>& finished) {
  std::mutex mutex;
  aco::run_on_lanes(workers_.lanes(), trials.count, [&](int lane, std::size_t i) {
    const auto trial = trials.at(i);
    if (!trial) return;
    const TrialRecord record = workers_.run(lane, runner, *trial);
    const std::lock_guard lock(mutex);
    finished(record);
  });
}

void serve_trials_as_worker(const Experiment& experiment, aco::PluginRegistry& registry) {
  TrialRunner runner(experiment, registry);
  // One trial at a time on this thread: the parent runs one worker per core, and the parent's
  // "where are you" signal goes to this thread.
  const aco::ThreadLimit threads(1);
  std::string fingerprint;
  aco::serve_worker_requests([&](const std::string& bytes) {
    const json request = json::from_cbor(bytes);
    if (request.contains("fingerprint")) {
      if (fingerprint.empty()) fingerprint = experiment.fingerprint(registry);
      if (request.at("fingerprint") != fingerprint)
        throw aco::Error("a worker process loaded another experiment than acobench: " +
                         fingerprint_change(request.at("fingerprint"), fingerprint) +
                         " (was the experiment file, a map or a plugin binary changed during the run?)");
    }
    for (const json& c : request.at("configs")) add_config_from(c, runner);
    reset_peak_memory();  // the trial's peak, not that of the trials this worker ran before
    const std::vector<std::uint8_t> reply = json::to_cbor(record_json(runner.run(order_from(request.at("trial")))));
    return std::string(reply.begin(), reply.end());
  });
}

}  // namespace aco::studies
