// The conformance checks in voxel worlds (issue 42): every bundled plugin that claims voxel worlds
// (Strategy::supports_voxel_worlds()) passes the "3D" checks, the others are said not to be run
// there, the claims are the ones the docs give, and a plugin that claims voxel worlds but reads
// the graph as a grid's fails with a message saying where.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "aco/sdk/conformance.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using aco::conformance::CheckResult;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

// The bundled plugins that plan in voxel worlds, as slot/name (docs/writing-plugins.md, "Voxel
// worlds"). Every other bundled plugin must not claim them.
const std::set<std::string> kClaimingVoxelWorlds{
    "init/uniform",
    "init/obstacle_density",
    "init/potential_field",
    "heuristic/distance",
    "heuristic/progress",
    "heuristic/adaptive",
    "heuristic/direction",
    "heuristic/potential_field",
    "update/ant_system",
    "update/acs",
    "update/elite",
    "update/gaussian",
    "update/max_min",
    "update/population",
    "update/wolf_pack",
    "deadlock/discard",
    "deadlock/backtrack",
    "deadlock/backtrack_penalty",
    "deadlock/clear_and_tabu",
    "smoother/none",
    "smoother/prune",
};

// The python plugins' example classes (their defaults name none), as tests/CMakeLists.txt gives
// them to aco-plugin-check.
const std::map<std::string, std::string> kPythonClass{
    {"init", "uniform:Uniform"}, {"heuristic", "distance:Distance"}, {"update", "ant_system:AntSystem"}};

std::vector<fs::path> bundled_libraries() {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(ACO_TEST_PLUGIN_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("aco_", 0) == 0 && entry.path().extension() == ".so") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Every check of the kit on a library, by plugin.
std::map<std::string, std::vector<CheckResult>> check(const fs::path& file, const aco::conformance::Options& options) {
  std::map<std::string, std::vector<CheckResult>> results;
  aco::conformance::check_file(file, options, [&](const CheckResult& r) { results[r.plugin].push_back(r); });
  return results;
}

}  // namespace

TEST_CASE("the voxel worlds of the conformance checks: sizes, moves and reachable goals", "[conformance][voxel]") {
  const auto problems = aco::conformance::voxel_problems();
  REQUIRE(problems.size() == 2);
  for (const auto& p : problems) {
    INFO(p.name);
    CHECK(p.graph.volumetric);
    CHECK(p.graph.options.neighbourhood == aco::Neighbourhood::twenty_six);
    CHECK_FALSE(p.graph.options.corner_cutting);
    CHECK(p.graph.terrain_costs.empty());
    const auto path = p.shortest_path();
    // The way up: every path climbs from z = 0 to the top layer.
    CHECK(p.graph.cell(path.front()).z == 0);
    CHECK(p.graph.cell(path.back()).z == p.graph.depth - 1);
    // The standard iterations walk the voxel world too.
    for (const auto& iteration : aco::conformance::standard_iterations(p)) CHECK_FALSE(iteration.ants.empty());
  }
  const auto& voxels = problems[0];
  CHECK(voxels.name == "voxels");
  CHECK((voxels.graph.width == 10 && voxels.graph.height == 8 && voxels.graph.depth == 6));
  // The walled-in corner voxel has no edges; the wall's gap is the only way across x = 5.
  CHECK(voxels.graph.degree(voxels.graph.node({9, 0, 0})) == 0);
  CHECK(voxels.map->passable({9, 0, 0}));
  for (const aco::NodeId n : voxels.shortest_path())
    if (voxels.graph.cell(n).x == 5) CHECK(voxels.graph.cell(n).z >= 3);
  const auto& floors = problems[1];
  CHECK(floors.name == "floors");
  CHECK((floors.graph.width == 4 && floors.graph.height == 4 && floors.graph.depth == 7));
}

