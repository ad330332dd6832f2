// Faults named where they happen (issue 29): after every hook that writes what the engine reads,
// the engine checks it and stops with the slot, the plugin and its file, the hook and the
// iteration. The plugins are the fixtures tests/fixtures/bad_value_*.cpp.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "acobench_support.hpp"
#include "aco/studies/results_db.hpp"
#include "support.hpp"

using Catch::Contains;
using Catch::EndsWith;

namespace {

const std::string kFaulty = ACO_TEST_FAULTY_PLUGIN_DIR;
const std::string kIteration = " (0-based, as Context::iteration)";

// The fixture's library: "plugin update/bad_value (DIR/aco_update_bad_value.so)".
std::string plugin(const std::string& slot, const std::string& name) {
  return "plugin " + slot + "/" + name + " (" + kFaulty + "/aco_" + slot + "_" + name + ".so)";
}

std::vector<std::string> map1_run(const std::vector<std::string>& more) {
  std::vector<std::string> args{"--map", (test::data_dir() / "maps/classic20/map1.txt").string(), "--start", "0,0", "--goal",
                                "19,19", "--ants", "10", "--iterations", "6", "--plugin-dir", kFaulty};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// acoplan ends with exit status 1 and exactly this message.
void expect_error(const std::vector<std::string>& args, const std::string& message) {
  const auto r = test::acoplan(map1_run(args));
  INFO(r.err);
  CHECK(r.exit_code == 1);
  CHECK(r.err == "acoplan: error: " + message + "\n");
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

// A fixture's bad value, and the message that must name it.
struct BadValue {
  std::vector<std::string> args;
  std::string slot, value, field, hook;
  int iteration;
};

TEST_CASE("a bad pheromone or heuristic value is named with the plugin, the hook and the iteration that wrote it",
          "[faults][acoplan]") {
  const std::string pheromone = "pheromone", heuristic = "heuristic (eta^beta)";
  const std::vector<BadValue> cases{
      {{"--update", "bad_value"}, "update", "nan", pheromone, "update()", 3},
      {{"--update", "bad_value", "--update.value", "negative", "--update.at_iteration", "0"}, "update", "-1", pheromone, "update()", 0},
      {{"--update", "bad_value", "--update.in_start", "true", "--update.value", "inf"}, "update", "inf", pheromone, "start()", 0},
      {{"--init", "bad_value"}, "init", "nan", pheromone, "initialize()", 0},
      {{"--init", "bad_value", "--init.value", "negative"}, "init", "-1", pheromone, "initialize()", 0},
      {{"--deadlock", "bad_value", "--deadlock.at_iteration", "2"}, "deadlock", "nan", pheromone, "after_iteration()", 2},
      {{"--deadlock", "bad_value", "--deadlock.value", "negative"}, "deadlock", "-1", pheromone, "after_iteration()", 3},
      {{"--heuristic", "bad_value"}, "heuristic", "nan", heuristic, "compute_powered()", 3},
      {{"--heuristic", "bad_value", "--heuristic.at_iteration", "0", "--heuristic.value", "negative"}, "heuristic", "-1", heuristic,
       "compute_powered()", 0},
      {{"--heuristic", "bad_value", "--heuristic.by_node", "true", "--heuristic.value", "inf", "--threads", "1"}, "heuristic", "inf",
       heuristic, "update_node()", 3},
      {{"--heuristic", "bad_value", "--heuristic.by_node", "true", "--threads", "2"}, "heuristic", "nan", heuristic, "update_node()", 3},
  };
  for (const BadValue& c : cases) {
    expect_error(c.args, plugin(c.slot, "bad_value") + " wrote " + c.value + " to the " + c.field + " of edge (0,0) -> (1,0) in " +
                             c.hook + " in iteration " + std::to_string(c.iteration) + kIteration + "; the " + c.field +
                             " must be finite and >= 0");
  }
}

TEST_CASE("NaN written in the run's last iteration fails the run and reaches no output", "[faults][acoplan]") {
  const auto svg = test::temp_file("last.svg", "").parent_path() / "picture.svg";
  const auto r = test::acoplan(map1_run({"--update", "bad_value", "--update.at_iteration", "5", "--json", "--svg", svg.string(),
                                         "--svg-pheromone"}));
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Contains(plugin("update", "bad_value") + " wrote nan to the pheromone") &&
                        Contains("in update() in iteration 5" + kIteration));
  CHECK_THAT(r.out, !Contains("nan"));
  CHECK((!std::filesystem::exists(svg) || read(svg).find("nan") == std::string::npos));
  // Never reached: the same run without the fault.
  const auto healthy = test::acoplan(map1_run({"--update", "bad_value", "--update.at_iteration", "-1", "--svg", svg.string(),
                                               "--svg-pheromone"}));
  CHECK(healthy.exit_code == 0);
  CHECK(read(svg).find("nan") == std::string::npos);
}

TEST_CASE("acobench stores a trial whose plugin writes NaN in its last iteration as failed, with the message",
          "[faults][acobench]") {
  using namespace test::acobench_helpers;
  const auto file = experiment(
      "name: nan\nseed: 3\nrepetitions: 2\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 10, iterations: 5}\nbaseline: {name: AS}\n"
      "configurations:\n  - {name: nan, update: bad_value, update.at_iteration: 4}\n");
  for (const bool in_process : {false, true}) {
    INFO((in_process ? "in process" : "worker processes"));
    const auto db = file.parent_path() / (in_process ? "in-process.db" : "workers.db");
    std::vector<std::string> args{"run", file.string(), "--db", db.string(), "--plugin-dir", kFaulty};
    if (in_process) args.push_back("--in-process");
    const auto r = run_acobench(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.err, Contains("2 trials failed"));
    int failed = 0;
    for (const auto& t : acobench::ResultsDb(db).trials()) {
      if (t.error.empty()) continue;
      ++failed;
      CHECK(t.stopped_by == "error");
      CHECK_FALSE(t.solved);
      CHECK_THAT(t.error, EndsWith(": " + plugin("update", "bad_value") +
                                   " wrote nan to the pheromone of edge (0,0) -> (1,0) in update() in iteration 4" + kIteration +
                                   "; the pheromone must be finite and >= 0"));
    }
    CHECK(failed == 2);
  }
}
