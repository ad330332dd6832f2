// The python plugins (plugins/<slot>/python): Python objects in the native colony, run through
// acoplan and acobench as a user runs them. Built only with ACO_BUILD_PYTHON.
#include <catch2/catch.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include "acobench_support.hpp"
#include "aco/studies/results_db.hpp"
#include "support.hpp"

using Catch::Contains;
using nlohmann::json;

namespace {

const std::string examples = ACO_TEST_PYTHON_EXAMPLES;
const std::string fixtures = ACO_TEST_PYTHON_FIXTURES;

std::string classic_map(int n) {
  return (test::data_dir() / ("maps/classic20/map" + std::to_string(n) + ".txt")).string();
}

std::vector<std::string> problem(int map, int seed) {
  return {"--map", classic_map(map), "--start",           "0,0", "--goal", "19,19", "--ants", "10", "--iterations",
          "15",    "--seed",         std::to_string(seed)};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// --<slot> python with a class from the examples (or the fixtures).
std::vector<std::string> python(const std::string& slot, const std::string& object,
                                const std::string& path = examples) {
  return {"--" + slot, "python", "--" + slot + ".class", object, "--" + slot + ".path", path};
}

// The run's results: its JSON without the times, the configuration and the plugin files.
json results(const std::vector<std::string>& args) {
  const auto r = test::acoplan(with(args, {"--json"}));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  json j = json::parse(r.out);
  for (const char* key : {"time_ms", "convergence_time_s", "config", "plugins"}) j.erase(key);
  return j;
}

// acoplan fails with exit status 1 and a message containing every one of `expected`.
void expect_error(const std::vector<std::string>& args, const std::vector<std::string>& expected) {
  const auto r = test::acoplan(args);
  INFO(r.err);
  CHECK(r.exit_code == 1);
  for (const auto& text : expected) CHECK_THAT(r.err, Contains(text));
}

}  // namespace

TEST_CASE("the Python Ant System gives the runs of update/ant_system bit for bit on every classic map",
          "[python][acoplan]") {
  for (int map = 1; map <= 3; ++map)
    for (int seed : {1, 2}) {
      INFO("map" << map << " seed " << seed);
      const auto native = results(with(problem(map, seed), {"--update", "ant_system"}));
      CHECK(native["solved"] == true);
      CHECK(results(with(problem(map, seed), python("update", "ant_system:AntSystem"))) == native);
      // The classic setting too: discard deadlock, corner cutting, beta 7.
      const auto classic = with(problem(map, seed), {"--preset", "ant-system", "--corner-cutting"});
      CHECK(results(with(classic, python("update", "ant_system:AntSystem"))) ==
            results(with(classic, {"--update", "ant_system"})));
    }
}

TEST_CASE("Python init and heuristic examples give the runs of init/uniform and heuristic/distance",
          "[python][acoplan]") {
  for (int map = 1; map <= 3; ++map) {
    INFO("map" << map);
    const auto native = results(with(problem(map, 3), {"--init", "uniform", "--heuristic", "distance"}));
    const auto args =
        with(with(problem(map, 3), python("init", "uniform:Uniform")), python("heuristic", "distance:Distance"));
    CHECK(results(args) == native);
  }
}

TEST_CASE("python plugins give the same run on 1 and 2 threads", "[python][acoplan][determinism]") {
  auto args = with(problem(2, 4), python("init", "uniform:Uniform"));
  args = with(with(args, python("heuristic", "distance:Distance")), python("update", "ant_system:AntSystem"));
  CHECK(results(with(args, {"--threads", "1"})) == results(with(args, {"--threads", "2"})));
}

TEST_CASE("a python update sees the context and the iteration as the engine has them", "[python][acoplan]") {
  // bridge_fixtures.checks asserts on each call: any failure would end the run with exit 1. Two
  // repeats on one Python object: its begin_run() starts each run afresh (seeds 9 and 10).
  const auto r = test::acoplan({"--map",          classic_map(1),
                                "--start",        "0,0",
                                "--goal",         "19,19",
                                "--ants",         "6",
                                "--iterations",   "4",
                                "--seed",         "9",
                                "--repeat",       "2",
                                "--update",       "python",
                                "--update.class", "bridge_fixtures:checks",
                                "--update.path",  fixtures});
  INFO(r.err);
  CHECK(r.exit_code == 0);
}

TEST_CASE("a python heuristic is called every iteration only when it varies by iteration", "[python][acoplan]") {
  const auto base = problem(1, 1);
  CHECK(test::acoplan(with(base, python("heuristic", "bridge_fixtures:FixedHeuristic", fixtures))).exit_code == 0);
  expect_error(with(base, python("heuristic", "bridge_fixtures:ChangingHeuristic", fixtures)),
               {"plugin heuristic/python (", "in iteration 2 (0-based, as Context::iteration)",
                "RuntimeError: compute() was called in iteration 2"});
}

TEST_CASE("a python hook may return a new array and an object made already is used as it is", "[python][acoplan]") {
  // ReturnsCopy halves tau: the same run whether the class or the module's instance is named.
  const auto from_class = results(with(problem(1, 1), python("update", "bridge_fixtures:ReturnsCopy", fixtures)));
  CHECK(results(with(problem(1, 1), python("update", "bridge_fixtures:instance", fixtures))) == from_class);
  CHECK(from_class != results(with(problem(1, 1), {"--update", "ant_system"})));
  // An attribute of a module that is only in sys.modules (the heuristic's class imported the
  // fixtures, which put it there): no path needed.
  const auto live = with(problem(1, 1), python("heuristic", "bridge_fixtures:FixedHeuristic", fixtures));
  const auto fixed = with(live, python("update", "bridge_fixtures:ReturnsCopy", fixtures));
  CHECK(results(with(live, {"--update", "python", "--update.class", "bridge_live:o17"})) == results(fixed));
}

TEST_CASE("python plugins name the plugin and what is wrong with the object they are given", "[python][bad-input]") {
  const auto base = problem(1, 1);
  const std::string plugin = "plugin update/python (";
  expect_error(with(base, {"--update", "python"}),
               {plugin, "update.class is empty: name the Python object as module:attribute"});
  expect_error(with(base, {"--update", "python", "--update.class", "AntSystem"}),
               {plugin, "update.class 'AntSystem' is not module:attribute"});
  expect_error(
      with(base, python("update", "no_such_module:AntSystem")),
      {plugin,
       "update.class 'no_such_module:AntSystem': no Python module 'no_such_module' (searched sys.path: " + examples});
  expect_error(with(base, python("update", "ant_system:AntSystm")),
               {plugin, "update.class 'ant_system:AntSystm': ant_system (" + examples +
                            "/ant_system.py) has no attribute 'AntSystm'"});
  expect_error(with(base, python("update", "bridge_fixtures:NoUpdate", fixtures)),
               {plugin, "the object has no method update(self, context, iteration, tau)"});
  expect_error(with(base, python("update", "bridge_fixtures:FailsToStart", fixtures)),
               {plugin, "failed in its factory",
                "bridge_fixtures:FailsToStart(), raised RuntimeError: no configuration (at " + fixtures +
                    "/bridge_fixtures.py:"});
  expect_error(with(base, python("init", "bridge_fixtures:NoUpdate.missing", fixtures)),
               {"plugin init/python (", "bridge_fixtures:NoUpdate has no attribute 'missing'"});
}

TEST_CASE("a Python exception ends the run with its type and message and the line that raised it",
          "[python][boundary]") {
  expect_error(
      with(problem(1, 1), python("update", "bridge_fixtures:Raises", fixtures)),
      {"acoplan: error: plugin update/python (", "failed in update() in iteration 0 (0-based, as Context::iteration): ",
       "bridge_fixtures:Raises.update() raised ValueError: deposit went wrong (at " + fixtures + "/bridge_fixtures.py:",
       " in update: raise ValueError(\"deposit went wrong\"))"});
}

TEST_CASE("NaN written by a python update stops the run as the engine's check does for a native one",
          "[python][faults]") {
  expect_error(with(problem(1, 1), python("update", "bridge_fixtures:WritesNan", fixtures)),
               {"acoplan: error: plugin update/python (",
                ") wrote nan to the pheromone of edge (0,0) -> (1,0) in update() in iteration 2 (0-based, as "
                "Context::iteration); "
                "the pheromone must be finite and >= 0\n"});
}

TEST_CASE("a python hook that returns the wrong array is refused with what was expected", "[python][bad-input]") {
  const std::string expected = "; return None (with the array filled in place) or a float64 array of ";
  expect_error(
      with(problem(1, 1), python("update", "bridge_fixtures:WrongLength", fixtures)),
      {"failed in update() in iteration 0", "WrongLength.update() returned an array of shape (3,)" + expected});
  expect_error(with(problem(1, 1), python("update", "bridge_fixtures:WrongDtype", fixtures)),
               {"WrongDtype.update() returned an array of dtype int64" + expected});
  expect_error(with(problem(1, 1), python("update", "bridge_fixtures:ReturnsList", fixtures)),
               {"ReturnsList.update() returned a list" + expected});
}

TEST_CASE("acoplan shows the python plugins' text parameters", "[python][acoplan]") {
  const auto described = test::acoplan({"--describe", "update/python"});
  CHECK(described.exit_code == 0);
  CHECK_THAT(described.out, Contains("class  text  default \"\"") && Contains("path  text  default \"\""));
  const auto help = test::acoplan({"--update", "python", "--help"});
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Contains("--update.class TEXT") && Contains("[text, default \"\"]"));
}

