#pragma once
// What a plugin library exports. A plugin is one class implementing one strategy interface,
// plus one line:
//
//   ACO_PLUGIN(update, ant_system, AntSystemUpdate, "1.0", "Ant System: ...", kParams)
//
// The class needs a constructor taking `const aco::ParameterValues&`; kParams is its parameter
// table: a SettingsTable over a struct of the parameters (see settings_table.hpp; the
// constructor then reads the struct with kParams.read(values)), or an array of ParamSpec rows
// read by name (aco::no_parameters for none). VERSION and SUMMARY are string literals.
//
// The macro exports two things:
// - a plugin record: plain text in the library's ".aco_plugins" section (plugin_record.hpp).
//   Hosts list plugins and check their ABI and standard library from the file alone, without
//   loading it, so no plugin code runs before a plugin is chosen and found compatible;
// - under the Boost.DLL alias aco_plugin__<slot>__<name>, the descriptor: the parameter table
//   and the factory, read once the library is loaded.
#include <boost/dll/alias.hpp>
#include <cstdint>
#include <span>
#include <type_traits>

#include "aco/map_reader.hpp"
#include "aco/parameters.hpp"
#include "aco/plugin_record.hpp"
#include "aco/settings_table.hpp"
#include "aco/slots.hpp"
#include "aco/strategies.hpp"

namespace aco {

// Bump on any change to the strategy interfaces, Context, Ant, Iteration, ParameterValues,
// Map or Graph (plugins read them through Context), or the descriptor below.
// 3: Map::blocked_reason() changed Map's vtable.
// 4: Heuristic::updates_by_node() and update_node() (lazy heuristic updates on large maps).
// 5: PheromoneUpdate::exploitation() removed: q0 is the colony setting ColonySettings::q0.
// 6: the sixth slot, local (LocalPlanner, LocalView).
// 7: LocalView::path (the rest of the global path).
// 8: the plugin record (section ".aco_plugins"); PluginDescriptor::compiler_abi removed (the
//    record's standard-library marker replaces it).
// 9: ParamType::text (free-text parameters, the python bridge's class and path): a value a
//    parameter table, and so the descriptor, may hold that older hosts cannot read.
// 10: the seventh slot, map (MapReader): a descriptor's slot may be "map", whose factory makes a
//     MapReader, and Map objects made by a plugin's code reach the host.
// 11: Context::figures, record() and add() (a plugin's own figures); the record's build field.
// 12: Trail (a pheromone with a lazy scale and bounds): PheromoneUpdate::update_trail(), and
//     DeadlockPolicy::after_iteration() takes a Trail.
// 13: Strategy::begin_run() (the lifecycle); Heuristic::specs() replaces varies_by_iteration(),
//     updates_by_node() and uses_walk().
// 14: voxel worlds: Cell::z, Map::depth() and volumetric(), Graph's depth, 26-move masks, cost()
//     and reverse_edge(), Strategy::supports_voxel_worlds().
// 15: Graph stores per edge only its target and move: cost(), reverse_edge() and position()
//     compute the rest (edge_costs, reverse_edges and positions removed; terrains keep theirs).
// 16: Context::deadline, the run's time limit for the smoother.
// A literal, so the record can spell it; kPluginAbiVersion is the one to use in code.
#define ACO_FRAMEWORK_PLUGIN_ABI 16
inline constexpr std::uint32_t kPluginAbiVersion = ACO_FRAMEWORK_PLUGIN_ABI;
inline constexpr std::uint32_t kPluginMagic = 0x50434f41;  // "ACOP"
inline constexpr const char* kPluginAliasPrefix = "aco_plugin__";

struct PluginDescriptor {
  // magic and abi_version are the first two fields in every ABI version.
  std::uint32_t magic;
  std::uint32_t abi_version;
  const char* slot;
  const char* name;
  const char* version;
  const char* summary;
  const ParamSpec* params;
  std::size_t param_count;
  Strategy* (*create)(const ParameterValues& values);

  std::span<const ParamSpec> parameters() const { return {params, param_count}; }
};

inline constexpr std::span<const ParamSpec> no_parameters{};

// ACO_PLUGIN's PARAMS: ParamSpec rows as they are, or a settings table's rows.
inline std::span<const ParamSpec> parameter_rows(std::span<const ParamSpec> rows) { return rows; }
template <class Settings>
std::span<const ParamSpec> parameter_rows(const SettingsTable<Settings>& table) {
  return table.parameters();
}

// The slots, by the identifier used in ACO_PLUGIN (aco/slots.hpp).
namespace slot {
#define ACO_SLOT_TYPE_(NAME, INTERFACE) \
  struct NAME {                         \
    using interface = INTERFACE;        \
  };
ACO_SLOTS(ACO_SLOT_TYPE_)
#undef ACO_SLOT_TYPE_
}  // namespace slot

}  // namespace aco

// Tests build one plugin with another value to check that the host refuses it.
#ifndef ACO_PLUGIN_ABI_VERSION
#define ACO_PLUGIN_ABI_VERSION ACO_FRAMEWORK_PLUGIN_ABI
#endif
#define ACO_PLUGIN_STRINGIFY_(X) #X
#define ACO_PLUGIN_STRINGIFY(X) ACO_PLUGIN_STRINGIFY_(X)

#define ACO_PLUGIN(SLOT, NAME, CLASS, VERSION, SUMMARY, PARAMS)                                                        \
  namespace {                                                                                                          \
  static_assert(std::is_base_of_v<::aco::slot::SLOT::interface, CLASS>,                                                \
                #CLASS " does not implement the interface of slot '" #SLOT "'");                                       \
  ::aco::Strategy* aco_plugin_create(const ::aco::ParameterValues& values) { return new CLASS(values); }               \
  const ::std::span<const ::aco::ParamSpec> aco_plugin_params{::aco::parameter_rows(PARAMS)};                          \
  const ::aco::PluginDescriptor aco_plugin_descriptor{                                                                 \
      ::aco::kPluginMagic,      ACO_PLUGIN_ABI_VERSION, #SLOT, #NAME, VERSION, SUMMARY, aco_plugin_params.data(),      \
      aco_plugin_params.size(), &aco_plugin_create};                                                                   \
  [[gnu::used, gnu::section(ACO_PLUGIN_RECORD_SECTION)]] const char aco_plugin_record__##SLOT##__##NAME[] =            \
      ACO_PLUGIN_RECORD_MAGIC                                                                                          \
      "\0" ACO_PLUGIN_STRINGIFY(ACO_PLUGIN_ABI_VERSION) "\0" ACO_PLUGIN_STDLIB "\0" __VERSION__                        \
                                                        "\0" ACO_BUILD_OPTIMISATION "\0" #SLOT "\0" #NAME "\0" VERSION \
                                                        "\0" SUMMARY;                                                  \
  }                                                                                                                    \
  BOOST_DLL_ALIAS(aco_plugin_descriptor, aco_plugin__##SLOT##__##NAME)
