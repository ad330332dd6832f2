// The 'ompl' planner (baselines/ompl): OMPL's sampling planners in the plane over the map. Built
// and registered only where OMPL is installed. Their runs are bounded by wall-clock time, so the
// tests assert only what holds on any machine under any load: a path, when found, is valid and no
// shorter than the straight line; every planner finds one within generous budgets (tried again
// with a larger one, as a loaded machine may leave a short budget too short).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acobench_support.hpp"
#include "aco/error.hpp"
#include "aco/planning/planning.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/terrain.hpp"
#include "ompl/ompl_planner.hpp"
#include "support.hpp"

namespace {

using Catch::Contains;

aco::OmplSettings settings(const std::string& planner, double time_limit, std::uint64_t seed = 1) {
  aco::OmplSettings s = aco::ompl_settings(aco::resolve(aco::ompl_parameters(), {{"planner", planner}}, "ompl."));
  s.time_limit = time_limit;
  s.seed = seed;
  return s;
}

// What every solved run must satisfy, whatever the machine.
void check_path(const aco::Graph& g, aco::NodeId start, aco::NodeId goal, const aco::OmplResult& r) {
  REQUIRE(r.solved);
  REQUIRE(r.path.size() >= 2);
  CHECK(r.path.front() == g.position(start));
  CHECK(r.path.back() == g.position(goal));
  for (std::size_t i = 1; i < r.path.size(); ++i) {
    INFO("segment " << i << " of " << r.path.size() - 1);
    CHECK(r.path[i].z() == 0.0);
    CHECK(aco::segment_free(*g.map, r.path[i - 1].head<2>(), r.path[i].head<2>(), g.options.corner_cutting));
  }
  CHECK(r.length == aco::polyline_length(r.path));
  CHECK(r.length >= (g.position(goal) - g.position(start)).norm() - 1e-9);
  // The anytime curve: one entry per reported solution, the final path's length last.
  REQUIRE(!r.best_so_far.empty());
  CHECK(r.best_so_far.back() == r.length);
  CHECK(r.elapsed_s.size() == r.best_so_far.size());
  CHECK(r.walks.size() == r.best_so_far.size());
  for (std::size_t i = 1; i < r.elapsed_s.size(); ++i) {
    CHECK(r.elapsed_s[i] >= r.elapsed_s[i - 1]);
    CHECK(r.walks[i] > r.walks[i - 1]);
  }
  CHECK(r.graph_states > 0);
  CHECK(r.status == "Exact solution");
}

// A budget of `first` seconds, then 4 and 16 times it until solved.
aco::OmplResult solve(const aco::Graph& g, aco::Cell start, aco::Cell goal, aco::OmplSettings s, double first) {
  aco::OmplResult r;
  for (double budget : {first, 4 * first, 16 * first}) {
    s.time_limit = budget;
    r = aco::run_ompl(g, g.node(start), g.node(goal), s);
    if (r.solved) break;
    WARN(s.planner << " found no path in " << budget << " s (" << r.status << "); trying a larger budget");
  }
  return r;
}

const char* const kPlanners[] = {"rrtconnect", "rrtstar", "informedrrtstar", "bitstar", "prmstar", "aitstar"};

}  // namespace

TEST_CASE("ompl: every planner finds a valid path on a classic map", "[ompl][slow]") {
  const auto map = test::classic_map(3);
  for (bool cc : {false, true}) {
    const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, cc});
    for (const char* planner : kPlanners) {
      INFO(planner << ", corner cutting " << cc);
      const auto r = solve(g, {0, 0}, {19, 19}, settings(planner, 0.5), 0.5);
      check_path(g, g.node({0, 0}), g.node({19, 19}), r);
      if (!cc) continue;
      // Without simplification the planner's own path, just as valid.
      aco::OmplSettings raw = settings(planner, 0.5, 2);
      raw.simplify = false;
      const auto unsimplified = solve(g, {0, 0}, {19, 19}, raw, 0.5);
      check_path(g, g.node({0, 0}), g.node({19, 19}), unsimplified);
      CHECK(unsimplified.simplification_time_s == 0.0);
    }
  }
}

