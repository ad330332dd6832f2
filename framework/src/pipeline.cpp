#include "aco/pipeline.hpp"

#include <algorithm>

namespace aco {

const char* default_plugin(const std::string& slot) {
  if (slot == "init") return "uniform";
  if (slot == "heuristic") return "distance";
  if (slot == "update") return "ant_system";
  if (slot == "deadlock") return "discard";
  if (slot == "smoother") return "none";
  throw Error("unknown slot '" + slot + "'");
}

PipelineSpec::PipelineSpec() {
  for (const char* slot : kSlots) slots[slot].plugin = default_plugin(slot);
}

LoadedPipeline instantiate(PluginRegistry& registry, const PipelineSpec& spec) {
  for (const auto& [slot, choice] : spec.slots)
    if (std::find(kSlots.begin(), kSlots.end(), slot) == kSlots.end()) {
      const std::vector<std::string> known(kSlots.begin(), kSlots.end());
      const auto near = nearest(slot, known);
      throw Error("unknown slot '" + slot + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?"));
    }
  LoadedPipeline loaded;
  auto make = [&](const char* slot, auto& target) {
    using Interface = typename std::remove_reference_t<decltype(target)>::element_type;
    const auto it = spec.slots.find(slot);
    const SlotChoice choice = it != spec.slots.end() ? it->second : SlotChoice{default_plugin(slot), {}};
    const PluginDescriptor& descriptor = registry.load(slot, choice.plugin);
    ParameterValues values = resolve(descriptor.parameters(), choice.params, "--" + std::string(slot) + ".");
    target = registry.create<Interface>(slot, choice.plugin, values);
    loaded.resolved[slot] = std::move(values);
  };
  make("init", loaded.init);
  make("heuristic", loaded.heuristic);
  make("update", loaded.update);
  make("deadlock", loaded.deadlock);
  make("smoother", loaded.smoother);
  return loaded;
}

ColonyResult run_colony(PluginRegistry& registry, const PipelineSpec& spec, const LoadedPipeline& pipeline,
                        const Graph& graph, NodeId start, NodeId goal, const ColonySettings& settings) {
  if (!settings.bidirectional) return run_colony(graph, start, goal, pipeline.colony(), settings);
  const LoadedPipeline backward = instantiate(registry, spec);
  const Pipeline backward_colony = backward.colony();
  return run_colony(graph, start, goal, pipeline.colony(), settings, &backward_colony);
}

}  // namespace aco
