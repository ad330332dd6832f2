// The seventh slot, map: map readers as plugins, chosen by the file's ending or by --map-format.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "aco/sdk/conformance.hpp"
#include "aco/engine/map_formats.hpp"
#include "aco/planning/plugin_catalog.hpp"
#include "aco/planning/run_spec.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

const std::filesystem::path room = std::filesystem::path(ACO_TEST_EXAMPLES_DIR) / "shapes_map/room.shapes";
const std::filesystem::path arena = test::data_dir() / "maps/movingai/arena.map";

aco::PluginRegistry& map_plugins() {
  static aco::PluginRegistry registry({ACO_TEST_MAP_PLUGIN_DIR, ACO_TEST_PLUGIN_DIR});
  return registry;
}
aco::PluginRegistry& greedy_and_map_plugins() {
  static aco::PluginRegistry registry({ACO_TEST_GREEDY_MAP_PLUGIN_DIR, ACO_TEST_MAP_PLUGIN_DIR, ACO_TEST_PLUGIN_DIR});
  return registry;
}

}  // namespace

TEST_CASE("a map plugin reads the files whose ending it claims", "[map_plugins]") {
  const auto map = aco::load_map(room, {}, map_plugins());
  CHECK(map->width() == 20);
  CHECK(map->height() == 16);
  CHECK_FALSE(map->passable({4, 0}));
  CHECK(map->passable({0, 0}));
  CHECK(aco::map_format_of(room, "", map_plugins()) == "shapes");
  CHECK(aco::map_format_of(arena, "", map_plugins()) == "movingai");
}

TEST_CASE("a run's keys choose the map plugin and set its parameters", "[map_plugins]") {
  const aco::RunSpec run = aco::resolve_run(
      {{"map", room.string()}, {"start", "0,0"}, {"goal", "39,31"}, {"map.resolution", "0.25"}}, map_plugins(), "--");
  CHECK(run.problem.map_format == "shapes");
  CHECK(run.problem.map_parameters.real("resolution") == 0.25);
  const aco::Keys keys = aco::to_keys(run);
  CHECK(keys.at("map-format") == "shapes");
  CHECK(keys.at("map.resolution") == "0.25");
  const aco::LoadedProblem problem = aco::load_problem(run.problem, &map_plugins());
  CHECK(problem.map->width() == 40);
  // A built-in format chosen by the ending adds no key: runs on bundled maps keep theirs.
  const aco::RunSpec bundled =
      aco::resolve_run({{"map", arena.string()}, {"start", "1,1"}, {"goal", "2,2"}}, map_plugins());
  CHECK(bundled.problem.map_format.empty());
  CHECK_FALSE(aco::to_keys(bundled).count("map-format"));
  CHECK_THROWS_WITH(
      aco::resolve_run({{"map", arena.string()}, {"start", "1,1"}, {"goal", "2,2"}, {"map.resolution", "1"}},
                       map_plugins(), "--"),
      Contains("--map.resolution: the built-in map format 'movingai'") && Contains("takes no parameters"));
  CHECK_THROWS_WITH(
      aco::resolve_run({{"map", room.string()}, {"start", "0,0"}, {"goal", "1,1"}, {"map-format", "shapez"}},
                       map_plugins(), "--"),
      Contains("--map-format: unknown map format 'shapez'") && Contains("did you mean 'shapes'?"));
}

TEST_CASE("two readers claiming one ending are an error naming both and --map-format", "[map_plugins]") {
  CHECK_THROWS_WITH(aco::load_map(arena, {}, greedy_and_map_plugins()),
                    Contains("the built-in format movingai and plugin map/greedy") && Contains("--map-format NAME"));
  CHECK_THROWS_WITH(aco::load_map(room, {}, greedy_and_map_plugins()),
                    Contains("plugin map/greedy") && Contains("plugin map/shapes") && Contains("--map-format NAME"));
  CHECK(aco::load_map(arena, {}, greedy_and_map_plugins(), "movingai")->width() == 49);
  CHECK(aco::load_map(room, {}, greedy_and_map_plugins(), "shapes")->width() == 20);
}

TEST_CASE("a file no format claims is read as a 0/1 matrix and otherwise mentions map plugins", "[map_plugins]") {
  const auto matrix = test::temp_file("grid.rows", "0 1\n0 0\n");
  CHECK(aco::load_map(matrix, {}, map_plugins())->width() == 2);
  const auto other = test::temp_file("grid.rows", "a format nobody reads\n");
  CHECK_THROWS_WITH(aco::load_map(other, {}, map_plugins()),
                    Contains("is not a number") && Contains("no built-in format or map plugin claims '.rows'") &&
                        Contains("--map-format NAME"));
  CHECK_THROWS_WITH(aco::load_map(room, {}, map_plugins(), "nothing"), Contains("unknown map format 'nothing'"));
}

TEST_CASE("listing and describing plugins shows map readers as map/NAME", "[map_plugins]") {
  const std::string listed = aco::list_plugins(map_plugins());
  CHECK_THAT(listed,
             Contains("map/movingai  built-in") && Contains("claims .yaml .yml") && Contains("map/shapes  0.1"));
  CHECK_THAT(aco::describe_plugin(map_plugins(), "map/shapes"), Contains("claims .shapes") && Contains("resolution"));
  CHECK_THAT(aco::describe_plugin(map_plugins(), "map/esri_ascii"), Contains("built-in") && Contains("claims .asc"));
}

TEST_CASE("aco-plugin-check's checks pass on the example map plugin and catch a reader of nothing", "[map_plugins]") {
  std::vector<aco::conformance::CheckResult> results;
  const int failures =
      aco::conformance::check_file(std::filesystem::path(ACO_TEST_MAP_PLUGIN_DIR) / "aco_map_shapes.so", {},
                                   [&](const auto& r) { results.push_back(r); });
  CHECK(failures == 0);
  CHECK(std::any_of(results.begin(), results.end(),
                    [](const auto& r) { return r.line() == "PASS map/shapes [defaults] values"; }));
  CHECK(std::any_of(results.begin(), results.end(),
                    [](const auto& r) { return r.line() == "PASS map/shapes [resolution=10] deterministic"; }));
  std::vector<std::string> lines;
  aco::conformance::check_file(std::filesystem::path(ACO_TEST_GREEDY_MAP_PLUGIN_DIR) / "aco_map_greedy.so", {},
                               [&](const auto& r) { lines.push_back(r.line()); });
  CHECK(lines == std::vector<std::string>{"PASS map/greedy [defaults] values",
                                          "PASS map/greedy [defaults] deterministic",
                                          "PASS map/greedy [defaults] threads"});
}

TEST_CASE("acoplan plans on a map a plugin reads", "[map_plugins]") {
  const auto r = test::acoplan({"--plugin-dir", ACO_TEST_MAP_PLUGIN_DIR, "--map", room.string(), "--start", "0,0",
                                "--goal", "39,31", "--map.resolution", "0.25", "--iterations", "20", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["solved"] == true);
  CHECK(j["config"]["map-format"] == "shapes");
  CHECK(j["config"]["map.resolution"] == 0.25);
  const auto help = test::acoplan({"--plugin-dir", ACO_TEST_MAP_PLUGIN_DIR, "--map", room.string(), "--help"});
  CHECK_THAT(help.out, Contains("map plugin 'shapes'") && Contains("--map.resolution"));
}