TEST_CASE("ompl: an open map, start at the goal, bad settings and maps", "[ompl]") {
  const auto open = test::grid(std::vector<std::string>(8, std::string(12, '.')));
  const aco::Graph g = aco::build_graph(open, {aco::Neighbourhood::eight, false});
  // On an open map the simplified path of RRT-Connect is the straight line.
  const auto r = solve(g, {0, 7}, {11, 0}, settings("rrtconnect", 1.0), 1.0);
  check_path(g, g.node({0, 7}), g.node({11, 0}), r);
  CHECK(r.length == Approx((g.position(g.node({11, 0})) - g.position(g.node({0, 7}))).norm()));
  const auto here = aco::run_ompl(g, g.node({3, 3}), g.node({3, 3}), settings("bitstar", 1.0));
  CHECK(here.solved);
  CHECK(here.length == 0.0);
  CHECK(here.path.size() == 1u);

  const auto table = aco::ompl_parameters();
  CHECK_THROWS_WITH(aco::resolve(table, {{"planner", "rrt"}}, "--ompl."), Contains("--ompl.planner"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"time_limit", "0"}}, "--ompl."), Contains("--ompl.time_limit"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"time_limit", "nan"}}, "--ompl."), Contains("not a finite number"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"range", "-1"}}, "--ompl."), Contains("--ompl.range"));
  CHECK_THROWS_WITH(aco::ompl_settings(aco::resolve(table, {{"planner", "prmstar"}, {"range", "2"}}, "ompl.")),
                    Contains("ompl.range applies to"));
  CHECK_NOTHROW(aco::ompl_settings(aco::resolve(table, {{"planner", "rrtstar"}, {"range", "2"}}, "ompl.")));
  aco::OmplSettings bad = settings("rrtconnect", 1.0);
  bad.time_limit = 0.0;
  CHECK_THROWS_AS(aco::run_ompl(g, g.node({0, 0}), g.node({1, 1}), bad), aco::Error);

  const auto walled = test::grid({"..#..", "..#..", "..#.."});
  const aco::Graph w = aco::build_graph(walled, {aco::Neighbourhood::eight, false});
  CHECK_THROWS_WITH(aco::run_ompl(w, w.node({2, 0}), w.node({0, 0}), settings("rrtconnect", 1.0)),
                    Contains("ompl: start (2,0) is a blocked cell"));
  // Unreachable: no exact solution, unsolved with a reason (plan() does not even call it).
  const auto cut = aco::run_ompl(w, w.node({0, 0}), w.node({4, 2}), settings("rrtconnect", 0.05));
  CHECK_FALSE(cut.solved);
  CHECK_THAT(cut.reason, Contains("no exact solution"));
  CHECK(cut.path.empty());

  // A terrain's cells are not the plane's unit squares.
  const aco::TerrainMap terrain(4, 4, 2.0, std::vector<double>(16, 1.0), 30.0, "flat4");
  const aco::Graph t = aco::build_graph(terrain, {aco::Neighbourhood::eight, false});
  CHECK_THROWS_WITH(aco::run_ompl(t, t.node({0, 0}), t.node({3, 3}), settings("rrtconnect", 1.0)),
                    Contains("plans in the plane"));
}

