// Faults named where they happen (issue 29): after every hook that writes what the engine reads,
// the engine checks it and stops with the slot, the plugin and its file, the hook and the
// iteration; a smoother's waypoints and a local planner's commands are checked likewise. The
// plugins are the fixtures tests/fixtures/bad_value_*.cpp, bad_smoother.cpp and bad_local.cpp.
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "acobench_support.hpp"
#include "aco/path.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/terrain.hpp"
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
  return test::map1_acoplan_args(kFaulty, more);
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
      {{"--update", "bad_value", "--update.value", "negative", "--update.at_iteration", "0"},
       "update",
       "-1",
       pheromone,
       "update()",
       0},
      {{"--update", "bad_value", "--update.in_start", "true", "--update.value", "inf"},
       "update",
       "inf",
       pheromone,
       "start()",
       0},
      {{"--init", "bad_value"}, "init", "nan", pheromone, "initialize()", 0},
      {{"--init", "bad_value", "--init.value", "negative"}, "init", "-1", pheromone, "initialize()", 0},
      {{"--deadlock", "bad_value", "--deadlock.at_iteration", "2"},
       "deadlock",
       "nan",
       pheromone,
       "after_iteration()",
       2},
      // ACS's update keeps the value for the ants to read; MAX-MIN's deposit on that edge (the
      // default pipeline's) would overwrite it first.
      {{"--deadlock", "bad_value", "--deadlock.value", "negative", "--update", "acs"},
       "deadlock",
       "-1",
       pheromone,
       "after_iteration()",
       3},
      {{"--heuristic", "bad_value"}, "heuristic", "nan", heuristic, "compute_powered()", 3},
      {{"--heuristic", "bad_value", "--heuristic.at_iteration", "0", "--heuristic.value", "negative"},
       "heuristic",
       "-1",
       heuristic,
       "compute_powered()",
       0},
      {{"--heuristic", "bad_value", "--heuristic.by_node", "true", "--heuristic.value", "inf", "--threads", "1"},
       "heuristic",
       "inf",
       heuristic,
       "update_node()",
       3},
      {{"--heuristic", "bad_value", "--heuristic.by_node", "true", "--threads", "2"},
       "heuristic",
       "nan",
       heuristic,
       "update_node()",
       3},
      {{"--heuristic", "bad_value", "--heuristic.by_step", "true", "--heuristic.value", "negative"},
       "heuristic",
       "-1",
       "step factor",
       "step_factors()",
       3},
      {{"--heuristic", "bad_value", "--heuristic.by_step", "true", "--heuristic.value", "inf"},
       "heuristic",
       "inf",
       "step factor",
       "step_factors()",
       3},
  };
  for (const BadValue& c : cases) {
    expect_error(c.args, plugin(c.slot, "bad_value") + " wrote " + c.value + " to the " + c.field +
                             " of edge (0,0) -> (1,0) in " + c.hook + " in iteration " + std::to_string(c.iteration) +
                             kIteration + "; the " + c.field + " must be finite and >= 0");
  }
}

TEST_CASE(
    "a bad pheromone value that a repeat of the run does not make again is blamed on a plugin that is not "
    "deterministic",
    "[faults][acoplan]") {
  // The engine checks the pheromone where the ants read it and at the run's end, and finds the
  // hook that wrote it by repeating the run with a check after every hook.
  const auto not_deterministic = [](const std::string& where, int iteration) {
    return "the pheromone of edge (0,0) -> (1,0) was nan " + where + " in iteration " + std::to_string(iteration) +
           kIteration +
           ", but not when the run was repeated with a check after every hook: the init, update or deadlock plugin is "
           "not "
           "deterministic (aco-plugin-check tells which); it must be finite and >= 0";
  };
  expect_error({"--update", "bad_value", "--update.once", "true"}, not_deterministic("where an ant read it", 4));
  expect_error({"--update", "bad_value", "--update.once", "true", "--update.at_iteration", "5"},
               not_deterministic("at the end of the run", 5));
}