TEST_CASE("every bundled plugin claims voxel worlds as the docs say", "[conformance][voxel]") {
  std::set<std::string> claiming, seen;
  for (const auto& plugin : test::plugins().available()) {
    if (plugin.name == "python") continue;  // below, with a class
    const std::string id = plugin.slot + "/" + plugin.name;
    INFO(id);
    seen.insert(id);
    const auto& descriptor = test::plugins().load(plugin.slot, plugin.name);
    const std::unique_ptr<aco::Strategy> strategy(
        descriptor.create(aco::resolve(descriptor.parameters(), {}, plugin.slot + ".")));
    if (strategy->supports_voxel_worlds()) claiming.insert(id);
  }
  // The bundled plugins the list names are built (octomap's map reader only where OctoMap is).
  for (const auto& id : kClaimingVoxelWorlds) CHECK(seen.count(id) == 1);
  CHECK(claiming == kClaimingVoxelWorlds);

  // docs/writing-plugins.md says the same: its list of the bundled plugins that plan in voxel worlds.
  std::ifstream in(fs::path(ACO_TEST_SOURCE_DIR) / "docs/writing-plugins.md");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str();
  const std::size_t begin = docs.find("Bundled plugins that claim voxel worlds:");
  REQUIRE(begin != std::string::npos);
  const std::string list = docs.substr(begin, docs.find("\n\n", begin) - begin);
  std::set<std::string> documented;
  const std::regex named(R"(`([a-z]+/[a-z_]+)`)");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), named); it != std::sregex_iterator(); ++it)
    documented.insert((*it)[1]);
  CHECK(documented == kClaimingVoxelWorlds);

  // And docs/voxel-worlds.md's table "Plugins in 3D", where there is one: a row naming a plugin
  // says "yes" exactly when the plugin claims voxel worlds.
  const fs::path page = fs::path(ACO_TEST_SOURCE_DIR) / "docs/voxel-worlds.md";
  if (fs::exists(page)) {
    std::ifstream page_in(page);
    std::stringstream page_text;
    page_text << page_in.rdbuf();
    const std::string all = page_text.str();
    const std::size_t heading = all.find("Plugins in 3D");
    REQUIRE(heading != std::string::npos);
    std::istringstream rows(all.substr(heading));
    int named_rows = 0;
    const std::regex yes(R"(\|\s*\**yes\**\s*\|)", std::regex::icase);
    for (std::string row; std::getline(rows, row);) {
      if (row.rfind('|', 0) != 0) {
        if (named_rows > 0) break;  // the table's end
        continue;
      }
      for (auto it = std::sregex_iterator(row.begin(), row.end(), named); it != std::sregex_iterator(); ++it) {
        INFO("docs/voxel-worlds.md: " << row);
        ++named_rows;
        if (seen.count((*it)[1]) == 0) continue;  // a planner, or a plugin this build leaves out
        CHECK(std::regex_search(row, yes) == (claiming.count((*it)[1]) == 1));
      }
    }
    CHECK(named_rows > 0);
  }
}

TEST_CASE("every bundled plugin that claims voxel worlds passes the conformance checks in 3D",
          "[conformance][voxel][slow]") {
  aco::conformance::Options options;
  options.grids = false;  // the ctest tests conformance_* run the 2D checks (and these again)
  std::set<std::string> passed_3d;
  for (const fs::path& file : bundled_libraries()) {
    if (file.filename().string().find("_python") != std::string::npos) continue;  // needs a class: below
    for (const auto& [plugin, results] : check(file, options)) {
      INFO(plugin << " (" << file.filename().string() << ")");
      const bool claims = kClaimingVoxelWorlds.count(plugin) == 1;
      int values_3d = 0, not_run = 0;
      for (const CheckResult& r : results) {
        INFO(r.line());
        CHECK(r.status != CheckResult::Status::fail);
        if (r.check == "3D values" && r.status == CheckResult::Status::pass) ++values_3d;
        if (r.check == "3D") {
          ++not_run;
          CHECK(r.status == CheckResult::Status::skip);
          CHECK_THAT(r.detail, StartsWith("not run in 3D: "));
        }
      }
      if (plugin.rfind("map/", 0) == 0) {  // no runs: nothing in 3D to say
        CHECK(values_3d + not_run == 0);
        continue;
      }
      if (claims) {
        CHECK(values_3d > 0);
        // Not at its defaults: a plugin may claim voxel worlds for some values only (prune with
        // clearance 0).
        for (const CheckResult& r : results)
          if (r.check == "3D") CHECK(r.parameters != "defaults");
        CHECK(not_run == (plugin == "smoother/prune" ? 1 : 0));
        passed_3d.insert(plugin);
      } else {
        CHECK(values_3d == 0);
        CHECK(not_run == 1);
      }
    }
  }
  CHECK(passed_3d == kClaimingVoxelWorlds);
}