TEST_CASE("ompl: plan() takes the continuous path as it is", "[ompl]") {
  const auto map = test::classic_map(1);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  aco::RunSpec run = aco::resolve_run(
      {{"planner", "ompl"}, {"ompl.planner", "rrtconnect"}, {"ompl.time_limit", "10"}, {"seed", "4"}}, test::plugins());
  const aco::PlanOutcome o = aco::plan(test::plugins(), g, g.node({0, 0}), g.node({19, 19}), run);
  REQUIRE(o.solved());
  CHECK(o.search.path.empty());
  CHECK(std::isnan(o.search.length));
  CHECK(o.length == aco::polyline_length(o.path));
  CHECK(o.path.front() == g.position(g.node({0, 0})));
  CHECK(o.path.back() == g.position(g.node({19, 19})));
  CHECK(o.search.iterations == static_cast<int>(o.search.best_so_far.size()));
  CHECK(o.search.best_so_far[o.search.best_iteration - 1] == o.length);
  CHECK(o.count("ompl.graph_states") > 0);
  CHECK(o.text("ompl.status") == "Exact solution");
  // RRT-Connect stops at its first solution, so with the process-global seed set again it draws the
  // same samples and finds the same path (unless the time limit stopped it, far beyond its need).
  CHECK(aco::plan(test::plugins(), g, g.node({0, 0}), g.node({19, 19}), run).path == o.path);
  // A smoother has nothing to smooth: refused when the run is resolved.
  CHECK_THROWS_WITH(aco::resolve_run({{"planner", "ompl"}, {"smoother", "prune"}}, test::plugins()),
                    Contains("takes no smoother"));
}

TEST_CASE("acoplan --planner ompl on a Moving AI scenario", "[ompl][acoplan]") {
  const std::string scen = (test::data_dir() / "maps/movingai/arena.map.scen").string();
  const std::vector<std::string> base = {"--scen",         scen,      "--scen-index",     "100", "--planner", "ompl",
                                         "--ompl.planner", "bitstar", "--ompl.time_limit"};
  auto args = base;
  args.insert(args.end(), {"0.3", "--json"});
  const auto r = test::acoplan(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("config").at("planner") == "ompl");
  CHECK(j.at("config").at("ompl.planner") == "bitstar");
  if (j.at("solved").get<bool>()) {  // 0.3 s is plenty for BIT* on this map, but not a promise
    CHECK(j.at("grid_path").empty());
    CHECK(j.at("grid_length").is_null());
    CHECK(j.at("path").size() >= 2u);
    const auto start = j.at("start"), goal = j.at("goal");
    CHECK(j.at("path").front() == nlohmann::json::array({start[0].get<double>(), start[1].get<double>()}));
    CHECK(j.at("length").get<double>() >=
          std::hypot(goal[0].get<double>() - start[0].get<double>(), goal[1].get<double>() - start[1].get<double>()));
    CHECK(j.at("ompl.graph_states").get<int>() > 0);
  } else {
    CHECK_THAT(j.at("reason").get<std::string>(), Contains("no exact solution"));
  }

  args = base;
  args.insert(args.end(), {"0.3", "--repeat", "2"});
  const auto summary = test::acoplan(args);
  INFO(summary.err);
  CHECK(summary.exit_code == 0);
  CHECK_THAT(summary.out, Contains("planner:  ompl (a continuous path: no grid path, no smoother)"));
  args = base;
  args.insert(args.end(), {"0.3", "--svg", (std::filesystem::temp_directory_path() / "aco-ompl-test.svg").string()});
  CHECK(test::acoplan(args).exit_code == 0);

  for (const auto& [key, value, message] :
       {std::tuple{"--ompl.planner", "rrt", "--ompl.planner: 'rrt' is not one of"},
        std::tuple{"--ompl.time_limit", "0", "--ompl.time_limit: 0 is outside the range"},
        std::tuple{"--ompl.time_limit", "nan", "--ompl.time_limit: 'nan' is not a finite number"},
        std::tuple{"--smoother", "prune", "takes no smoother"}}) {
    const auto bad = test::acoplan({"--scen", scen, "--scen-index", "100", "--planner", "ompl", key, value});
    INFO(key << " " << value);
    CHECK(bad.exit_code == 1);
    CHECK_THAT(bad.err, Contains(message));
  }
}

