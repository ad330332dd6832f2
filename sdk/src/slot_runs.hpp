#pragma once
// A plugin run as the engine runs it, one overload per slot, on one standard problem: what it
// produces goes into the trace, with what breaks its interface's contract. Internal to the checks.
#include <type_traits>

#include "aco/engine/colony.hpp"
#include "aco/sdk/conformance.hpp"
#include "trace.hpp"

namespace aco::conformance {

// The iterations of a checked run (the Context's max_iterations).
constexpr int kIterations = 10;

void run_slot(PheromoneInit& init, const Problem& problem, Trace& trace);
void run_slot(Heuristic& heuristic, const Problem& problem, Trace& trace);
void run_slot(PheromoneUpdate& update, const Problem& problem, Trace& trace);
void run_slot(DeadlockPolicy& deadlock, const Problem& problem, Trace& trace);
void run_slot(Smoother& smoother, const Problem& problem, Trace& trace);
void run_slot(LocalPlanner& planner, const Problem& problem, Trace& trace);
void run_slot(MapReader& reader, const Problem& problem, Trace& trace);

// A colony run with `pipeline`, the default plugins in its empty slots: its path, which must
// step along graph edges from start to goal, and its pheromone.
void run_colony_filled(ColonyStrategies pipeline, const Problem& problem, const ColonySettings& settings, Trace& trace);

// The colony with the plugin in its slot and the default plugins in the others.
template <class Interface>
void run_colony_with(Interface& plugin, const Problem& problem, const ColonySettings& settings, Trace& trace) {
  ColonyStrategies pipeline;
  if constexpr (std::is_same_v<Interface, PheromoneInit>) pipeline.init = &plugin;
  if constexpr (std::is_same_v<Interface, Heuristic>) pipeline.heuristic = &plugin;
  if constexpr (std::is_same_v<Interface, PheromoneUpdate>) pipeline.update = &plugin;
  if constexpr (std::is_same_v<Interface, DeadlockPolicy>) pipeline.deadlock = &plugin;
  run_colony_filled(pipeline, problem, settings, trace);
}

}  // namespace aco::conformance
