#pragma once
// acoplan's logic without main(): what a parsed command line does, writing to a stream. The
// acoplan_core library holds it with the option parsing, so tests run it in-process; the runs,
// reports, plugin listings and irace's table are the planning library's (aco/planning/plan_request.hpp,
// aco/planning/plugin_catalog.hpp, aco/planning/irace_parameters.hpp).
#include <ostream>

#include "command_line.hpp"

namespace acoplan {

// The cost of an unsolved run under --irace: irace needs a number, and this one is longer than
// any path on a map acoplan can load, so irace ranks a configuration that fails below every one
// that succeeds.
inline constexpr double kIraceUnsolvedCost = 1e9;

// Carries out the request (plan, help, list, describe, print the config, dump irace's table) and
// returns the exit status (aco::kExitOk, or aco::kExitNoPath when a run found no path). Errors are thrown (aco::Error),
// as parse_command_line() does.
int run(Request& request, std::ostream& out);

}  // namespace acoplan
