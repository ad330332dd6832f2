#pragma once
// acosim --batch: generated variations of a scenario and their summary.
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "aco/process/worker_process.hpp"
#include "aco/simulation/simulation.hpp"

namespace aco::simulation {

// `count` variations of `base` (its own unknown and moving obstacles replaced): one to three
// unknown cells on or beside the global path (planned once on the map, as the robot would),
// clear of the start and the goal, never cutting every way from start to goal, and one or two discs crossing the path
// at 0.2-0.5 per second from 3-5 away. Variation k depends only on (seed, k).
std::vector<Scenario> variations(const Scenario& base, int count, std::uint64_t seed, aco::PluginRegistry& registry);

struct BatchSummary {
  int runs = 0;
  int reached = 0;
  int collisions = 0;
  int reached_with_collision = 0;  // 0 by construction (a collision ends a run); counted to show it
  int replans = 0;
  double mean_time = 0.0;  // over the reached runs
  double mean_clearance = 0.0;  // smallest clearance per run, averaged
  std::map<std::string, int> outcomes;
  std::vector<SimulationResult> results;  // per variation, without their frames
};

// Runs the scenarios in parallel in this process (each simulation is sequential and
// deterministic, so the summary does not depend on the thread count). A plugin that crashes
// ends the process.
BatchSummary run_batch(const std::vector<Scenario>& scenarios, aco::PluginRegistry& registry);

// The same batch of `count` variations, each in a worker process (aco/process/worker_process.hpp), one
// per lane: `command` starts acosim serving them (serve_variations). A variation whose plugin
// crashes, runs over `limits.timeout_s` or grows its worker's memory by more than
// `limits.memory_bytes` costs only itself: its outcome is "crashed", "timeout" (as a simulation
// over its own time limit) or "out of memory", its reason the failure naming the plugin hook,
// and `failed` hears of it when it happens (from one lane at a time). The other variations'
// results are run_batch's. An error (a worker that cannot start, a plugin that throws) ends the
// batch as an aco::Error.
BatchSummary run_batch_in_workers(int count, const std::vector<std::string>& command, int lanes,
                                  const aco::WorkerLimits& limits,
                                  const std::function<void(int variation, const SimulationResult&)>& failed);

// In a worker process of run_batch_in_workers: answers each request "K" with the result of
// variation K of variations(base, count, seed) (without its frames), one at a time, until the
// parent is done. The variations are made on the first request, so that a plugin crashing while
// the global path is planned is reported as that request's failure.
void serve_variations(const Scenario& base, int count, std::uint64_t seed, aco::PluginRegistry& registry);

}  // namespace aco::simulation
