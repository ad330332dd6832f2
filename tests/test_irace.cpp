// Tuning hook-up: acoplan --irace (the cost line), --dump-irace-params (irace's parameter file)
// and tools/irace/target-runner: the file's syntax and that every value irace may sample is one
// acoplan accepts. A real irace run is the test irace_tuning_run (tests/irace_run.sh).
#include <signal.h>
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "aco/engine/colony.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/pipeline.hpp"
#include "support.hpp"

using Catch::Contains;
using Catch::StartsWith;
using nlohmann::json;

namespace {

const std::string map1_scen = (test::data_dir() / "maps/classic20/map1.txt.scen").string();
const std::vector<std::string> quick{"--scen", map1_scen, "--iterations", "20", "--corner-cutting"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> result;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) result.push_back(line);
  return result;
}

// The only line of an --irace run's stdout, as a number.
double irace_cost(const std::vector<std::string>& args) {
  const auto r = test::acoplan(with(args, {"--irace"}));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto out = lines(r.out);
  REQUIRE(out.size() == 1);
  std::size_t used = 0;
  const double cost = std::stod(out[0], &used);
  REQUIRE(used == out[0].size());
  return cost;
}

// One line of irace's parameter file.
struct IraceParameter {
  std::string name, flag, type, domain, condition;
  std::vector<std::string> values() const {
    std::vector<std::string> result;
    std::istringstream in(domain);
    for (std::string v; std::getline(in, v, ',');) result.push_back(v.substr(v.find_first_not_of(' ')));
    return result;
  }
};

// Parses the file, checking every line against irace's syntax and every name for uniqueness.
std::vector<IraceParameter> parse_irace_parameters(const std::string& text) {
  static const std::regex line_syntax(
      R"re(^([A-Za-z][A-Za-z0-9_]*) "(--[A-Za-z0-9_.-]+[ =])" ([icr]) \(([^()]+)\)(?: \| (.+))?$)re");
  std::vector<IraceParameter> parameters;
  std::set<std::string> names;
  for (const auto& line : lines(text)) {
    if (line.empty() || line[0] == '#') continue;
    std::smatch m;
    INFO(line);
    REQUIRE(std::regex_match(line, m, line_syntax));
    CHECK(names.insert(m[1]).second);
    parameters.push_back({m[1], m[2], m[3], m[4], m[5]});
  }
  return parameters;
}

// How irace passes a parameter: switch and value joined, then split at spaces by the shell.
std::vector<std::string> argument(const IraceParameter& p, const std::string& value) {
  if (p.flag.back() == '=') return {p.flag + value};
  return {p.flag.substr(0, p.flag.size() - 1), value};
}

// The plugins irace may choose in a slot: not those with a text parameter (python's class).
std::vector<std::string> tunable(const std::string& slot) {
  std::vector<std::string> names;
  for (const auto& name : test::plugins().names(slot)) {
    const auto params = test::plugins().load(slot, name).parameters();
    if (std::none_of(params.begin(), params.end(), [](const auto& p) { return p.type == aco::ParamType::text; }))
      names.push_back(name);
  }
  return names;
}

const aco::ParamSpec& spec_named(std::span<const aco::ParamSpec> table, const std::string& name) {
  const auto it = std::find_if(table.begin(), table.end(), [&](const auto& s) { return s.name == name; });
  REQUIRE(it != table.end());
  return *it;
}

}  // namespace

TEST_CASE("acoplan --irace prints only the final length, the same as --json's", "[acoplan][irace]") {
  for (const auto& seed : {"1", "2"}) {
    const auto args = with(quick, {"--seed", seed, "--update", "acs", "--smoother", "prune"});
    const auto r = test::acoplan(with(args, {"--json"}));
    REQUIRE(r.exit_code == 0);
    CHECK(irace_cost(args) == json::parse(r.out)["length"].get<double>());
  }
  // --repeat: the mean over the runs.
  const auto repeated = with(quick, {"--repeat", "4"});
  const auto r = test::acoplan(with(repeated, {"--json"}));
  REQUIRE(r.exit_code == 0);
  CHECK(irace_cost(repeated) == Approx(json::parse(r.out)["summary"]["length"]["mean"].get<double>()).epsilon(1e-12));
}

