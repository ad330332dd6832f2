// aco::RunSpec: one typed configuration per run, resolved once from keys, written back as keys
// and JSON with the same names.
#include <boost/program_options.hpp>
#include <catch2/catch.hpp>

#include "aco/hosts/program_options_error.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/settings_table.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

aco::RunSpec resolve(const aco::Keys& keys) { return aco::resolve_run(keys, test::plugins(), "--"); }

// The error for a config file with this text, without the file's name, or "no error".
std::string config_error(const std::string& text) {
  const auto file = test::temp_file("run.ini", text).string();
  try {
    aco::read_config_file(file);
  } catch (const aco::Error& e) {
    const std::string message = e.what();
    return message.rfind(file, 0) == 0 ? message.substr(file.size()) : message;
  }
  return "no error";
}

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
  const aco::Keys keys{{"map", "m.map"},
                       {"start", "1,2"},
                       {"goal", "30,4"},
                       {"max-slope", "35"},
                       {"neighbourhood", "16"},
                       {"corner-cutting", "true"},
                       {"ants", "20"},
                       {"search", "bidirectional"},
                       {"update", "acs"},
                       {"q0", "0.25"},
                       {"heuristic", "progress"},
                       {"beta", "0.1234567890123456"}};
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

TEST_CASE("changed_values lists the keys that differ from the defaults of their tables", "[run_spec]") {
  const aco::Keys problem{{"map", "m.map"}, {"start", "1,2"}, {"goal", "30,4"}};
  CHECK(aco::changed_values(resolve(problem), test::plugins()).empty());
  aco::Keys keys = problem;
  keys.insert({{"update", "max_min"},
               {"update.rho", "0.3"},  // ant_system's default, not max_min's (0.1)
               {"update.p_best", "0.05"},  // max_min's default, given
               {"q0", "0.25"},
               {"ants", std::to_string(aco::ColonySettings{}.ants)},
               {"neighbourhood", "16"}});
  std::vector<std::string> changed;
  for (const auto& [key, value] : aco::changed_values(resolve(keys), test::plugins()))
    changed.push_back(key + "=" + aco::to_string(value));
  CHECK(changed == std::vector<std::string>{"neighbourhood=16", "q0=0.25", "update=max_min", "update.rho=0.3"});
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
  CHECK_THAT(key_error({{"neighbourhood", "12"}}), Contains("is not one of 4,8,16,6,18,26"));
  CHECK(key_error({{"planner", "pso"}, {"pso.particles", "10"}}).empty());
}

