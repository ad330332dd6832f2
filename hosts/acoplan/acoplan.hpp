#pragma once
// acoplan's logic without main(): what a parsed command line does, writing to a stream. The
// acoplan_core library holds it with the option parsing, the reports and the irace support, so
// tests run it in-process.
#include <ostream>

#include "command_line.hpp"

namespace acoplan {

inline constexpr int kExitError = 1;
inline constexpr int kExitUnsolved = 3;  // no path found (goal unreachable or no ant arrived)

// Carries out the request (plan, help, list, describe, print the config, dump irace's table) and
// returns the exit status. Errors are thrown (aco::Error), as parse_command_line() does.
int run(Request& request, std::ostream& out);

}  // namespace acoplan