TEST_CASE(
    "acoplan --irace-cost: gap is the grid path's gap to A*, any-angle-gap the final path's to the any-angle optimum",
    "[acoplan][irace]") {
  // A short run that stays above the optimum: two ants, two iterations, no local search.
  const std::vector<std::string> args{
      "--scen",         (test::data_dir() / "maps/movingai/dao/arena2.map.scen").string(),
      "--scen-index",   "900",
      "--ants",         "2",
      "--iterations",   "2",
      "--local-search", "none",
      "--band-search",  "0",
      "--q0",           "0",
      "--seed",         "3"};
  const auto r = test::acoplan(with(args, {"--json"}));
  REQUIRE(r.exit_code == 0);
  const json run = json::parse(r.out);
  const double gap = 100.0 * (run["grid_length"].get<double>() / run["optimal_length"].get<double>() - 1.0);
  REQUIRE(gap > 1.0);
  CHECK(irace_cost(with(args, {"--irace-cost", "gap"})) == Approx(gap).epsilon(1e-12));
  CHECK(irace_cost(with(args, {"--irace-cost", "gap-penalised"})) == Approx(gap * (1.0 + gap)).epsilon(1e-12));
  CHECK(irace_cost(with(args, {"--irace-cost", "length"})) == run["length"].get<double>());
  // The optimum itself costs exactly 0, though its sum may differ from A*'s in the last bits.
  CHECK(irace_cost(with(quick, {"--irace-cost", "gap-penalised"})) == 0.0);
  const auto bad = test::acoplan(with(quick, {"--irace", "--irace-cost", "mean"}));
  CHECK(bad.exit_code == 1);
  CHECK_THAT(
      bad.err,
      Contains("--irace-cost: 'mean' is not one of length,gap,gap-penalised,any-angle-gap,any-angle-gap-penalised"));
  // any-angle-gap(-penalised): the final path's gap to the exact any-angle optimum; here the grid
  // path's, which has 45-degree turns, and then taut's (the default pipeline's smoother), which
  // finds the optimum on this problem.
  const auto grid = with(args, {"--smoother", "none"});
  const json unsmoothed = json::parse(test::acoplan(with(grid, {"--json"})).out);
  const double any_angle_gap =
      100.0 * (unsmoothed["length"].get<double>() / unsmoothed["any_angle_length"].get<double>() - 1.0);
  REQUIRE(any_angle_gap > gap);
  CHECK(irace_cost(with(grid, {"--irace-cost", "any-angle-gap"})) == Approx(any_angle_gap).epsilon(1e-12));
  CHECK(irace_cost(with(grid, {"--irace-cost", "any-angle-gap-penalised"})) ==
        Approx(any_angle_gap * (1.0 + any_angle_gap)).epsilon(1e-12));
  REQUIRE(run["length"].get<double>() == Approx(run["any_angle_length"].get<double>()).epsilon(1e-12));
  CHECK(irace_cost(with(args, {"--irace-cost", "any-angle-gap-penalised"})) == 0.0);
  const auto terrain = test::acoplan({"--map", (test::data_dir() / "terrain/generated/hills40-s101.asc").string(),
                                      "--start", "0,0", "--goal", "39,39", "--ants", "2", "--iterations", "2",
                                      "--irace", "--irace-cost", "any-angle-gap"});
  CHECK(terrain.exit_code == 1);
  CHECK_THAT(terrain.err, Contains("no exact any-angle optimum (2D grid maps only)"));
  // --irace-effort X adds X times the ants' moves per walk over the optimal path's length.
  const double effort = run["ant_steps"].get<double>() / run["convergence_walks"].back().get<double>() /
                        run["optimal_length"].get<double>();
  REQUIRE(effort > 1.0);
  CHECK(irace_cost(with(args, {"--irace-cost", "gap", "--irace-effort", "0.5"})) ==
        Approx(gap + 0.5 * effort).epsilon(1e-12));
  const auto negative = test::acoplan(with(quick, {"--irace", "--irace-effort", "-1"}));
  CHECK(negative.exit_code == 1);
  CHECK_THAT(negative.err, Contains("--irace-effort: -1 is outside the range"));
}

