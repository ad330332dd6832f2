#include <catch2/catch.hpp>
#include <algorithm>
#include <fstream>

#include "aco/error.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "support.hpp"

using Catch::Contains;
namespace fs = std::filesystem;

TEST_CASE("plugins are listed from their export tables, one library each", "[registry]") {
  aco::PluginRegistry registry({ACO_TEST_PLUGIN_DIR});
  const std::vector<std::pair<std::string, std::string>> baseline{
      {"init", "uniform"}, {"heuristic", "distance"}, {"update", "ant_system"}, {"update", "max_min"},
      {"update", "acs"},   {"deadlock", "discard"},   {"smoother", "none"}};
  for (const auto& [slot, name] : baseline) {
    const auto* found = registry.find(slot, name);
    REQUIRE(found != nullptr);
    CHECK(found->file.filename() == "aco_" + slot + "_" + name + ".so");
  }
  const auto updates = registry.names("update");
  CHECK(std::is_sorted(updates.begin(), updates.end()));
  for (const char* name : {"acs", "ant_system", "max_min"})
    CHECK(std::count(updates.begin(), updates.end(), name) == 1);
  const auto& d = registry.load("update", "ant_system");
  CHECK(std::string(d.slot) == "update");
  CHECK(std::string(d.name) == "ant_system");
  CHECK(d.abi_version == aco::kPluginAbiVersion);
  CHECK(d.param_count == 2);
}

TEST_CASE("an unknown plugin is an error naming the nearest and the available ones", "[registry]") {
  aco::PluginRegistry registry({ACO_TEST_PLUGIN_DIR});
  REQUIRE_THROWS_WITH(registry.load("update", "max_mn"),
                      Contains("unknown update plugin 'max_mn'") && Contains("did you mean 'max_min'?") &&
                          Contains("available: acs, ant_system, elite, gaussian, max_min"));
  REQUIRE_THROWS_WITH(registry.load("smoother", "prune_xyz"), Contains("unknown smoother plugin") && Contains("none"));
}

TEST_CASE("a plugin built for another ABI version is refused before use", "[registry][abi]") {
  aco::PluginRegistry registry({ACO_TEST_BAD_PLUGIN_DIR});
  REQUIRE(registry.find("update", "wrong_abi") != nullptr);
  REQUIRE_THROWS_WITH(registry.load("update", "wrong_abi"),
                      Contains("plugin update/wrong_abi") &&
                          Contains("ABI 999, host expects " + std::to_string(aco::kPluginAbiVersion)));
  REQUIRE_THROWS_WITH(registry.create("update", "wrong_abi", {}), Contains("ABI 999"));
}

TEST_CASE("removing one plugin library leaves the others working", "[registry]") {
  const fs::path dir = test::temp_file("placeholder", "").parent_path() / "plugins";
  fs::create_directories(dir);
  for (const auto& entry : fs::directory_iterator(ACO_TEST_PLUGIN_DIR))
    if (entry.path().extension() == ".so" && entry.path().filename() != "aco_update_max_min.so")
      fs::copy_file(entry.path(), dir / entry.path().filename());
  std::ofstream(dir / "not_a_plugin.so") << "this is not an ELF file";
  aco::PluginRegistry registry({dir});
  CHECK(registry.find("update", "max_min") == nullptr);
  REQUIRE_THROWS_WITH(registry.load("update", "max_min"),
                      Contains("unknown update plugin 'max_min'") &&
                          Contains("available: acs, ant_system, elite, gaussian, population") &&
                          Contains("wolf_pack; searched:"));  // python between them when built
  const auto& d = registry.load("update", "ant_system");
  auto update = registry.create<aco::PheromoneUpdate>("update", "ant_system", aco::resolve(d.parameters(), {}, ""));
  CHECK(update != nullptr);
}

TEST_CASE("a plugin of the wrong slot is not accepted as another interface", "[registry]") {
  aco::PluginRegistry registry({ACO_TEST_PLUGIN_DIR});
  const auto& d = registry.load("init", "uniform");
  REQUIRE_THROWS_WITH(registry.create<aco::Heuristic>("init", "uniform", aco::resolve(d.parameters(), {}, "")),
                      Contains("does not implement the init interface"));
}

TEST_CASE("acoplan does not link any plugin library", "[registry]") {
  const auto ldd = test::run({"/usr/bin/ldd", ACO_TEST_ACOPLAN});
  REQUIRE(ldd.exit_code == 0);
  CHECK_THAT(ldd.out, Contains("libaco.so"));
  CHECK_THAT(ldd.out, !Contains("aco_update") && !Contains("aco_init") && !Contains("aco_heuristic") &&
                          !Contains("aco_deadlock") && !Contains("aco_smoother"));
}
