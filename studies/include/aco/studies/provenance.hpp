#pragma once
// Where results came from, for the results database and the processes that make them (worker
// processes, MPI ranks): what changed between two fingerprints. (The machine's name is
// aco::hostname(), aco/machine.hpp.)
#include <string>

namespace aco::studies {

// Why the fingerprint `now` is not the `stored` one, for messages: for acobench's fingerprints,
// the plugin binary or the part of the experiment that changed.
std::string fingerprint_change(const std::string& stored, const std::string& now);

}  // namespace aco::studies