TEST_CASE("NaN written in the run's last iteration fails the run and reaches no output", "[faults][acoplan]") {
  const auto svg = test::temp_file("last.svg", "").parent_path() / "picture.svg";
  const auto r = test::acoplan(map1_run(
      {"--update", "bad_value", "--update.at_iteration", "5", "--json", "--svg", svg.string(), "--svg-pheromone"}));
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Contains(plugin("update", "bad_value") + " wrote nan to the pheromone") &&
                        Contains("in update() in iteration 5" + kIteration));
  CHECK_THAT(r.out, !Contains("nan"));
  CHECK((!std::filesystem::exists(svg) || read(svg).find("nan") == std::string::npos));
  // Never reached: the same run without the fault.
  const auto healthy = test::acoplan(
      map1_run({"--update", "bad_value", "--update.at_iteration", "-1", "--svg", svg.string(), "--svg-pheromone"}));
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
    REQUIRE(r.exit_code == 3);
    CHECK_THAT(r.err, Contains("2 of 4 trials failed") && Contains("a plugin wrote an invalid value: 2"));
    int failed = 0;
    for (const auto& t : aco::studies::ResultsDb(db).trials()) {
      if (t.error.empty()) continue;
      ++failed;
      CHECK(t.stopped_by == "error");
      CHECK_FALSE(t.solved);
      CHECK_THAT(t.error, EndsWith(": " + plugin("update", "bad_value") +
                                   " wrote nan to the pheromone of edge (0,0) -> (1,0) in update() in iteration 4" +
                                   kIteration + "; the pheromone must be finite and >= 0"));
    }
    CHECK(failed == 2);
  }
}

TEST_CASE("a smoother's waypoints must be finite, on free cells, from the start to the goal", "[faults][acoplan]") {
  const std::string bad = plugin("smoother", "bad") + " returned bad waypoints in smooth(): ";
  const std::string rule = " (waypoints must be finite and on free cells, from the start's position to the goal's)";
  // map1's first blocked cell is (6,0).
  expect_error({"--smoother", "bad"}, bad + "waypoint 1 (0-based) of 37, (6, 0, 0), lies on no free cell" + rule);
  const auto dropped = test::acoplan(map1_run({"--smoother", "bad", "--smoother.fault", "drop_goal"}));
  CHECK(dropped.exit_code == 1);
  CHECK_THAT(dropped.err,
             Contains(bad + "the last waypoint, (") && Contains("is not the goal (19,19) at (19, 19, 0)" + rule));
  const auto nan = test::acoplan(map1_run({"--smoother", "bad", "--smoother.fault", "nan"}));
  CHECK(nan.exit_code == 1);
  CHECK_THAT(nan.err, Contains(bad + "waypoint ") && Contains(", nan, 0), is not finite" + rule));
}

TEST_CASE("a waypoint is on a free cell when a free cell's closed square holds it", "[faults][path]") {
  // . # .
  // . . #
  const auto map = test::grid({".#.", "..#"});
  const aco::Graph graph = aco::build_graph(map, {});
  const auto on = [&](double x, double y) { return aco::on_free_cell(graph, {x, y, 0.0}); };
  CHECK(on(0, 0));
  CHECK_FALSE(on(1, 0));
  CHECK_FALSE(on(1.2, -0.3));
  CHECK(on(0.5, 0));  // the border of a free and a blocked cell
  CHECK(on(1.5, 0.5));  // the corner of two blocked and two free cells
  CHECK_FALSE(on(2, 1));
  CHECK(on(2, 0.5));  // between the free (2,0) and the blocked (2,1)
  CHECK_FALSE(on(-0.6, 0));  // outside the map
  CHECK_FALSE(on(3.5, 1.5));
  // On terrain, positions are in the cell size's units.
  const aco::TerrainMap terrain(3, 1, 10.0, {1, 1, 1}, 90, "flat");
  const aco::Graph ground = aco::build_graph(terrain, {});
  CHECK(aco::on_free_cell(ground, ground.position(2)));
  CHECK(aco::on_free_cell(ground, {25, 5, 1}));
  CHECK_FALSE(aco::on_free_cell(ground, {25, 5.1, 1}));
}

TEST_CASE("acosim stops on a local planner's NaN command or one far outside the dynamic window", "[faults][acosim]") {
  const auto scenario = [](const std::string& fault) {
    const auto file = test::temp_file("bad_local.yaml",
                                      "run: {map: open.txt, start: [0, 2], goal: [11, 2], local: bad, "
                                      "local.fault: " +
                                          fault + "}\n");
    std::ofstream open(file.parent_path() / "open.txt");
    for (int y = 0; y < 5; ++y) open << "0 0 0 0 0 0 0 0 0 0 0 0\n";
    return file.string();
  };
  const std::string window =
      ", outside the dynamic window v in [0, 0.02], w in [-0.0872665, 0.0872665] "
      "(a command must be finite and inside it)\n";
  for (const auto& [fault, command] : {std::pair{"nan", "v = nan, w = 0"}, std::pair{"outside", "v = 15, w = 0"}}) {
    INFO(fault);
    const auto r = test::run({ACO_TEST_ACOSIM, scenario(fault), "--plugin-dir", kFaulty, "--json"});
    CHECK(r.exit_code == 1);
    CHECK(r.out.empty());
    CHECK(r.err == "acosim: error: " + plugin("local", "bad") + " returned the command " + command +
                       " in command() at control step 3 (0-based, t = 0.3 s)" + window);
  }
}