TEST_CASE("acoplan --irace gives an unsolved run the penalty cost and exit status 0 but errors still fail",
          "[acoplan][irace][bad-input]") {
  const auto walled = test::temp_file("walled.txt", "0 1 0\n0 1 0\n0 1 0\n");
  const std::vector<std::string> unsolved{"--map", walled.string(), "--start", "0,0", "--goal", "2,2"};
  CHECK(irace_cost(unsolved) == 1e9);
  CHECK(irace_cost(with(unsolved, {"--repeat", "2"})) == 1e9);
  for (const auto& bad : {std::vector<std::string>{"--irace", "--ants", "0"},
                          {"--irace", "--update", "nope"},
                          {"--irace", "--map", "/nonexistent.map", "--start", "0,0", "--goal", "1,1"}}) {
    const auto r = test::acoplan(bad);
    CHECK(r.exit_code == 1);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Contains("acoplan: error: "));
  }
}

TEST_CASE("acoplan --dump-irace-params lists the colony and every plugin of every slot with conditions",
          "[acoplan][irace]") {
  const auto r = test::acoplan({"--dump-irace-params", "-"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto parameters = parse_irace_parameters(r.out);
  std::map<std::string, IraceParameter> by_name;
  for (const auto& p : parameters) by_name[p.name] = p;

  // The colony's table, without the seed (irace passes its own), the null model (a question
  // asked of a pipeline, not a setting) and the time limit (a budget irace would raise).
  CHECK(by_name.count("seed") == 0);
  CHECK(by_name.count("null_model") == 0);
  CHECK(by_name.count("time_limit") == 0);
  for (const auto& p : parameters) CHECK(p.flag != "--seed ");
  for (const auto& spec : aco::colony_parameters())
    if (std::string(spec.name) != "seed" && std::string(spec.name) != "null-model" &&
        std::string(spec.name) != "time-limit") {
      std::string name = spec.name;
      std::replace(name.begin(), name.end(), '-', '_');
      REQUIRE(by_name.count(name));
      CHECK(by_name[name].condition.empty());
    }
  CHECK(by_name["same_path_stop"].flag == "--same-path-stop=");
  CHECK(by_name["same_path_stop"].domain == "true, false");

  // One categorical per slot with every plugin found, and each plugin's parameters under it;
  // not the local slot, which acoplan does not use (see the next test), nor a plugin with a
  // text parameter, which irace could only run without its text (python without its class).
  CHECK(by_name.count("local") == 0);
  std::size_t plugin_parameters = 0;
  for (const char* slot : aco::kSlots) {
    if (std::string(slot) == "local") continue;
    REQUIRE(by_name.count(slot));
    const auto& choice = by_name[slot];
    CHECK(choice.type == "c");
    CHECK(choice.flag == std::string("--") + slot + " ");
    const auto chosen = choice.values();
    CHECK(chosen == tunable(slot));
    for (const auto& plugin : test::plugins().names(slot))
      if (std::find(chosen.begin(), chosen.end(), plugin) == chosen.end())
        CHECK_THAT(r.out, Contains("# skipped " + std::string(slot) + "/" + plugin + ": its text parameter "));
    for (const auto& plugin : choice.values())
      for (const auto& spec : test::plugins().load(slot, plugin).parameters()) {
        ++plugin_parameters;
        const std::string flag = std::string("--") + slot + "." + spec.name;
        const std::string condition = std::string(slot) + " == \"" + plugin + "\"";
        const auto lines = std::count_if(parameters.begin(), parameters.end(), [&](const auto& p) {
          return p.flag.substr(0, p.flag.size() - 1) == flag && p.condition == condition;
        });
        const bool skipped = r.out.find("# skipped " + flag + ":") != std::string::npos;
        INFO(flag << " | " << condition);
        CHECK(lines + skipped == 1);
      }
  }
  // Parameters several plugins share get their own names.
  CHECK(by_name.count("update_rho_acs"));
  CHECK(by_name.count("update_rho_max_min"));
  CHECK(by_name["update_p_best"].condition == "update == \"max_min\"");
  CHECK(parameters.size() > plugin_parameters);  // one line each, minus the few skipped, plus colony and slots
}

TEST_CASE("acoplan --irace-slots local dumps the parameters of the local planners", "[acoplan][irace]") {
  const auto r = test::acoplan({"--dump-irace-params", "-", "--irace-slots", "local"});
  REQUIRE(r.exit_code == 0);
  std::map<std::string, IraceParameter> by_name;
  for (const auto& p : parse_irace_parameters(r.out)) by_name[p.name] = p;
  REQUIRE(by_name.count("local"));
  CHECK(by_name["local"].values() == test::plugins().names("local"));
  CHECK(by_name["local_heading"].condition == "local == \"dwa\"");
  CHECK(by_name.count("update") == 0);
}

TEST_CASE("every value at the ends of a dumped range is finite and accepted by acoplan", "[acoplan][irace]") {
  const auto r = test::acoplan({"--dump-irace-params", "-"});
  REQUIRE(r.exit_code == 0);
  std::map<std::string, std::string> plugin_of;  // condition -> plugin
  for (const auto& p : parse_irace_parameters(r.out)) {
    INFO(p.name << " " << p.domain);
    const auto values = p.values();
    if (p.type != "c") {
      REQUIRE(values.size() == 2);
      const double low = std::stod(values[0]), high = std::stod(values[1]);
      CHECK(std::isfinite(low));
      CHECK(std::isfinite(high));
      CHECK(low < high);
      if (p.type == "i") CHECK((low == std::floor(low) && high == std::floor(high)));
    }
    // The parameter's own table checks each end (or each choice) as acoplan would.
    const std::string option = p.flag.substr(2, p.flag.size() - 3);
    const auto dot = option.find('.');
    if (dot == std::string::npos && std::find(aco::kSlots.begin(), aco::kSlots.end(), option) != aco::kSlots.end())
      continue;
    std::span<const aco::ParamSpec> table = aco::colony_parameters();
    if (dot != std::string::npos) {
      const std::string slot = option.substr(0, dot);
      const std::string plugin =
          p.condition.substr(p.condition.find('"') + 1, p.condition.rfind('"') - p.condition.find('"') - 1);
      table = test::plugins().load(slot, plugin).parameters();
    }
    const auto& spec = spec_named(table, dot == std::string::npos ? option : option.substr(dot + 1));
    for (const auto& value : values) CHECK_NOTHROW(aco::parse_value(spec, value, option));
  }
  // The rule for open and unbounded ends: (0:1] starts at irace's 0.0001, 0:1e12 stops at 100 x default.
  CHECK_THAT(r.out, Contains("update_rho_max_min \"--update.rho \" r (0.0001, 1) | update == \"max_min\""));
  CHECK_THAT(r.out, Contains("update_p_best \"--update.p_best \" r (0.0001, 0.9999) | update == \"max_min\""));
  CHECK_THAT(r.out, Contains("ants \"--ants \" i (1, 5000)"));
  CHECK_THAT(r.out,
             Contains("# skipped --update.tau_min: range (0:1e12] capped at 100 x default 1e-06 leaves no interval"));
}

TEST_CASE("acoplan runs the lowest value of every dumped parameter, passed as irace passes it", "[acoplan][irace]") {
  const auto parameters = parse_irace_parameters(test::acoplan({"--dump-irace-params", "-"}).out);
  // tools/irace/forbidden.txt forbids b < a and weight_max <= weight_min: those two take their highest.
  const std::set<std::string> highest{"init_b", "init_weight_max"};
  auto value = [&](const IraceParameter& p) { return highest.count(p.name) ? p.values().back() : p.values().front(); };
  std::vector<std::string> colony{"--scen", map1_scen};
  for (const auto& p : parameters)
    if (p.condition.empty() && std::find(aco::kSlots.begin(), aco::kSlots.end(), p.name) == aco::kSlots.end())
      for (const auto& a : argument(p, value(p))) colony.push_back(a);
  // Each plugin with its parameters at their lowest, in the baseline pipeline.
  for (const char* slot : aco::kSlots)
    for (const auto& plugin : tunable(slot)) {
      auto args = with(colony, {std::string("--") + slot, plugin});
      for (const auto& p : parameters)
        if (p.condition == std::string(slot) + " == \"" + plugin + "\"")
          for (const auto& a : argument(p, value(p))) args.push_back(a);
      INFO(slot << " " << plugin);
      irace_cost(args);
    }
}

TEST_CASE("tools/irace/forbidden.txt names parameters of the dumped file", "[acoplan][irace]") {
  std::set<std::string> names;
  for (const auto& p : parse_irace_parameters(test::acoplan({"--dump-irace-params", "-"}).out)) names.insert(p.name);
  std::ifstream in(test::data_dir().parent_path() / "tools/irace/forbidden.txt");
  REQUIRE(in);
  static const std::regex identifier("[A-Za-z][A-Za-z0-9_]*");
  int expressions = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    ++expressions;
    const std::string code = std::regex_replace(line, std::regex("\"[^\"]*\""), "");  // drop quoted values
    for (std::sregex_iterator it(code.begin(), code.end(), identifier), end; it != end; ++it)
      CHECK(names.count(it->str()));
  }
  CHECK(expressions == 5);
}

TEST_CASE("acoplan --irace-slots limits the tuned slots and --dump-irace-params writes files and honours --plugin-dir",
          "[acoplan][irace][bad-input]") {
  const auto only = test::acoplan({"--dump-irace-params", "-", "--irace-slots", "update,init"});
  REQUIRE(only.exit_code == 0);
  std::set<std::string> conditions, names;
  for (const auto& p : parse_irace_parameters(only.out)) {
    names.insert(p.name);
    if (!p.condition.empty()) conditions.insert(p.condition.substr(0, p.condition.find(' ')));
  }
  CHECK(conditions == std::set<std::string>{"init", "update"});
  CHECK(names.count("update"));
  CHECK(names.count("init"));
  CHECK(names.count("heuristic") == 0);
  CHECK(names.count("ants"));

  const auto file = test::temp_file("parameters.txt", "");
  const auto written = test::acoplan({"--dump-irace-params", file.string()});
  CHECK(written.exit_code == 0);
  CHECK(written.out.empty());
  std::ifstream in(file);
  const std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(content == test::acoplan({"--dump-irace-params", "-"}).out);

  // A plugin that cannot be loaded is left out with the reason; the others stay.
  const auto bad = test::acoplan({"--dump-irace-params", "-", "--plugin-dir", ACO_TEST_BAD_PLUGIN_DIR});
  CHECK(bad.exit_code == 0);
  CHECK_THAT(bad.out, Contains("# skipped update/wrong_abi: ") && Contains("ABI 999"));
  CHECK_THAT(bad.out, Contains("update \"--update \" c (acs, ant_system,"));

  // A folder under a file cannot be made, whoever runs the test.
  const std::string unwritable = (test::data_dir() / "maps/classic20/map1.txt/p.txt").string();
  for (const auto& [args, expected] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--dump-irace-params", "-", "--irace-slots", "update,smooth"}, "--irace-slots: 'smooth' is not a slot"},
           {{"--irace-slots", "update"}, "--irace-slots needs --dump-irace-params"},
           {{"--dump-irace-params", unwritable}, unwritable + ": cannot write the irace parameter file: "}}) {
    const auto r = test::acoplan(args);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Contains(expected));
  }
}

