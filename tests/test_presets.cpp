// Named presets (data/presets/NAME.ini): --preset NAME, --list-presets, `preset:` in experiment
// files, each paper's pipeline as the paper experiments run it.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "aco/error.hpp"
#include "aco/planning/presets.hpp"
#include "acobench_support.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace test::acobench_helpers;

namespace {

// acoplan --print-config's lines without the problem (map, start, goal, seed).
std::string pipeline_of(const std::vector<std::string>& args) {
  const auto r = test::acoplan(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::string kept;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("map =", 0) != 0 && line.rfind("# ", 0) != 0) kept += line + "\n";
  return kept;
}

}  // namespace

TEST_CASE("every bundled preset is listed with its first comment line", "[presets]") {
  std::vector<std::string> names;
  for (const auto& p : aco::list_presets()) {
    names.push_back(p.name);
    CHECK_FALSE(p.summary.empty());
    CHECK(p.summary.back() == '.');  // a whole sentence, not a line cut mid-way
  }
  CHECK(names == std::vector<std::string>{"ant-system", "paper000", "paper001", "paper002", "paper003", "paper004",
                                          "robust", "terrain", "voxel"});
  const auto r = test::acoplan({"--list-presets"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out,
             Contains("  paper001  Paper 001's improved colony") && Contains("  robust  The recommended pipeline"));
}

TEST_CASE("acoplan --preset NAME reads the named preset file and mistakes are named", "[presets][acoplan]") {
  const std::string robust = (test::data_dir() / "presets" / "robust.ini").string();
  CHECK(pipeline_of({"--preset", "robust", "--print-config"}) == pipeline_of({"--config", robust, "--print-config"}));
  CHECK(aco::preset_file("paper002") == test::data_dir() / "presets" / "paper002.ini");
  const auto unknown = test::acoplan({"--preset", "paper01"});
  CHECK(unknown.exit_code == 1);
  CHECK_THAT(unknown.err,
             Contains("unknown preset 'paper01'; did you mean 'paper001'?") && Contains("available: ant-system"));
  CHECK_THAT(test::acoplan({"--preset", "robust", "--config", robust}).err,
             Contains("--config and --preset: give one of them"));
  // The command line wins over the preset.
  CHECK_THAT(pipeline_of({"--preset", "paper001", "--beta", "3", "--print-config"}),
             Contains("beta = 3") && Contains("heuristic = direction"));
}

TEST_CASE("each paper's preset is the pipeline its experiment ran before presets were named", "[presets][acobench]") {
  // The improved configurations as the experiment files wrote them key by key (until presets),
  // against `preset: paperNNN` over the same settings: the same resolved run.
  const std::vector<std::pair<std::string, std::string>> papers{
      {"paper001",
       "{preset: ant-system, ants: 20, iterations: 200, alpha: 1, beta: 1, corner-cutting: true, same-path-stop: true, "
       "same-path-fraction: 0.9, heuristic: direction, deadlock: backtrack_penalty}"},
      {"paper002",
       "{preset: ant-system, ants: 50, iterations: 100, alpha: 1, beta: 7, corner-cutting: true, update: gaussian, "
       "update.psi: 300, update.mu: 0, update.sigma: 1, update.rho: 0.3, update.q: 1, deadlock: clear_and_tabu}"},
      {"paper004",
       "{preset: ant-system, ants: 50, iterations: 50, corner-cutting: true, alpha: 2, beta: 8, update: ant_system, "
       "update.rho: 0.9, update.q: 1, init: fireworks, deadlock: backtrack_penalty}"}};
  for (const auto& [preset, keys] : papers) {
    INFO(preset);
    const auto e = load("name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\nbaseline: " + keys +
                        "\nconfigurations:\n  - {name: named, preset: " + preset + "}\n");
    CHECK(aco::to_json(*e.configurations[0].run) == aco::to_json(*e.configurations[1].run));
  }
  CHECK_THROWS_WITH(
      load("name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\nbaseline: {preset: nope}\n"),
      Contains("unknown preset 'nope'"));
  CHECK_THROWS_WITH(load("name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
                         "baseline: {preset: robust, config: x.ini}\n"),
                    Contains("'config' and 'preset': give one of them"));
}

TEST_CASE("a command naming no pipeline runs the recommended preset for its map's kind", "[presets][acoplan]") {
  const std::string terrain = (test::data_dir() / "terrain" / "epf20.asc.scen").string();
  // acoplan: robust on 2D maps (the bundled demo map, a Moving AI scenario), terrain on height maps.
  CHECK(pipeline_of({"--print-config"}) == pipeline_of({"--preset", "robust", "--print-config"}));
  const std::string room = (test::data_dir() / "maps" / "generated" / "room32-8-s1.map.scen").string();
  CHECK(pipeline_of({"--scen", room, "--print-config"}) ==
        pipeline_of({"--scen", room, "--preset", "robust", "--print-config"}));
  CHECK(pipeline_of({"--scen", terrain, "--print-config"}) ==
        pipeline_of({"--scen", terrain, "--preset", "terrain", "--print-config"}));
  CHECK(pipeline_of({"--scen", terrain, "--print-config"}) !=
        pipeline_of({"--scen", terrain, "--preset", "robust", "--print-config"}));
  // Another plugin in a slot drops the preset's parameters of that slot instead of refusing them.
  CHECK_THAT(pipeline_of({"--heuristic", "distance", "--print-config"}),
             Contains("heuristic = distance") && !Contains("floor"));
}

TEST_CASE("acobench configurations naming no pipeline run the recommended preset", "[presets][acobench]") {
  const std::string problems = "name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n";
  const auto e = load(problems +
                      "baseline: {name: bare}\nconfigurations:\n  - {name: mmas, update: max_min}\n"
                      "  - {name: classic, preset: ant-system}\n");
  const auto robust = load(problems + "baseline: {name: robust, preset: robust}\n");
  CHECK(aco::to_json(*e.configurations[0].run) == aco::to_json(*robust.configurations[0].run));
  CHECK(e.configurations[1].run->colony.fill_dead_ends);  // robust's, under its own update
  CHECK(e.configurations[1].run->pipeline.at("update").plugin == "max_min");
  // A configuration naming a preset gets that preset alone, not the recommended one beneath it.
  CHECK_FALSE(e.configurations[2].run->colony.fill_dead_ends);
  CHECK(e.configurations[2].run->pipeline.at("heuristic").plugin == "distance");
  // Height maps: terrain's; a mix of kinds must name one.
  const std::string terrain =
      "  - {scen: " + (test::data_dir() / "terrain" / "epf20.asc.scen").string() + ", count: 1}\n";
  const auto t = load("name: t\nproblems:\n" + terrain + "baseline: {name: bare}\n");
  CHECK(t.configurations[0].run->colony.bidirectional);
  CHECK_THROWS_WITH(load(problems + terrain + "baseline: {name: bare}\n"),
                    Contains("the problems mix 2D maps and height maps"));
  CHECK_NOTHROW(load(problems + terrain + "baseline: {name: named, preset: robust}\n"));
}

TEST_CASE("acosim runs the recommended pipeline under a scenario naming none and takes run keys on its command line",
          "[presets][acosim][slow]") {
  const auto scenario =
      test::temp_file("bare.yaml", "run:\n  map: " + map1() + "\n  start: [0, 0]\n  goal: [19, 19]\n  local: dwa\n");
  const auto json_of = [&](const std::vector<std::string>& args) {
    std::vector<std::string> argv{ACO_TEST_ACOSIM, scenario.string(), "--json"};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto r = test::run(argv);
    INFO(r.err);
    REQUIRE(r.exit_code != 1);  // 0 reached, 3 not: the configuration is what is looked at
    return nlohmann::json::parse(r.out)["config"];
  };
  const auto bare = json_of({});
  CHECK(bare["update"] == "max_min");
  CHECK(bare["fill-dead-ends"] == true);
  CHECK(bare["local.follow"] == 0.5);  // the DWA's defaults: the measured best
  CHECK(bare["local.predict"] == true);
  const auto keyed = json_of({"--ants", "20", "--local.follow=0", "--corner-cutting", "--update", "max_min"});
  CHECK(keyed["ants"] == 20);
  CHECK(keyed["local.follow"] == 0.0);
  CHECK(keyed["corner-cutting"] == true);
  CHECK(keyed["update"] == "max_min");
  const auto paper = json_of({"--preset", "paper003"});
  CHECK(paper["update"] == "wolf_pack");
  CHECK(paper["local.follow"] == 0.0);
  CHECK(paper["local.predict"] == false);
  const auto error = [&](const std::vector<std::string>& args) {
    std::vector<std::string> argv{ACO_TEST_ACOSIM, scenario.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto r = test::run(argv);
    CHECK(r.exit_code == 1);
    return r.err;
  };
  CHECK_THAT(error({"--local.folow", "1"}), Contains("did you mean 'local.follow'"));
  CHECK_THAT(error({"--start", "1,1"}), Contains("--start: 'start' is the scenario's, not a run key to change"));
  CHECK_THAT(error({"--preset", "nope"}), Contains("unknown preset 'nope'"));
}

TEST_CASE("the default preset follows the map's kind: voxel worlds get the voxel preset", "[presets][voxel]") {
  CHECK(aco::default_preset("maps/arena.map") == "robust");
  CHECK(aco::default_preset("terrain/epf20.asc.scen") == "terrain");
  CHECK(aco::default_preset("voxel/Simple.3dmap") == "voxel");
  CHECK(aco::default_preset("voxel/Simple.3dmap.3dscen") == "voxel");
  CHECK(aco::default_preset("octomap/hall.bt") == "voxel");
  CHECK(aco::default_preset("octomap/hall.ot") == "voxel");
}
