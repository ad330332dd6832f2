#pragma once
// What every command prints for --version: which framework built it, from which commit, how.
#include <string>

namespace aco {

// "acoplan 0.1.0 (commit 2a5e52b, Release build, GCC 12.2.0)": the project version, the git
// commit the build was configured at ("unknown" outside a git checkout), the CMake build type and
// the compiler.
std::string version_text(const std::string& program);
// The project version alone, "0.1.0": what version_text() starts with (Python's aco.__version__).
std::string version();

}  // namespace aco