TEST_CASE("acobench runs the ompl planner: its runs rows, no grid length, no gap", "[ompl][acobench]") {
  using namespace test::acobench_helpers;
  const auto file = experiment(
      "name: ompl\nseed: 3\nrepetitions: 2\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 10, iterations: 5}\nbaseline: {name: AS}\n"
      "configurations:\n  - {name: RRT-Connect, planner: ompl, ompl.planner: rrtconnect, ompl.time_limit: 10}\n");
  const auto db = file.parent_path() / "ompl.db";
  const auto r = run_acobench({"run", file.string(), "--db", db.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  sqlite3* handle = nullptr;
  REQUIRE(sqlite3_open_v2(db.string().c_str(), &handle, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  REQUIRE(
      sqlite3_prepare_v2(handle,
                         "SELECT r.solved, r.time, r.solution_length, r.grid_length IS NULL, r.gap IS NULL, t.path "
                         "FROM runs r JOIN plannerConfigs c ON c.id = r.plannerid JOIN run_texts t ON t.runid = r.id "
                         "WHERE c.name = 'RRT-Connect'",
                         -1, &stmt, nullptr) == SQLITE_OK);
  int rows = 0;
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    ++rows;
    CHECK(sqlite3_column_int(stmt, 0) == 1);  // 10 s is far beyond what RRT-Connect needs here
    CHECK(sqlite3_column_double(stmt, 1) > 0.0);
    CHECK(sqlite3_column_double(stmt, 2) >= std::hypot(19.0, 19.0));
    CHECK(sqlite3_column_int(stmt, 3) == 1);
    CHECK(sqlite3_column_int(stmt, 4) == 1);
    const auto path = nlohmann::json::parse(reinterpret_cast<const char*>(sqlite3_column_text(stmt, 5)));
    CHECK(path.size() >= 2u);
  }
  sqlite3_finalize(stmt);
  sqlite3_close(handle);
  CHECK(rows == 2);
  // The report reads them back: no gap for them (not -100 %, their grid length being NULL).
  const auto out = file.parent_path() / "report";
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  INFO(report.err);
  REQUIRE(report.exit_code == 0);
  std::ifstream md(out / "report.md");
  std::string line;
  int rrt_rows = 0;
  while (std::getline(md, line))
    if (line.rfind("| RRT-Connect | 2 | 100 % |", 0) == 0) {
      ++rrt_rows;
      CHECK_THAT(line, !Contains("-100.00"));
    }
  CHECK(rrt_rows == 1);
}

namespace {

// The equal-time experiment: a colony (the baseline) and RRT-Connect given its time, on two
// problem sets; `repetitions` and `colony_keys` vary.
std::string equal_time_text(int repetitions, const std::string& colony_keys, bool tied) {
  return "name: equal-time\nseed: 5\nrepetitions: " + std::to_string(repetitions) +
         "\nproblems:\n"
         "  - {map: " +
         test::acobench_helpers::map1() +
         ", start: [0, 0], goal: [19, 19], name: 'corner#1'}\n"
         "  - {map: " +
         test::acobench_helpers::map1() +
         ", start: [0, 19], goal: [19, 0], name: 'other#1'}\n"
         "settings: {ants: 10, iterations: 10}\nbaseline: {name: colony" +
         colony_keys + "}\n" +
         (tied ? "configurations:\n  - {name: RRT-Connect, planner: ompl, ompl.planner: rrtconnect, time-limit-from: "
                 "colony}\n"
               : "");
}

// Each pair's rows of the table "Same time, who is shorter" in report.md, as cells.
std::vector<std::vector<std::string>> equal_time_rows(const std::filesystem::path& report_md) {
  std::ifstream md(report_md);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(md, line);) {
    if (line.rfind("| colony | RRT-Connect |", 0) != 0) continue;
    std::vector<std::string> cells;
    std::istringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) cells.push_back(cell.substr(1, cell.size() - 2));
    rows.push_back(cells);
  }
  return rows;
}

// Checks that each RRT-Connect trial was stored after the colony's trial of its problem and
// repetition, with the colony's time as its time limit; returns how many pairs it checked.
int checked_pairs(const std::filesystem::path& db) {
  sqlite3* handle = nullptr;
  REQUIRE(sqlite3_open_v2(db.string().c_str(), &handle, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  REQUIRE(sqlite3_prepare_v2(handle,
                             "SELECT o.id, c.id, p.value, c.time FROM runs o "
                             "JOIN plannerConfigs oc ON oc.id = o.plannerid AND oc.name = 'RRT-Connect' "
                             "JOIN runs c ON c.experimentid = o.experimentid AND c.repetition = o.repetition "
                             "JOIN plannerConfigs cc ON cc.id = c.plannerid AND cc.name = 'colony' "
                             "LEFT JOIN properties p ON p.runid = o.id AND p.name = 'time_limit'",
                             -1, &stmt, nullptr) == SQLITE_OK);
  int pairs = 0;
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    ++pairs;
    CHECK(sqlite3_column_int(stmt, 0) > sqlite3_column_int(stmt, 1));  // stored after its colony trial
    REQUIRE(sqlite3_column_type(stmt, 2) == SQLITE_FLOAT);
    CHECK(sqlite3_column_double(stmt, 2) == sqlite3_column_double(stmt, 3));  // exactly the colony's time
  }
  sqlite3_finalize(stmt);
  sqlite3_close(handle);
  return pairs;
}

int cell(const std::vector<std::string>& row, std::size_t column) { return std::stoi(row.at(column)); }

}  // namespace

TEST_CASE("acobench: time-limit-from gives OMPL the colony's time, trial by trial, and the report pairs them",
          "[ompl][acobench][equal-time]") {
  using namespace test::acobench_helpers;
  // First the colony alone, then OMPL added with one more repetition: its limits come from
  // trials stored by the earlier run and from trials of this one.
  const auto file = test::temp_file("equal-time.yaml", equal_time_text(2, "", false));
  const auto db = file.parent_path() / "equal-time.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", db.string()}).exit_code == 0);
  std::ofstream(file) << equal_time_text(3, "", true);
  const auto r = run_acobench({"run", file.string(), "--db", db.string(), "--threads", "2"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);

  CHECK(checked_pairs(db) == 6);

  const auto out = file.parent_path() / "report";
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  INFO(report.err);
  REQUIRE(report.exit_code == 0);
  CHECK_THAT(file_bytes(out / "report.md"), Contains("## Same time, who is shorter"));
  const auto rows = equal_time_rows(out / "report.md");
  REQUIRE(rows.size() == 3);  // corner, other, all
  CHECK(rows[0][2] == "corner");
  CHECK(rows[1][2] == "other");
  CHECK(rows[2][2] == "all");
  for (const auto& row : rows) {
    INFO(row[2]);
    const int n = row[2] == "all" ? 6 : 3;
    CHECK(cell(row, 3) == n);  // pairs
    CHECK(cell(row, 4) == n);  // equal time
    CHECK(cell(row, 5) + cell(row, 6) + cell(row, 7) + cell(row, 8) == n);
    CHECK(cell(row, 9) + cell(row, 10) + cell(row, 11) == cell(row, 5));
  }
  for (std::size_t column = 3; column <= 11; ++column)
    CHECK(cell(rows[0], column) + cell(rows[1], column) == cell(rows[2], column));
}

