#include "aco/studies/experiment.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/planning/run_spec.hpp"
#include "targets.hpp"

namespace fuzz {
namespace {

aco::PluginRegistry& registry() {
  static aco::PluginRegistry r({ACO_FUZZ_PLUGIN_DIR});
  return r;
}

// The INI reader, then the keys it read resolved as a run (every value parsed and checked).
void ini_config(std::string_view input) {
  const auto file = write_scratch_file("fuzz.ini", input);
  expect_no_crash([&] { aco::resolve_run(aco::read_config_file(file.string()), registry()); });
}

void experiment(std::string_view input) {
  const auto file = write_scratch_file("experiments/fuzz.yaml", input);
  expect_no_crash([&] { aco::studies::load_experiment(file, registry()); });
}

constexpr Target kTargets[] = {{"ini_config", ini_config}, {"experiment", experiment}};

}  // namespace

std::span<const Target> config_targets() { return kTargets; }

}  // namespace fuzz
