// A plugin's own figures (issue 29): Context::record() and add() in any hook, kept beside the
// planner's properties (PlanOutcome::properties) as "<slot>/<plugin>.<name>" and written by one
// path to acoplan's --json, acobench's database, runs.csv and report. The plugin is the fixture
// tests/fixtures/figures_deadlock.cpp (built unoptimised: the report must warn of it).
#include <catch2/catch.hpp>

#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "acobench_support.hpp"
#include "aco/error.hpp"
#include "aco/figures.hpp"
#include "aco/plugin_call.hpp"
#include "aco/studies/plots.hpp"
#include "aco/studies/results_db.hpp"
#include "support.hpp"

using Catch::Contains;
using Catch::EndsWith;

namespace {

const std::string kFigures = ACO_TEST_FIGURES_PLUGIN_DIR;
const std::string kFixtureFile = kFigures + "/aco_deadlock_figures.so";
const std::string kIteration = " (0-based, as Context::iteration)";

std::vector<std::string> map1_run(const std::vector<std::string>& more) {
  return test::map1_acoplan_args(kFigures, more);
}

nlohmann::json acoplan_json(const std::vector<std::string>& args) {
  const auto r = test::acoplan(map1_run(args));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("Context::record() and add() check the name and the value with or without a sink", "[figures]") {
  aco::Context context;  // as a plugin's own unit test has it: no sink
  context.add("restarts");
  context.record("share", 0.5);
  const std::string rule =
      "a figure's name is lower-case letters, digits and '_', starting with a letter, at most 64 characters";
  CHECK_THROWS_WITH(context.add("Restarts"), "a strategy called Context::add() with the figure name 'Restarts'; " +
                                                 rule + " (as 'restarts' or 'nodes_forbidden')");
  CHECK_THROWS_AS(context.record("", 1.0), aco::PluginFault);
  CHECK_THROWS_AS(context.add(std::string(65, 'a')), aco::PluginFault);
  CHECK_THROWS_WITH(context.record("share", std::numeric_limits<double>::infinity()),
                    "a strategy recorded inf as the figure 'share'; a figure must be finite");

  aco::FigureSink sink;
  context.figures = &sink;
  const aco::PluginIdentity mine{"update", "mine", "/x/aco_update_mine.so"};
  {
    const aco::PluginCallScope scope(mine, "update()", 4);
    context.add("restarts", 2);
    context.add("restarts");
    context.record("share", 0.25);
    context.record("share", 0.75);  // the last value stays
    CHECK_THROWS_WITH(
        context.record("share", std::nan("")),
        "plugin update/mine (/x/aco_update_mine.so) recorded nan as the figure 'share' in update() in iteration 4" +
            kIteration + "; a figure must be finite");
  }
  context.add("unguarded", 5);  // a strategy the registry did not make
  const auto figures = sink.figures();
  CHECK(figures == std::map<std::string, aco::ParamValue>{{"update/mine.restarts", std::int64_t{3}},
                                                          {"update/mine.share", 0.75},
                                                          {"plugin.unguarded", std::int64_t{5}}});
  sink.set_parallel(true);
  const aco::PluginIdentity deadlock{"deadlock", "mine", ""};
  const aco::PluginCallScope scope(deadlock, "on_stuck()", 1);
  CHECK_THROWS_WITH(context.record("at", 1.0),
                    Contains("plugin deadlock/mine called Context::record() for the figure 'at' in "
                             "on_stuck() in iteration 1" +
                             kIteration) &&
                        Contains("count with Context::add()"));
  context.add("stuck");  // counts are fine on construction threads
}

TEST_CASE("a plugin's figures reach acoplan's --json and summary, the same for every thread count",
          "[figures][acoplan]") {
  const auto one = acoplan_json({"--deadlock", "figures", "--threads", "1", "--json"});
  CHECK(one.at("deadlock/figures.last_iteration") == 5.0);  // recorded in after_iteration(): the last iteration's
  const auto stuck = one.at("deadlock/figures.stuck").get<std::int64_t>();
  CHECK(stuck > 0);  // added in on_stuck(), on the construction threads
  for (const char* threads : {"2", "4"}) {
    const auto many = acoplan_json({"--deadlock", "figures", "--threads", threads, "--json"});
    CHECK(many.at("deadlock/figures.stuck") == stuck);
  }
  CHECK(one.at("ant_steps").get<std::int64_t>() > 0);  // the planner's own properties, where they always were
  // Bundled plugins' figures: MAX-MIN's restarts (0 when none), deadlock/backtrack's back-offs.
  const auto bundled =
      acoplan_json({"--update", "max_min", "--update.restart_after", "1", "--deadlock", "backtrack", "--json"});
  CHECK(bundled.at("update/max_min.restarts").get<std::int64_t>() >= 1);
  CHECK(bundled.at("deadlock/backtrack.backoffs").get<std::int64_t>() > 0);
  CHECK(acoplan_json({"--update", "max_min", "--json"}).at("update/max_min.restarts") == 0);

  const auto text = test::acoplan(map1_run({"--deadlock", "figures"}));
  CHECK_THAT(text.out, Contains("figures:  deadlock/figures.last_iteration 5, deadlock/figures.stuck " +
                                std::to_string(stuck) + ", update/max_min.restarts 0\n"));
  const auto runs = test::acoplan(map1_run({"--deadlock", "figures", "--repeat", "3"}));
  CHECK_THAT(runs.out, Contains("  deadlock/figures.stuck mean "));
}

TEST_CASE("a figure's bad name, NaN value or record() on a construction thread stops the run naming the plugin",
          "[figures][acoplan]") {
  const std::string plugin = "plugin deadlock/figures (" + kFixtureFile + ")";
  const auto expect = [&](const std::string& mistake, const std::string& message) {
    const auto r = test::acoplan(map1_run({"--deadlock", "figures", "--deadlock.mistake", mistake}));
    INFO(mistake);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Contains(message));
  };
  expect("nan", "acoplan: error: " + plugin +
                    " recorded nan as the figure 'ratio' in after_iteration() in iteration 2" + kIteration +
                    "; a figure must be finite\n");
  expect("bad_name", "acoplan: error: " + plugin +
                         " called Context::add() with the figure name 'Bad Name' in after_iteration() in "
                         "iteration 0" +
                         kIteration + "; a figure's name is lower-case letters");
  expect("record_on_stuck",
         plugin + " called Context::record() for the figure 'stuck_at' in on_stuck() in iteration 0" + kIteration);
  expect("record_and_add",
         "acoplan: error: " + plugin + " gave the figure 'stuck' to both Context::record() and Context::add()");
}

TEST_CASE("acobench keeps the figures and the planners' properties per trial: database, workers, runs.csv, report",
          "[figures][acobench]") {
  using namespace test::acobench_helpers;
  const auto file = experiment(
      "name: figures\nseed: 5\nrepetitions: 3\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 10, iterations: 6}\nbaseline: {name: AS}\n"
      "configurations:\n  - {name: counted, deadlock: figures}\n  - {name: fireworks, planner: ifwa, ifwa.iterations: "
      "5}\n");
  std::vector<std::filesystem::path> dbs;
  for (const bool in_process : {false, true}) {
    const auto db = file.parent_path() / (in_process ? "in-process.db" : "workers.db");
    std::vector<std::string> args{"run", file.string(), "--db", db.string(), "--plugin-dir", kFigures};
    if (in_process) args.push_back("--in-process");
    const auto r = run_acobench(args);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    dbs.push_back(db);
  }
  // The worker processes send the properties back with the trial: the same rows as in process.
  CHECK(database_rows(dbs[0]) == database_rows(dbs[1]));
  const auto& db = dbs[0];
  const std::string of =
      " FROM properties p JOIN runs r ON r.id = p.runid JOIN plannerConfigs c ON c.id = r.plannerid WHERE ";
  CHECK(sql_value(db, "SELECT count(*)" + of +
                          "c.name = 'counted' AND p.name = 'deadlock/figures.stuck' AND p.value > 0") == "3");
  CHECK(sql_value(db, "SELECT min(p.value)" + of +
                          "c.name = 'counted' AND p.name = 'deadlock/figures.last_iteration'") == "5.0");
  CHECK(sql_value(db, "SELECT count(*)" + of +
                          "c.name = 'fireworks' AND p.name = 'evaluations' AND typeof(p.value) = 'integer' "
                          "AND p.value > 0") == "3");
  CHECK(sql_value(db, "SELECT count(*)" + of + "c.name = 'AS' AND p.name = 'ant_steps' AND p.value = r.ant_steps") ==
        "3");

  const auto out = file.parent_path() / "report";
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  REQUIRE(report.exit_code == 0);
  // runs.csv: a column per property beyond its fixed ones, empty where a run has none.
  std::istringstream csv(read(out / "runs.csv"));
  std::string header, line;
  std::getline(csv, header);
  std::string fixed_columns;
  for (const auto& name : aco::studies::runs_csv_columns()) fixed_columns += (fixed_columns.empty() ? "" : ",") + name;
  CHECK(header == fixed_columns +
                      ",corridors,deadlock/backtrack.backoffs,deadlock/figures.last_iteration,deadlock/figures.stuck,"
                      "evaluations,optimal_corridor_walked,update/max_min.restarts");
  int counted_rows = 0;
  while (std::getline(csv, line)) {
    if (line.find("\"counted\"") == std::string::npos) continue;
    ++counted_rows;
    CHECK_THAT(line, Contains(",,5,"));  // no backoffs (the baseline's robust preset backtracks), last_iteration, stuck
    // No evaluations for the colony; whether its walks took the optimum's corridor; no MAX-MIN restart.
    CHECK_THAT(line, EndsWith(",,0,0") || EndsWith(",,1,0"));
  }
  CHECK(counted_rows == 3);
  // The report: a table of each configuration's figures, the plugins it ran, and a warning of the
  // unoptimised fixture, also on stderr.
  const std::string md = read(out / "report.md");
  CHECK_THAT(md, Contains("## Run properties and plugin figures"));
  CHECK_THAT(md, Contains("| counted | deadlock/figures.stuck | 3 |"));
  CHECK_THAT(md, Contains("| fireworks | evaluations | 3 |"));
  CHECK_THAT(md, Contains("## Plugins"));
  CHECK_THAT(md, Contains("| counted | deadlock | figures | 1.0 | unoptimised | "));
  CHECK_THAT(md, Contains(" | " + kFixtureFile + " |"));
  const std::string warning = "plugin deadlock/figures (" + kFixtureFile +
                              ") is an unoptimised build (configurations 'counted'): their times mean little";
  CHECK_THAT(md, Contains("> **Warning:** " + warning));
  CHECK_THAT(report.err, Contains("acobench: warning: " + warning));
  CHECK_THAT(read(out / "report.html"), Contains("<p class=\"warning\"><strong>Warning:</strong> " + warning));
  // The bundled plugins of this (release) build are optimised: no warning names them.
  CHECK(md.find("plugin update/ant_system") == std::string::npos);
}

TEST_CASE("40 series get 40 distinct colour and line style pairs, the same for a configuration in every chart",
          "[figures][plots]") {
  std::set<std::pair<std::string, std::string>> styles;
  for (std::size_t k = 0; k < aco::studies::kDistinctStyles; ++k)
    styles.emplace(aco::studies::series_style(k).colour, aco::studies::series_style(k).dash);
  CHECK(styles.size() == aco::studies::kDistinctStyles);
  // A chart of 20 series: 20 distinct strokes, each legend entry drawn as its line.
  aco::studies::LineChart chart;
  for (int k = 0; k < 20; ++k) chart.series.push_back({"config " + std::to_string(k), {1.0 + k, 2.0}, {}, {}, {}, {}});
  chart.series[3].style = 17;  // a series keeps the style it is given
  const std::string svg = aco::studies::line_chart_svg(chart);
  std::set<std::string> strokes;
  for (std::size_t at = svg.find("class=\"series\""); at != std::string::npos;
       at = svg.find("class=\"series\"", at + 1)) {
    const auto begin = svg.find("stroke=", at), end = svg.find(" stroke-width", at);
    strokes.insert(svg.substr(begin, end - begin));
  }
  CHECK(strokes.size() == 19);  // series 3 and 17 share style 17
  CHECK_THAT(svg, Contains(aco::studies::stroke_attributes(17) + " stroke-width=\"2\"/><text x=\"") &&
                      Contains(">config 3</text>"));
  CHECK(aco::studies::stroke_attributes(12) == "stroke=\"#2ca02c\" stroke-dasharray=\"7,3\"");
}
