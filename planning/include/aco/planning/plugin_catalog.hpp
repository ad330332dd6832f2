#pragma once
// The plugins a registry found, as acoplan --list-plugins and --describe print them.
#include <string>

#include "aco/engine/plugin_registry.hpp"

namespace aco {

// Every plugin found, by slot: version, summary (or why it is unusable), its file and the files
// it shadows; then the folders searched. Runs no plugin code.
std::string list_plugins(PluginRegistry& registry);

// One plugin, "slot/name" ("update/max_min"), or the name alone when one slot only has a plugin
// so called: its provenance and its parameter table with types, defaults and ranges. Error for an
// unknown name (with the nearest), and for a bare name that several slots have (init and
// heuristic both have potential_field), listing the slot/name forms to give instead.
std::string describe_plugin(PluginRegistry& registry, const std::string& name);

}  // namespace aco
