#pragma once
// A pipeline is one plugin per slot plus its parameters: what a user composes on the command
// line (--update max_min --update.rho 0.02) or in an experiment file.
#include <array>
#include <map>
#include <memory>
#include <string>

#include "aco/colony.hpp"
#include "aco/plugin_registry.hpp"

namespace aco {

inline constexpr std::array<const char*, 5> kSlots = {"init", "heuristic", "update", "deadlock", "smoother"};
const char* default_plugin(const std::string& slot);  // uniform, distance, ant_system, discard, none

struct SlotChoice {
  std::string plugin;
  std::map<std::string, std::string> params;  // name -> text, checked against the plugin's table
};

// Every slot, with the defaults filled in for slots the user did not set.
struct PipelineSpec {
  std::map<std::string, SlotChoice> slots;
  PipelineSpec();
};

struct LoadedPipeline {
  std::unique_ptr<PheromoneInit> init;
  std::unique_ptr<Heuristic> heuristic;
  std::unique_ptr<PheromoneUpdate> update;
  std::unique_ptr<DeadlockPolicy> deadlock;
  std::unique_ptr<Smoother> smoother;
  std::map<std::string, ParameterValues> resolved;  // slot -> every parameter, defaults included

  Pipeline colony() const { return {init.get(), heuristic.get(), update.get(), deadlock.get()}; }
};

// Loads and instantiates every slot's plugin. Unknown plugins, unknown parameter names and
// out-of-range values are errors that name the slot, the key and the nearest valid key.
LoadedPipeline instantiate(PluginRegistry& registry, const PipelineSpec& spec);

// run_colony with a loaded pipeline. The bidirectional search's backward colony gets its own
// instances of the same plugins, instantiated here from `spec`.
ColonyResult run_colony(PluginRegistry& registry, const PipelineSpec& spec, const LoadedPipeline& pipeline,
                        const Graph& graph, NodeId start, NodeId goal, const ColonySettings& settings);

}  // namespace aco