TEST_CASE("the python plugins do not claim voxel worlds, and the checks say they were not run in 3D",
          "[conformance][voxel][python]") {
  for (const fs::path& file : bundled_libraries()) {
    if (file.filename().string().find("_python") == std::string::npos) continue;
    const std::string slot = file.filename().string().substr(4, file.filename().string().find('_', 4) - 4);
    aco::conformance::Options options;
    options.grids = false;
    options.integer_cap = 2;
    options.fixed = {{"class", kPythonClass.at(slot)}, {"path", std::string(ACO_TEST_EXAMPLES_DIR) + "/python"}};
    const auto results = check(file, options).at(slot + "/python");
    INFO(file.filename().string());
    const auto not_run = std::count_if(results.begin(), results.end(), [](const CheckResult& r) {
      return r.check == "3D" && r.status == CheckResult::Status::skip;
    });
    CHECK(not_run == 1);
    CHECK(std::none_of(results.begin(), results.end(), [](const CheckResult& r) {
      return r.status == CheckResult::Status::fail || r.check == "3D values";
    }));
  }
}

TEST_CASE("a plugin that claims voxel worlds but reads the graph as a grid's fails the 3D checks",
          "[conformance][voxel]") {
  // init/flat sets tau = 1 / the step's length in the plane, which is 0 for a step up or down.
  const auto results = check(fs::path(ACO_TEST_FAULTY_PLUGIN_DIR) / "aco_init_flat.so", {}).at("init/flat");
  std::map<std::string, CheckResult> by_check;
  for (const auto& r : results) by_check.emplace(r.check, r);
  for (const char* passes : {"values", "deterministic", "threads", "reused"}) {
    INFO(passes);
    REQUIRE(by_check.count(passes) == 1);
    CHECK(by_check.at(passes).status == CheckResult::Status::pass);  // a grid is fine
  }
  REQUIRE(by_check.count("3D values") == 1);
  const CheckResult& values = by_check.at("3D values");
  CHECK(values.status == CheckResult::Status::fail);
  CHECK(values.line().rfind("FAIL init/flat [defaults] 3D values: voxels: tau after initialize()[2] = inf (must be "
                            "finite and > 0)",
                            0) == 0);
  CHECK_THAT(values.detail, Contains("use cost(e), reverse_edge(e) and position(n)"));

  // A plugin that does not claim them is not run there: one line says so, not a failure.
  const auto taut = check(fs::path(ACO_TEST_PLUGIN_DIR) / "aco_smoother_taut.so", {}).at("smoother/taut");
  const auto skipped = std::count_if(taut.begin(), taut.end(), [](const CheckResult& r) { return r.check == "3D"; });
  CHECK(skipped == 1);
  const auto line = std::find_if(taut.begin(), taut.end(), [](const CheckResult& r) { return r.check == "3D"; });
  REQUIRE(line != taut.end());
  CHECK(line->line() ==
        "SKIP smoother/taut [defaults] 3D: not run in 3D: it does not claim voxel worlds (supports_voxel_worlds() is "
        "false)");
}
