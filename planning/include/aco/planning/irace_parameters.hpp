#pragma once
// Tuning with irace: the parameter file built from the colony's and the plugins' parameter
// tables (acoplan --dump-irace-params).
#include <string>
#include <vector>

#include "aco/engine/plugin_registry.hpp"

namespace aco {

// irace's parameter file (one line per parameter: name "switch" type (domain) [| condition]):
// the colony's table without seed, then for each of `slots` a categorical choice among the
// slot's plugins and every plugin's parameters, conditional on that choice. Numeric ranges are
// made finite and closed by the rule stated in the file's header.
std::string irace_parameters(PluginRegistry& registry, const std::vector<std::string>& slots);

// The parameter file of one plugin (`plugin`: "update/mine"): its slot fixed to it (a choice of
// one, so irace passes --update mine itself) and the plugin's parameters; the colony and the
// other slots stay as the target runner's acoplan options set them. An Error names a `plugin`
// that is not SLOT/NAME of a plugin found, or one whose parameters irace cannot tune.
std::string irace_plugin_parameters(PluginRegistry& registry, const std::string& plugin);

}  // namespace aco
