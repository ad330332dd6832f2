#pragma once
// A pipeline is one plugin per slot plus its parameters: what a user composes on the command
// line (--update max_min --update.rho 0.02) or in an experiment file, resolved by resolve_run().
#include <array>
#include <map>
#include <memory>
#include <string>

#include "aco/colony.hpp"
#include "aco/plugin_registry.hpp"

namespace aco {

inline constexpr std::array<const char*, 6> kSlots = {"init", "heuristic", "update", "deadlock", "smoother", "local"};
// uniform, distance, ant_system, discard, none, track
const char* default_plugin(const std::string& slot);

// A slot's plugin and its resolved parameters (every one, defaults included).
struct SlotSpec {
  std::string plugin;
  ParameterValues parameters;
};
using PipelineSpec = std::map<std::string, SlotSpec>;  // slot -> plugin, for every slot of kSlots

struct LoadedPipeline {
  std::unique_ptr<PheromoneInit> init;
  std::unique_ptr<Heuristic> heuristic;
  std::unique_ptr<PheromoneUpdate> update;
  std::unique_ptr<DeadlockPolicy> deadlock;
  std::unique_ptr<Smoother> smoother;
  std::unique_ptr<LocalPlanner> local;  // drives the robot along the path (acosim)

  Pipeline colony() const { return {init.get(), heuristic.get(), update.get(), deadlock.get()}; }
};

// Instantiates every slot's plugin with its resolved parameters (see resolve_run()).
LoadedPipeline instantiate(PluginRegistry& registry, const PipelineSpec& spec);

// run_colony with a loaded pipeline. The bidirectional search's backward colony gets its own
// instances of the same plugins, instantiated here from `spec`. Both record into `figures`.
ColonyResult run_colony(PluginRegistry& registry, const PipelineSpec& spec, const LoadedPipeline& pipeline,
                        const Graph& graph, NodeId start, NodeId goal, const ColonySettings& settings,
                        FigureSink* figures = nullptr);

}  // namespace aco