TEST_CASE("acobench: a colony trial that fails leaves its time-limit-from trial stored as failed, not run",
          "[ompl][acobench][equal-time][failures]") {
  using namespace test::acobench_helpers;
  const auto file =
      test::temp_file("equal-time.yaml", equal_time_text(2, ", update: throwing, update.at_iteration: 2", true));
  const auto db = file.parent_path() / "equal-time.db";
  const auto r = run_acobench({"run", file.string(), "--db", db.string(), "--plugin-dir", ACO_TEST_FAULTY_PLUGIN_DIR});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 3);
  CHECK_THAT(r.err, Contains("other error: 4\n    'RRT-Connect': 4, e.g. problem 'corner#1', repetition 0: not run: "
                             "its time limit (time-limit-from) is the time of 'colony' on the same problem and "
                             "repetition, and that trial failed: configuration 'colony'"));
  int failed = 0;
  for (const auto& t : aco::studies::ResultsDb(db).trials()) {
    CHECK_FALSE(t.error.empty());
    CHECK_FALSE(t.solved);
    ++failed;
  }
  CHECK(failed == 8);
  const auto out = file.parent_path() / "report";
  REQUIRE(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
  const auto rows = equal_time_rows(out / "report.md");
  REQUIRE(rows.size() == 3);
  CHECK(cell(rows[2], 3) == 4);  // pairs
  CHECK(cell(rows[2], 4) == 0);  // none had the colony's time: there was none
  CHECK(cell(rows[2], 8) == 4);  // neither solved
}

