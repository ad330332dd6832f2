#pragma once
// The fuzz targets: one per loader or parser of hostile input, each taking the raw bytes of one
// input. A target returns normally when the loader succeeds or refuses the input with an
// aco::Error; anything else (another exception, a crash, a sanitizer report) is a bug. The
// libFuzzer harnesses (fuzz_main.cpp) and the regression test (tests/test_fuzz_regressions.cpp)
// share them, so every input a harness found is replayed by the normal test suite.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "aco/error.hpp"

namespace fuzz {

struct Target {
  const char* name;  // the harness name and its folder under corpus/ and regressions/
  void (*run)(std::string_view input);
};

// The map and scenario loaders (need only libaco; map_targets.cpp) and the config and
// experiment readers (need the planning library, acobench and the plugins; config_targets.cpp).
std::span<const Target> map_targets();
std::span<const Target> config_targets();
const Target& find_target(const std::string& name, std::span<const Target> targets);

// The memory limit (aco/memory_limit.hpp) while targets run, far below the fuzzer's
// -rss_limit_mb: a header claiming a huge map must be refused by the loader's estimate, not
// allocated (which the fuzzer would report as out of memory).
inline constexpr std::uint64_t kMemoryLimit = std::uint64_t(32) << 20;

// Input of the ROS target: the YAML, then this line, then the PGM bytes (written as map.pgm
// beside the YAML, which should name it).
inline constexpr std::string_view kRosSeparator = "\n--- PGM ---\n";

// Writes `bytes` to `relative` in a private temporary folder (removed at exit) for the readers
// that take a file. Its "experiments" folder is for experiment files: maps, scenarios, presets
// and terrain beside it link to data/, so "../maps/..." resolves as in data/experiments.
std::filesystem::path write_scratch_file(const std::string& relative, std::string_view bytes);

// Runs a loader: success and aco::Error are both fine; anything else escapes to the fuzzer.
template <class Load>
void expect_no_crash(Load load) {
  try {
    load();
  } catch (const aco::Error&) {}
}

}  // namespace fuzz
