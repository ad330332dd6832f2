// Named presets (data/presets/NAME.ini): --preset NAME, --list-presets, `preset:` in experiment
// files, each paper's pipeline as the paper experiments run it.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "aco/error.hpp"
#include "aco/presets.hpp"
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
  CHECK(names == std::vector<std::string>{"ant-system", "paper000", "paper001", "paper002", "paper003", "paper004", "robust", "terrain"});
  const auto r = test::acoplan({"--list-presets"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Contains("  paper001  Paper 001's improved colony") && Contains("  robust  The recommended pipeline"));
}

TEST_CASE("acoplan --preset NAME reads the named preset file and mistakes are named", "[presets][acoplan]") {
  const std::string robust = (test::data_dir() / "presets" / "robust.ini").string();
  CHECK(pipeline_of({"--preset", "robust", "--print-config"}) == pipeline_of({"--config", robust, "--print-config"}));
  CHECK(aco::preset_file("paper002") == test::data_dir() / "presets" / "paper002.ini");
  const auto unknown = test::acoplan({"--preset", "paper01"});
  CHECK(unknown.exit_code == 1);
  CHECK_THAT(unknown.err, Contains("unknown preset 'paper01'; did you mean 'paper001'?") && Contains("available: ant-system"));
  CHECK_THAT(test::acoplan({"--preset", "robust", "--config", robust}).err, Contains("--config and --preset: give one of them"));
  // The command line wins over the preset.
  CHECK_THAT(pipeline_of({"--preset", "paper001", "--beta", "3", "--print-config"}), Contains("beta = 3") && Contains("heuristic = direction"));
}

TEST_CASE("each paper's preset is the pipeline its experiment ran before presets were named", "[presets][acobench]") {
  // The improved configurations as the experiment files wrote them key by key (until presets),
  // against `preset: paperNNN` over the same settings: the same resolved run.
  const std::vector<std::pair<std::string, std::string>> papers{
      {"paper001", "{preset: ant-system, ants: 20, iterations: 200, alpha: 1, beta: 1, corner-cutting: true, same-path-stop: true, "
                   "same-path-fraction: 0.9, heuristic: direction, deadlock: backtrack_penalty}"},
      {"paper002", "{preset: ant-system, ants: 50, iterations: 100, alpha: 1, beta: 7, corner-cutting: true, update: gaussian, "
                   "update.psi: 300, update.mu: 0, update.sigma: 1, update.rho: 0.3, update.q: 1, deadlock: clear_and_tabu}"},
      {"paper004", "{preset: ant-system, ants: 50, iterations: 50, corner-cutting: true, alpha: 2, beta: 8, update: ant_system, "
                   "update.rho: 0.9, update.q: 1, init: fireworks, deadlock: backtrack_penalty}"}};
  for (const auto& [preset, keys] : papers) {
    INFO(preset);
    const auto e = load("name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\nbaseline: " + keys +
                        "\nconfigurations:\n  - {name: named, preset: " + preset + "}\n");
    CHECK(aco::to_json(*e.configurations[0].run) == aco::to_json(*e.configurations[1].run));
  }
  CHECK_THROWS_WITH(load("name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\nbaseline: {preset: nope}\n"),
                    Contains("unknown preset 'nope'"));
  CHECK_THROWS_WITH(load("name: p\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
                         "baseline: {preset: robust, config: x.ini}\n"),
                    Contains("'config' and 'preset': give one of them"));
}