TEST_CASE("acobench: time-limit-from errors name the key and what is missing", "[ompl][acobench][equal-time]") {
  using namespace test::acobench_helpers;
  const std::string head = "name: e\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n";
  CHECK_THROWS_WITH(load(head + "baseline: {name: A*, planner: astar}\nconfigurations:\n"
                                "  - {name: RRT*, planner: ompl, time-limit-from: colony}\n"),
                    Contains("experiment.yaml:6: configuration 'RRT*': time-limit-from: colony: the experiment has "
                             "no colony configuration (planner: aco)"));
  CHECK_THROWS_WITH(load(head + "baseline: {name: A*, planner: astar}\nconfigurations:\n"
                                "  - {name: c1, planner: aco}\n  - {name: c2, planner: aco, beta: 2}\n"
                                "  - {name: RRT*, planner: ompl, time-limit-from: colony}\n"),
                    Contains("time-limit-from: colony: the experiment has 2 colony configurations ('c1', 'c2'): name "
                             "one"));
  CHECK_THROWS_WITH(load(head + "configurations:\n  - {name: RRT*, planner: ompl, time-limit-from: nobody}\n"),
                    Contains("configuration 'RRT*': time-limit-from: 'nobody' is not a configuration of this file"));
  CHECK_THROWS_WITH(load(head + "configurations:\n  - {name: c1, planner: aco, time-limit-from: baseline}\n"),
                    Contains("time-limit-from: only an OMPL configuration (planner: ompl)"));
  CHECK_THROWS_WITH(load(head + "settings: {time-limit-from: colony}\n"),
                    Contains("time-limit-from belongs to an OMPL configuration under 'configurations'"));
  // Another shard may run the colony's trial: refused, not waited for.
  const auto file = experiment(head + "configurations:\n  - {name: RRT*, planner: ompl, time-limit-from: colony}\n");
  const auto db = file.parent_path() / "shard.db";
  const auto r = run_acobench({"run", file.string(), "--shard", "1/2", "--db", db.string()});
  CHECK(r.exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(db));
  CHECK_THAT(r.err, Contains("time-limit-from: a trial's time limit is the time another configuration took") &&
                        Contains("without --shard"));
}

#ifdef ACO_TEST_MPIEXEC
TEST_CASE("acobench under mpirun: time-limit-from trials run after their colony trials on the worker ranks",
          "[ompl][acobench][equal-time][mpi]") {
  using namespace test::acobench_helpers;
  const auto file = test::temp_file("equal-time.yaml", equal_time_text(3, "", true));
  const auto db = file.parent_path() / "equal-time.db";
  const auto r = test::run(mpirun(3, {"run", file.string(), "--db", db.string(), "--threads", "1"}), kMpiEnvironment);
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Contains("2 worker ranks"));
  CHECK(checked_pairs(db) == 6);
}
#endif