TEST_CASE("a host's spelling names every key of a mistake as its user writes it", "[run_spec][errors]") {
  const aco::KeySpelling python = aco::KeySpelling::keyword(), yaml;
  CHECK(python("update.rho") == "update_rho");
  CHECK(python.to_give("max-memory") == "max_memory=");
  CHECK(python.within("update.")("tau-min") == "update_tau_min");
  CHECK(yaml.to_give("map-format", "NAME") == "map-format: NAME");
  CHECK(aco::KeySpelling("--").to_give("map-format", "NAME") == "--map-format NAME");
  auto error = [&](const aco::Keys& keys, const aco::KeySpelling& spelling) {
    try {
      aco::resolve_run(keys, test::plugins(), spelling);
    } catch (const aco::KeyError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // Every message of a mistake, in Python's spelling, names no option.
  const std::vector<aco::Keys> mistakes = {{{"antz", "3"}},
                                           {{"update", "acs"}, {"update.x1", "0.5"}},
                                           {{"update", "acs"}, {"update.xi", "2"}},
                                           {{"scen", "x.scen"}, {"start", "1,1"}},
                                           {{"scen-index", "3"}},
                                           {{"map-format", "movingai"}},
                                           {{"same-path-stop", "maybe"}},
                                           {{"ifwa.radius", "2"}}};
  for (const aco::Keys& keys : mistakes) {
    const std::string message = error(keys, python);
    INFO(message);
    CHECK(!message.empty());
    CHECK(message.find("--") == std::string::npos);
    CHECK(message.find('.') == std::string::npos);  // update_xi, not update.xi
  }
  CHECK_THAT(error({{"update", "acs"}, {"update.x1", "0.5"}}, python), Contains("did you mean 'update_xi'?"));
  CHECK_THAT(error({{"scen-index", "3"}}, python), Contains("scen_index needs scen"));
  CHECK_THAT(error({{"scen-index", "3"}}, yaml), Contains("scen-index needs scen"));
}

TEST_CASE("a settings table reads and writes its struct and takes its defaults from it", "[run_spec]") {
  const auto table = aco::colony_parameters();
  const auto ants =
      std::find_if(table.begin(), table.end(), [](const auto& p) { return std::string(p.name) == "ants"; });
  REQUIRE(ants != table.end());
  CHECK(std::string(ants->default_value) == std::to_string(aco::ColonySettings{}.ants));
  aco::ColonySettings s;
  s.ants = 7;
  s.walk_limit = 2.5;
  s.local_search = aco::LocalSearch::loops;
  s.bidirectional = true;
  s.seed = 123456789012345;
  const aco::ColonySettings back = aco::colony_settings(aco::colony_values(s));
  CHECK(back.ants == 7);
  CHECK(back.walk_limit == 2.5);
  CHECK(back.local_search == aco::LocalSearch::loops);
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

TEST_CASE("a config file holds key = value lines, [sections] and comments", "[run_spec]") {
  const auto file = test::temp_file("run.ini",
                                    "# acoplan\nants = 20  # trailing comment\n; a comment line\n\n"
                                    "[update]\n  rho=0.2\r\n[ local. ]\nkey = a = b\nempty =\n");
  CHECK(aco::read_config_file(file.string()) ==
        aco::Keys{{"ants", "20"}, {"update.rho", "0.2"}, {"local.key", "a = b"}, {"local.empty", ""}});
  const auto settings = aco::read_config_settings(file.string());
  REQUIRE(settings.size() == 4);
  CHECK(settings[1].key == "update.rho");
  CHECK(settings[1].line == 6);
  // Text that looks like a Boost.ProgramOptions placeholder is text; resolve_run() judges it.
  CHECK(aco::read_config_file(test::temp_file("p.ini", "%canonical_option% = %value%\n[%x%]\n%% = %\n").string()) ==
        aco::Keys{{"%canonical_option%", "%value%"}, {"%x%.%%", "%"}});
}

// Found by the ini_config fuzz harness: Boost.ProgramOptions' message for the second line never
// came back (its what() replaced "%invalid_line%" with the line, which holds it again, forever).
TEST_CASE("a bad config line is an error naming the file, the line number and the line", "[run_spec][errors]") {
  CHECK(config_error("beta = 0.3\n%invalid_line%x\n") == ":2: '%invalid_line%x' is not a 'key = value' line");
  for (const std::string line : {"%canonical_option%", "%value%", "%prefix_option%", "%option%", "%%", "%", "[update"})
    CHECK(config_error("ants = 3\n\n  " + line + "  # comment\n") == ":3: '" + line + "' is not a 'key = value' line");
  CHECK(config_error("[]\n") == ":1: '[]' names no section");
  CHECK(config_error("= 5\n") == ":1: '= 5' has no key before the '='");
  CHECK(config_error("beta = 1\n[x]\n\nbeta = 2\nbeta = 3\n") == ":5: 'x.beta' is set twice (first on line 4)");
}

// Boost.ProgramOptions' what() never came back on these (aco/hosts/program_options_error.hpp).
TEST_CASE("Boost.ProgramOptions errors are reported with the user's text as typed", "[run_spec][errors]") {
  namespace po = boost::program_options;
  const auto message = [](const std::vector<std::string>& args) {
    po::options_description options;
    options.add_options()("batch", po::value<int>());
    std::vector<const char*> argv{"host"};
    for (const auto& a : args) argv.push_back(a.c_str());
    try {
      po::variables_map vm;
      po::store(po::parse_command_line(static_cast<int>(argv.size()), argv.data(), options), vm);
    } catch (po::error& e) {
      return aco::program_options_message(e);
    }
    return std::string("no error");
  };
  CHECK(message({"--batch", "%value%"}) == "the argument ('%value%') for option '--batch' is invalid");
  CHECK(message({"--batch=%canonical_option%x"}) ==
        "the argument ('%canonical_option%x') for option '--batch' is invalid");
  CHECK(message({"--%canonical_option%"}) == "unrecognised option '--%canonical_option%'");
  CHECK(message({"--batch"}) == "the required argument for option '--batch' is missing");
  // Text naming a placeholder substituted after it was replaced too: this line showed as ''.
  po::invalid_config_file_syntax line("%option%", po::invalid_syntax::unrecognized_line);
  CHECK(aco::program_options_message(line) == "the options configuration file contains an invalid line '%option%'");
  po::error plain("100% fixed text");
  CHECK(aco::program_options_message(plain) == "100% fixed text");
}
