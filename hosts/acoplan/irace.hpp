#pragma once
// Tuning with irace: the parameter file built from the colony's and the plugins' parameter
// tables (--dump-irace-params), and the cost acoplan reports to irace's target runner (--irace).
#include <string>
#include <vector>

#include "aco/plugin_registry.hpp"

namespace acoplan {

// The cost of an unsolved run under --irace: irace needs a number, and this one is longer than
// any path on a map acoplan can load, so irace ranks a configuration that fails below every one
// that succeeds.
inline constexpr double kIraceUnsolvedCost = 1e9;

// irace's parameter file (one line per parameter: name "switch" type (domain) [| condition]):
// the colony's table without seed, then for each of `slots` a categorical choice among the
// slot's plugins and every plugin's parameters, conditional on that choice. Numeric ranges are
// made finite and closed by the rule stated in the file's header.
std::string irace_parameters(aco::PluginRegistry& registry, const std::vector<std::string>& slots);

}  // namespace acoplan
