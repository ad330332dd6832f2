#pragma once
// The slots, written once. Everything that lists slots comes from here: the export macro's check
// (plugin.hpp), the pipeline (pipeline.hpp), the error boundary's decorators (plugin_guard.hpp),
// the conformance checks' dispatch (sdk conformance), the hosts' options, --list-plugins; and a
// test (tests/test_slots.cpp) compares aco-new-plugin's slots and docs/writing-plugins.md's slot
// table with kSlotTable. A new slot is one line here plus the code where it really differs: its
// interface, its guard's decorator, its conformance runs, its scaffold template and docs row.
//
// ACO_PIPELINE_SLOTS(X) calls X(NAME, INTERFACE) for each slot a run fills with one plugin, in
// pipeline order; ACO_SLOTS(X) for every slot, the pipeline's and then map, whose plugin is
// chosen by the map file (its extension, or --map-format).
#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

#define ACO_PIPELINE_SLOTS(X) \
  X(init, PheromoneInit)      \
  X(heuristic, Heuristic)     \
  X(update, PheromoneUpdate)  \
  X(deadlock, DeadlockPolicy) \
  X(smoother, Smoother)       \
  X(local, LocalPlanner)
#define ACO_SLOTS(X)    \
  ACO_PIPELINE_SLOTS(X) \
  X(map, MapReader)

namespace aco {

struct SlotInfo {
  const char* name;  // the slot, as in ACO_PLUGIN(NAME, ...), "slot/name" and the plugin file name
  const char* interface;  // the class a plugin of the slot implements
  const char* option;  // the run key (acoplan option) choosing its plugin: "update", "map-format"
  const char* default_plugin;  // the plugin a run gets unless it chooses; "" if the map file decides
  const char* method;  // the interface's one pure virtual
  const char* hooks;  // its optional virtuals, comma separated ("" none)
  const char* checked;  // what aco-plugin-check checks beyond constructing every parameter set
  bool pipeline;  // one plugin per run in every run (ACO_PIPELINE_SLOTS)
};

inline constexpr SlotInfo kSlotTable[] = {
    {"init", "PheromoneInit", "init", "uniform", "initialize", "",
     "pheromone > 0 and finite; deterministic; same on 1 and 4 threads; a colony run", true},
    {"heuristic", "Heuristic", "heuristic", "distance", "compute", "specs, compute_powered, update_node, step_factors",
     "eta and factors >= 0 and finite; update_node as compute_powered; deterministic; threads; a colony run", true},
    {"update", "PheromoneUpdate", "update", "ant_system", "update", "start, update_trail",
     "pheromone >= 0 and finite after each iteration case; deterministic; threads; a colony run", true},
    {"deadlock", "DeadlockPolicy", "deadlock", "discard", "on_stuck", "after_iteration",
     "steps back within the walk; pheromone finite; deterministic; threads; a colony run", true},
    {"smoother", "Smoother", "smoother", "none", "smooth", "",
     "waypoints finite, on free cells, ends kept; deterministic; threads", true},
    {"local", "LocalPlanner", "local", "track", "command", "",
     "commands finite and inside the dynamic window; deterministic; threads", true},
    {"map", "MapReader", "map-format", "", "read", "extensions, sample",
     "claims an extension or is chosen by name; a missing file is an Error naming it; its sample reads "
     "deterministically into a map with finite positions",
     false},
};

namespace detail {
constexpr std::size_t count_pipeline_slots() {
  std::size_t n = 0;
  for (const SlotInfo& s : kSlotTable) n += s.pipeline ? 1 : 0;
  return n;
}
}  // namespace detail

// The pipeline's slots, in order: every run has one plugin in each.
inline constexpr auto kSlots = [] {
  std::array<const char*, detail::count_pipeline_slots()> names{};
  std::size_t i = 0;
  for (const SlotInfo& s : kSlotTable)
    if (s.pipeline) names[i++] = s.name;
  return names;
}();

// Every slot's row, or null.
constexpr const SlotInfo* find_slot(std::string_view name) {
  for (const SlotInfo& s : kSlotTable)
    if (name == s.name) return &s;
  return nullptr;
}

// The table and the X-macro lists agree (same slots, same interfaces, same order).
namespace detail {
#define ACO_SLOT_ROW_(NAME, INTERFACE) {#NAME, #INTERFACE},
inline constexpr std::pair<std::string_view, std::string_view> kSlotMacroRows[] = {ACO_SLOTS(ACO_SLOT_ROW_)};
#undef ACO_SLOT_ROW_
constexpr bool table_matches_macro() {
  if (std::size(kSlotMacroRows) != std::size(kSlotTable)) return false;
  for (std::size_t i = 0; i < std::size(kSlotTable); ++i)
    if (kSlotMacroRows[i].first != kSlotTable[i].name || kSlotMacroRows[i].second != kSlotTable[i].interface)
      return false;
  return true;
}
#define ACO_SLOT_COUNT_(NAME, INTERFACE) +1
// The pipeline's slots come first, as ACO_PIPELINE_SLOTS lists them.
static_assert(count_pipeline_slots() == 0 ACO_PIPELINE_SLOTS(ACO_SLOT_COUNT_),
              "ACO_PIPELINE_SLOTS and kSlotTable's pipeline rows differ");
#undef ACO_SLOT_COUNT_
static_assert(table_matches_macro(), "kSlotTable and ACO_SLOTS list different slots");
}  // namespace detail

}  // namespace aco
