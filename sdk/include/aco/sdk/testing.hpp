#pragma once
// For Catch2 tests of a plugin (aco-new-plugin generates one): the standard tiny maps and
// iterations of the conformance checks, a Context for any iteration of them, the plugin loaded
// from its library file, and the checks of aco-plugin-check as Catch2 checks.
//
//   #define CATCH_CONFIG_MAIN
//   #include "aco/sdk/testing.hpp"
//   TEST_CASE("conformance") { aco::testing::check_conformance(PLUGIN_FILE); }
//   TEST_CASE("best path gains") {
//     const auto problem = aco::testing::standard_problems().front();
//     auto update = aco::testing::create<aco::PheromoneUpdate>(PLUGIN_FILE, {{"rho", "0.5"}});
//     ... update->update(problem.context(), aco::testing::standard_iterations(problem)[0].view(), tau) ...
//   }
// Link aco::conformance and Catch2::Catch2.
#include <catch2/catch.hpp>

#include <filesystem>
#include <span>
#include <string>

#include "aco/sdk/conformance.hpp"

namespace aco::testing {

using conformance::create;  // the plugin of a slot in a library file
using conformance::IterationCase;  // one iteration's ants; view() is the Iteration
using conformance::make_problem;  // a map from rows of text
using conformance::make_voxel_problem;  // a voxel world (aco::VoxelMap) with start and goal
using conformance::Problem;  // a map, its graph, start, goal; context(iteration)
using conformance::standard_iterations;  // ants arrived, no ant arrived, all ants dead
using conformance::standard_problems;  // open, obstacles, dead end, corridor
using conformance::voxel_problems;  // voxels, floors: voxel worlds, 26-neighbourhood
using conformance::walk;  // an Ant along given nodes

// Every check aco-plugin-check makes, on every plugin of the file, as one Catch2 check each
// (a failure shows the line aco-plugin-check would print).
inline void check_conformance(const std::filesystem::path& file, const conformance::Options& options = {}) {
  conformance::check_file(file, options, [](const conformance::CheckResult& result) {
    INFO(result.line());
    CHECK(result.status != conformance::CheckResult::Status::fail);
  });
}

// Every value finite and >= minimum (> minimum when strict); `what` names them in the message.
inline void check_values(std::span<const double> values, const std::string& what, double minimum = 0.0,
                         bool strict = false) {
  const std::string bad = conformance::bad_value(values, what, minimum, strict);
  INFO(bad);
  CHECK(bad.empty());
}

}  // namespace aco::testing
