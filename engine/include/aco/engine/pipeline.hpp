#pragma once
// A pipeline is one plugin per slot plus its parameters: what a user composes on the command
// line (--update max_min --update.rho 0.02) or in an experiment file, resolved by resolve_run().
#include <map>
#include <memory>
#include <string>

#include "aco/engine/colony.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/slots.hpp"

namespace aco {

// kSlotTable's default_plugin of a pipeline slot (kSlots, aco/slots.hpp); an Error for another.
const char* default_plugin(const std::string& slot);

// A slot's plugin and its resolved parameters (every one, defaults included).
struct SlotSpec {
  std::string plugin;
  ParameterValues parameters;
};
using PipelineSpec = std::map<std::string, SlotSpec>;  // slot -> plugin, for every slot of kSlots

// One member per pipeline slot, named as the slot (local drives acosim's robot along the path).
struct PipelinePlugins {
#define ACO_PIPELINE_MEMBER_(NAME, INTERFACE) std::unique_ptr<INTERFACE> NAME;
  ACO_PIPELINE_SLOTS(ACO_PIPELINE_MEMBER_)
#undef ACO_PIPELINE_MEMBER_

  ColonyStrategies strategies() const { return {init.get(), heuristic.get(), update.get(), deadlock.get()}; }
};

// Instantiates every slot's plugin with its resolved parameters (see resolve_run()).
PipelinePlugins instantiate(PluginRegistry& registry, const PipelineSpec& spec);

// run_colony() with a pipeline's plugins. The bidirectional search's backward colony, and the
// islands' further colonies, get their own instances of the same plugins, instantiated here from
// `spec`. All record into `figures`.
ColonyResult run_pipeline(PluginRegistry& registry, const PipelineSpec& spec, const PipelinePlugins& pipeline,
                          const Graph& graph, NodeId start, NodeId goal, const ColonySettings& settings,
                          FigureSink* figures = nullptr);

}  // namespace aco
