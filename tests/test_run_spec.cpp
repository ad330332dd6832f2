// aco::RunSpec: one typed configuration per run, resolved once from keys, written back as keys
// and JSON with the same names.
#include <catch2/catch.hpp>

#include "aco/run_spec.hpp"
#include "aco/settings_table.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

aco::RunSpec resolve(const aco::Keys& keys) { return aco::resolve_run(keys, test::plugins(), "--"); }

std::string key_error(const aco::Keys& keys, std::string* key = nullptr) {
  try {
    resolve(keys);
  } catch (const aco::KeyError& e) {
    if (key) *key = e.key();
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("resolve_run types every key once, and to_keys and JSON give the same run back", "[run_spec]") {
  const aco::Keys keys{{"map", "m.map"},          {"start", "1,2"},         {"goal", "30,4"},
                       {"max-slope", "35"},        {"neighbourhood", "16"},  {"corner-cutting", "true"},
                       {"ants", "20"},             {"search", "bidirectional"}, {"update", "acs"},
                       {"q0", "0.25"},      {"heuristic", "progress"}, {"beta", "0.1234567890123456"}};
  const aco::RunSpec run = resolve(keys);
  CHECK(run.problem.map == "m.map");
  CHECK(run.problem.start == aco::Cell{1, 2});
  CHECK(run.problem.goal == aco::Cell{30, 4});
  CHECK(run.problem.terrain.max_slope_deg == 35.0);
  CHECK(run.graph.neighbourhood == aco::Neighbourhood::sixteen);
  CHECK(run.graph.corner_cutting);
  CHECK(run.colony.ants == 20);
  CHECK(run.colony.bidirectional);
  CHECK(run.colony.beta == 0.1234567890123456);
  CHECK(run.colony.iterations == aco::ColonySettings{}.iterations);  // defaults from the struct
  CHECK(run.pipeline.at("update").plugin == "acs");
  CHECK(run.colony.q0 == 0.25);
  CHECK(run.pipeline.at("update").parameters.real("rho") == 0.3);  // the plugin's default
  CHECK(run.pipeline.at("init").plugin == "uniform");

  const aco::Keys written = aco::to_keys(run);
  CHECK(written.at("q0") == "0.25");
  CHECK(written.at("search") == "bidirectional");
  CHECK(written.at("start") == "1,2");
  CHECK(aco::to_keys(resolve(written)) == written);
  const std::string json = aco::to_json(run);
  CHECK_THAT(json, Contains("\"ants\":20") && Contains("\"q0\":0.25") && Contains("\"corner-cutting\":true"));
  CHECK(aco::to_keys(aco::run_spec_from_json(json, test::plugins())) == written);
}

TEST_CASE("resolve_run names the key of every mistake", "[run_spec][errors]") {
  std::string key;
  CHECK_THAT(key_error({{"antz", "3"}}, &key), Contains("unknown key '--antz'") && Contains("did you mean '--ants'?"));
  CHECK(key == "--antz");
  CHECK_THAT(key_error({{"update", "acs"}, {"update.x1", "0.5"}}, &key), Contains("did you mean '--update.xi'?"));
  CHECK(key == "--update.x1");
  CHECK_THAT(key_error({{"beta", "99"}}, &key), Contains("--beta: 99 is outside the range [0, 50]"));
  CHECK(key == "--beta");
  CHECK_THAT(key_error({{"update", "nope"}}, &key), Contains("--update: ") && Contains("nope"));
  CHECK(key == "--update");
  CHECK_THAT(key_error({{"ifwa.radius", "2"}}), Contains("planner 'ifwa', but the planner is 'aco'"));
  CHECK_THAT(key_error({{"planner", "ifwa"}, {"ifwa.radius", "-2"}}), Contains("--ifwa.radius"));
  CHECK_THAT(key_error({{"scen", "x.scen"}, {"start", "1,1"}}), Contains("either --scen or --start/--goal"));
  CHECK_THAT(key_error({{"scen-index", "3"}}), Contains("--scen-index needs --scen"));
  CHECK_THAT(key_error({{"start", "1;2"}}, &key), Contains("'1;2' is not a cell"));
  CHECK(key == "--start");
  CHECK_THAT(key_error({{"neighbourhood", "6"}}), Contains("is not one of 4,8,16"));
  CHECK(key_error({{"planner", "pso"}, {"pso.particles", "10"}}).empty());
}

TEST_CASE("a settings table reads and writes its struct and takes its defaults from it", "[run_spec]") {
  const auto table = aco::colony_parameters();
  const auto ants = std::find_if(table.begin(), table.end(), [](const auto& p) { return std::string(p.name) == "ants"; });
  REQUIRE(ants != table.end());
  CHECK(std::string(ants->default_value) == std::to_string(aco::ColonySettings{}.ants));
  aco::ColonySettings s;
  s.ants = 7;
  s.walk_limit = 2.5;
  s.local_search = "loops";
  s.bidirectional = true;
  s.seed = 123456789012345;
  const aco::ColonySettings back = aco::colony_settings(aco::colony_values(s));
  CHECK(back.ants == 7);
  CHECK(back.walk_limit == 2.5);
  CHECK(back.local_search == "loops");
  CHECK(back.bidirectional);
  CHECK(back.seed == 123456789012345u);
  CHECK(aco::to_string(aco::colony_values(s).all().at("search")) == "bidirectional");
}

TEST_CASE("load_problem checks start and goal and takes a scenario's cells", "[run_spec][errors]") {
  aco::ProblemSpec p;
  p.map = test::data_dir() / "maps/classic20/map1.txt";
  p.start = aco::Cell{0, 0};
  p.goal = aco::Cell{25, 3};
  CHECK_THROWS_WITH(aco::load_problem(p), Contains("goal (25,3) is outside the 20x20 map"));
  p.goal = aco::Cell{6, 0};
  CHECK_THROWS_WITH(aco::load_problem(p), Contains("goal (6,0) is blocked: an obstacle"));
  aco::ProblemSpec scen;
  scen.scen = test::data_dir() / "maps/movingai/arena.map.scen";
  scen.scen_index = 3;
  const auto loaded = aco::load_problem(scen);
  CHECK(loaded.map->width() == 49);
  scen.scen_index = 100000;
  CHECK_THROWS_WITH(aco::load_problem(scen), Contains("scen-index 100000 is out of range"));
}