TEST_CASE("acoplan --irace-plugin dumps one plugin's parameters with its slot fixed to it",
          "[acoplan][irace][bad-input]") {
  const auto one = test::acoplan({"--dump-irace-params", "-", "--irace-plugin", "update/max_min"});
  REQUIRE(one.exit_code == 0);
  const auto parameters = parse_irace_parameters(one.out);
  REQUIRE(parameters.size() == 7);
  // A choice of one: irace passes --update max_min itself, and nothing is conditional on it.
  CHECK(parameters[0].name == "update");
  CHECK(parameters[0].values() == std::vector<std::string>{"max_min"});
  for (const auto& p : parameters) {
    CHECK(p.condition.empty());
    CHECK_THAT(p.flag, StartsWith("--update"));
  }
  CHECK(parameters[3].name == "update_p_best");
  // A plugin of --plugin-dir's is found, as the target runner's acoplan finds it.
  const auto faulty = test::acoplan(
      {"--dump-irace-params", "-", "--irace-plugin", "update/throwing", "--plugin-dir", ACO_TEST_FAULTY_PLUGIN_DIR});
  CHECK(faulty.exit_code == 0);
  CHECK_THAT(faulty.out, Contains("update \"--update \" c (throwing)\n"));

  for (const auto& [args, expected] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"--irace-plugin", "update/acs"}, "--irace-plugin needs --dump-irace-params"},
           {{"--dump-irace-params", "-", "--irace-plugin", "acs"},
            "--irace-plugin: 'acs' is not SLOT/NAME (e.g. update/acs)"},
           {{"--dump-irace-params", "-", "--irace-plugin", "updat/acs"},
            "--irace-plugin updat/acs: 'updat' is not a slot"},
           {{"--dump-irace-params", "-", "--irace-plugin", "update/nope"}, "unknown update plugin 'nope'"},
           {{"--dump-irace-params", "-", "--irace-plugin", "update/acs", "--irace-slots", "update"},
            "--irace-plugin and --irace-slots: give one of them"},
           {{"--dump-irace-params", "-", "--irace-plugin", "smoother/none"},
            "--irace-plugin smoother/none: no parameter irace can tune"}}) {
    const auto r = test::acoplan(args);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Contains(expected));
  }
}