TEST_CASE("acobench runs a python update in its worker processes with the results of the native one",
          "[python][acobench]") {
  std::string text = "name: python-bridge\nseed: 5\nrepetitions: 2\nproblems:\n";
  for (int map = 1; map <= 3; ++map) text += "  - {map: " + classic_map(map) + ", start: [0, 0], goal: [19, 19]}\n";
  text +=
      "settings: {preset: ant-system, ants: 10, iterations: 15}\nbaseline: {name: native, update: ant_system}\n"
      "configurations:\n  - {name: python, update: {plugin: python, class: 'ant_system:AntSystem', path: " +
      examples + "}}\n";
  const auto file = test::acobench_helpers::experiment(text);
  const auto db = file.parent_path() / "python.db";
  const auto r = test::acobench_helpers::run_acobench({"run", file.string(), "--db", db.string(), "--threads", "2"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const aco::studies::ResultsDb stored(db);
  std::map<int, std::string> config_names;
  for (const auto& [id, config] : stored.configs()) config_names[id] = config.name;
  std::map<std::pair<int, int>, std::map<std::string, aco::studies::TrialRecord>> trials;
  for (const auto& t : stored.trials()) trials[{t.problem, t.repetition}][config_names[t.config]] = t;
  REQUIRE(trials.size() == 6);
  for (const auto& [key, by_config] : trials) {
    INFO("problem " << key.first << " repetition " << key.second);
    REQUIRE(by_config.size() == 2);
    const auto& native = by_config.at("native");
    const auto& python = by_config.at("python");
    CHECK(native.error.empty());
    CHECK(python.error.empty());
    CHECK(native.solved);
    CHECK(python.seed == native.seed);
    CHECK(python.length == native.length);
    CHECK(python.path_json == native.path_json);
    CHECK(python.best_so_far == native.best_so_far);
    CHECK(python.ant_steps == native.ant_steps);
  }
}
