#include "aco/engine/pipeline.hpp"

#include <algorithm>
#include <vector>

#include "aco/error.hpp"

namespace aco {

const char* default_plugin(const std::string& slot) {
  const SlotInfo* info = find_slot(slot);
  if (!info || !info->pipeline) throw Error("unknown slot '" + slot + "'");
  return info->default_plugin;
}

PipelinePlugins instantiate(PluginRegistry& registry, const PipelineSpec& spec) {
  PipelinePlugins loaded;
  auto make = [&](const char* slot, auto& target) {
    using Interface = typename std::remove_reference_t<decltype(target)>::element_type;
    const auto it = spec.find(slot);
    if (it == spec.end()) throw Error(std::string("the pipeline has no plugin for the slot '") + slot + "'");
    target = registry.create<Interface>(slot, it->second.plugin, it->second.parameters);
  };
#define ACO_MAKE_SLOT_(NAME, INTERFACE) make(#NAME, loaded.NAME);
  ACO_PIPELINE_SLOTS(ACO_MAKE_SLOT_)
#undef ACO_MAKE_SLOT_
  return loaded;
}

ColonyResult run_pipeline(PluginRegistry& registry, const PipelineSpec& spec, const PipelinePlugins& pipeline,
                          const Graph& graph, NodeId start, NodeId goal, const ColonySettings& settings,
                          FigureSink* figures) {
  ColonyStrategies forward = pipeline.strategies();
  forward.figures = figures;
  if (settings.colonies > 1) {
    std::vector<PipelinePlugins> more;
    std::vector<ColonyStrategies> islands;
    for (int c = 1; c < settings.colonies; ++c) more.push_back(instantiate(registry, spec));
    for (const PipelinePlugins& plugins : more) {
      islands.push_back(plugins.strategies());
      islands.back().figures = figures;
    }
    return run_colony(graph, start, goal, forward, settings, nullptr, islands);
  }
  if (!settings.bidirectional) return run_colony(graph, start, goal, forward, settings);
  const PipelinePlugins backward = instantiate(registry, spec);
  ColonyStrategies backward_colony = backward.strategies();
  backward_colony.figures = figures;
  return run_colony(graph, start, goal, forward, settings, &backward_colony);
}

}  // namespace aco
