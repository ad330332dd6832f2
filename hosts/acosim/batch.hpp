#pragma once
// acosim --batch: generated variations of a scenario and their summary.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "simulation.hpp"

namespace acosim {

// `count` variations of `base` (its own unknown and moving obstacles replaced): one to three
// unknown cells on or beside the global path (planned once on the map, as the robot would),
// clear of the start and the goal, never cutting every way from start to goal, and one or two discs crossing the path at 0.2-0.5 per second
// from 3-5 away. Variation k depends only on (seed, k).
std::vector<Scenario> variations(const Scenario& base, int count, std::uint64_t seed, aco::PluginRegistry& registry);

struct BatchSummary {
  int runs = 0;
  int reached = 0;
  int collisions = 0;
  int reached_with_collision = 0;  // 0 by construction (a collision ends a run); counted to show it
  int replans = 0;
  double mean_time = 0.0;       // over the reached runs
  double mean_clearance = 0.0;  // smallest clearance per run, averaged
  std::map<std::string, int> outcomes;
  std::vector<SimulationResult> results;  // per variation, without their frames
};

// Runs the scenarios in parallel (each simulation is sequential and deterministic, so the
// summary does not depend on the thread count).
BatchSummary run_batch(const std::vector<Scenario>& scenarios, aco::PluginRegistry& registry);

}  // namespace acosim