TEST_CASE("tools/irace/target-runner calls acoplan as irace would and prints the cost last", "[acoplan][irace]") {
  const auto runner = (test::data_dir().parent_path() / "tools/irace/target-runner").string();
  const auto r = test::run(
      {"/bin/bash", runner, "3", "1", "42", map1_scen, "--ants", "20", "--update", "max_min", "--update.rho", "0.2"},
      {std::string("ACOPLAN=") + ACO_TEST_ACOPLAN, "ACOPLAN_OPTIONS=--iterations 20 --corner-cutting"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto direct = test::acoplan({"--scen", map1_scen, "--seed", "42", "--ants", "20", "--update", "max_min",
                                     "--update.rho", "0.2", "--iterations", "20", "--corner-cutting", "--json"});
  REQUIRE(direct.exit_code == 0);
  REQUIRE(!lines(r.out).empty());
  CHECK(std::stod(lines(r.out).back()) == json::parse(direct.out)["length"].get<double>());
}

TEST_CASE("acoplan says which plugin hook SIGUSR1 stopped, however often the signal comes", "[acoplan][contain]") {
  // `timeout -s USR1` sends the signal to acoplan and then to its process group. With the handler
  // installed SA_RESETHAND, a second one that came while the kernel was starting the handler
  // found the default action and ended acoplan before it wrote a byte (the target-runner's log
  // lacked acoplan's line, now and then). Here a burst of them, once the plugin says it hangs;
  // the report must be there every time.
  const auto log = test::temp_file("stopped.log", "");
  const auto read_log = [&] {
    std::ifstream in(log);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  const pid_t pid =
      test::start({ACO_TEST_ACOPLAN, "--scen", map1_scen, "--seed", "7", "--iterations", "20", "--threads", "1",
                   "--update", "hanging", "--update.announce=true", "--plugin-dir", ACO_TEST_HOSTILE_PLUGIN_DIR},
                  log);
  // No time limit of its own: ctest's bounds a plugin that never says it hangs.
  int status = 0;
  while (read_log().find("update/hanging: hanging\n") == std::string::npos) {
    if (::waitpid(pid, &status, WNOHANG) == pid) FAIL("acoplan ended before its plugin hung:\n" << read_log());
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  for (int i = 0; i < 1000; ++i) ::kill(pid, SIGUSR1);
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  const std::string text = read_log();
  INFO(text);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGUSR1);
  CHECK_THAT(text, Contains("\nacoplan: error: stopped: SIGUSR1 in plugin update/hanging (") &&
                       Contains("aco_update_hanging.so) in update() in iteration 3 (0-based, as "
                                "Context::iteration)\n"));
  // Once, however many signals came.
  CHECK(text.find("stopped:") == text.rfind("stopped:"));
}

TEST_CASE("tools/irace/target-runner gives a crashed or timed-out evaluation the failure cost and logs why",
          "[acoplan][irace][contain]") {
  const auto runner = (test::data_dir().parent_path() / "tools/irace/target-runner").string();
  const std::string hostile = ACO_TEST_HOSTILE_PLUGIN_DIR;
  const std::string acoplan = std::string("ACOPLAN=") + ACO_TEST_ACOPLAN;
  const std::string options = "ACOPLAN_OPTIONS=--threads 1 --iterations 20 --corner-cutting";
  const auto log = test::temp_file("failures.log", "");
  const std::string to_log = "ACOPLAN_FAILURE_LOG=" + log.string();
  const auto read_log = [&] {
    std::ifstream in(log);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  // irace reads the runner's stdout and stderr together, every word a number: only the cost.
  const auto check_failure_cost = [](const test::CommandResult& r, double cost) {
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.empty());
    REQUIRE(lines(r.out).size() == 1);
    CHECK(std::stod(r.out) == cost);
  };

  const auto crashed =
      test::run({"/bin/bash", runner, "3", "1", "42", map1_scen, "--update", "crashing", "--plugin-dir", hostile},
                {acoplan, options, to_log});
  check_failure_cost(crashed, 1e10);
  CHECK_THAT(read_log(),
             Contains("configuration 3, instance 1, seed 42: crashed: SIGSEGV (acoplan: error: crashed: SIGSEGV "
                      "in plugin update/crashing (") &&
                 Contains("aco_update_crashing.so) in update() in iteration 3 (0-based, as Context::iteration))\n") &&
                 Contains(" --seed 42 --irace --threads 1 --iterations 20 --corner-cutting --update crashing "));

  // A hang, stopped at ACOPLAN_TIMEOUT: acoplan says where it was. The plugin hangs for good, so
  // the limit only has to outlast acoplan's start on a loaded machine (0.5 s did not, once).
  std::filesystem::remove(log);
  const auto hung =
      test::run({"/bin/bash", runner, "4", "2", "7", map1_scen, "--update", "hanging", "--plugin-dir", hostile},
                {acoplan, options, to_log, "ACOPLAN_TIMEOUT=3", "ACOPLAN_FAILURE_COST=5e9"});
  check_failure_cost(hung, 5e9);
  CHECK_THAT(read_log(),
             StartsWith("configuration 4, instance 2, seed 7: timed out after 3 s (acoplan: error: stopped: "
                        "SIGUSR1 in plugin update/hanging (") &&
                 Contains("aco_update_hanging.so) in update() in iteration 3 (0-based, as Context::iteration))\n  "
                          "timeout -s USR1 -k 2 3 "));

  // By default the log is in the current folder: irace's execution directory.
  const auto dir = log.parent_path() / "exec-dir";
  std::filesystem::create_directories(dir);
  const auto aborted =
      test::run({"/bin/sh", "-c", "cd \"$0\" && exec /bin/bash \"$@\"", dir.string(), runner, "5", "1", "9", map1_scen,
                 "--update", "crashing", "--update.abort=true", "--plugin-dir", hostile},
                {acoplan, options});
  check_failure_cost(aborted, 1e10);
  std::ifstream in(dir / "target-runner-failures.log");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(text,
             StartsWith("configuration 5, instance 1, seed 9: crashed: SIGABRT (acoplan: error: crashed: SIGABRT in "
                        "plugin update/crashing ("));

  // An error is not a failure of the configuration: it stops irace, with acoplan's message.
  std::filesystem::remove(log);
  const auto wrong =
      test::run({"/bin/bash", runner, "6", "1", "1", map1_scen, "--update", "nope"}, {acoplan, options, to_log});
  CHECK(wrong.exit_code == 1);
  CHECK(wrong.out.empty());
  CHECK_THAT(wrong.err, Contains("acoplan: error: unknown update plugin 'nope'"));
  CHECK_FALSE(std::filesystem::exists(log));
  const auto bad_limit =
      test::run({"/bin/bash", runner, "6", "1", "1", map1_scen}, {acoplan, options, to_log, "ACOPLAN_TIMEOUT=soon"});
  CHECK(bad_limit.exit_code != 0);
  CHECK_THAT(bad_limit.err, Contains("invalid time interval"));
  CHECK_FALSE(std::filesystem::exists(log));
}
