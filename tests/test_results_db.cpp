// acobench's results database: OMPL's layout, read-back, refusing foreign files, surviving SIGKILL.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "aco/studies/results_db.hpp"
#include "acobench_support.hpp"
#include "aco/error.hpp"
#include "support.hpp"

using Catch::Contains;
using test::acobench_helpers::sql_exec;
namespace fs = std::filesystem;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const std::string kName = "ablation";
const std::string kFingerprint = "experiment ablation\nants = 50\nmaps = map1, arena\n";
const std::vector<aco::studies::ProblemRecord> kProblems{
    {"map1", R"({"map":"data/maps/classic20/map1.txt","start":[0,0],"goal":[19,19],"neighbourhood":8})", 28.38},
    {"arena", R"({"map":"arena.map","start":[1,2],"goal":[40,41],"neighbourhood":8})", -1.0}};

fs::path fresh_db() { return test::temp_file("unused", "").parent_path() / "results.db"; }

aco::studies::ResultsDb open(const fs::path& file, const std::string& fingerprint = kFingerprint) {
  return aco::studies::ResultsDb(file, kName, fingerprint, kProblems);
}

aco::studies::ConfigRecord config(const std::string& name, double rho) {
  return {name, R"({"update":")" + name + R"(","update.rho":)" + std::to_string(rho) + "}"};
}

// A trial whose values all depend on its key, solved from iteration 3 on unless `solved` is false.
aco::studies::TrialRecord trial(int problem, int config_id, int repetition, bool solved = true, int iterations = 6) {
  aco::studies::TrialRecord t;
  t.problem = problem;
  t.config = config_id;
  t.repetition = repetition;
  t.seed = 0xFFFF'FFFF'0000'0000ULL + static_cast<std::uint64_t>(repetition);  // above INT64_MAX
  t.solved = solved;
  t.length = solved ? 30.5 + repetition : 0.0;
  t.grid_length = solved ? 31.25 + repetition : 0.0;
  t.turns = solved ? 4 + problem : 0;
  t.iterations = iterations;
  t.best_iteration = solved ? 3 : 0;
  t.time_s = 0.125 * (repetition + 1);
  t.ant_steps = 1000 + static_cast<std::uint64_t>(repetition);
  t.stopped_by = solved ? "stagnation" : "iterations";
  t.path_json = solved ? "[[0,0],[5.5,4],[19,19]]" : "[]";
  for (int i = 1; i <= iterations; ++i) {
    t.best_so_far.push_back(solved && i >= 3 ? 40.0 - i : kInf);
    t.elapsed_s.push_back(0.015625 * i * (repetition + 1));
    t.walks.push_back(static_cast<std::uint64_t>(10 * i));
  }
  t.properties = {{"ant_steps", std::int64_t{1000 + repetition}},
                  {"stopped_by", t.stopped_by},
                  {"update/max_min.restarts", std::int64_t{repetition}},
                  {"heuristic/mine.share", 0.25 * repetition}};
  return t;
}

void check_equal(const aco::studies::TrialRecord& a, const aco::studies::TrialRecord& b) {
  CHECK(a.problem == b.problem);
  CHECK(a.config == b.config);
  CHECK(a.repetition == b.repetition);
  CHECK(a.seed == b.seed);
  CHECK(a.solved == b.solved);
  CHECK(a.length == b.length);
  CHECK(a.grid_length == b.grid_length);
  CHECK(a.turns == b.turns);
  CHECK(a.iterations == b.iterations);
  CHECK(a.best_iteration == b.best_iteration);
  CHECK(a.time_s == b.time_s);
  CHECK(a.ant_steps == b.ant_steps);
  CHECK(a.stopped_by == b.stopped_by);
  CHECK(a.path_json == b.path_json);
  CHECK(a.best_so_far == b.best_so_far);  // infinities compare equal
  CHECK(a.elapsed_s == b.elapsed_s);
  CHECK(a.walks == b.walks);
  CHECK(a.properties == b.properties);
}

// Creates the database with one Ant System trial; returns its configuration's id.
int with_one_trial(const fs::path& file) {
  auto db = open(file);
  const int id = db.add_config(config("ant_system", 0.1));
  db.store(trial(0, id, 0));
  return id;
}

std::string bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The first column of the first row of a query, as text ("NULL" for NULL), run on the file
// directly with SQLite.
std::string sql_value(const fs::path& file, const std::string& sql) {
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(file.c_str(), &raw, SQLITE_OPEN_READWRITE, nullptr);
  std::unique_ptr<sqlite3, decltype(&sqlite3_close)> db(raw, sqlite3_close);
  REQUIRE(rc == SQLITE_OK);
  sqlite3_stmt* raw_statement = nullptr;
  INFO(sql << ": " << sqlite3_errmsg(raw));
  REQUIRE(sqlite3_prepare_v2(raw, sql.c_str(), -1, &raw_statement, nullptr) == SQLITE_OK);
  std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)> statement(raw_statement, sqlite3_finalize);
  REQUIRE(sqlite3_step(raw_statement) == SQLITE_ROW);
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(raw_statement, 0));
  return text ? text : "NULL";
}

}  // namespace

TEST_CASE("a results database reads back every stored trial after reopening", "[resultsdb]") {
  const fs::path file = fresh_db();
  std::vector<aco::studies::TrialRecord> stored;
  int as = 0, mmas = 0;
  {
    auto db = open(file);
    as = db.add_config(config("ant_system", 0.5));
    mmas = db.add_config(config("max_min", 0.02));
    CHECK(as != mmas);
    // Stored out of order: trials() sorts by (problem, config, repetition).
    for (int problem : {1, 0})
      for (int id : {mmas, as})
        for (int repetition : {1, 0}) {
          stored.push_back(trial(problem, id, repetition, !(problem == 1 && repetition == 1)));
          db.store(stored.back());
        }
  }
  std::sort(stored.begin(), stored.end(), [](const auto& a, const auto& b) {
    return std::tie(a.problem, a.config, a.repetition) < std::tie(b.problem, b.config, b.repetition);
  });

  auto db = open(file);
  const auto problems = db.problems();
  REQUIRE(problems.size() == 2);
  CHECK(problems[0].name == "map1");
  CHECK(problems[0].setup_json == kProblems[0].setup_json);
  CHECK(problems[0].optimal_length == 28.38);
  CHECK(problems[1].optimal_length == -1.0);
  const auto configs = db.configs();
  REQUIRE(configs.size() == 2);
  CHECK(configs[0].first == as);
  CHECK(configs[0].second.name == "ant_system");
  CHECK(configs[1].second.settings_json == config("max_min", 0.02).settings_json);
  CHECK(db.meta("experiment_name") == kName);
  CHECK(db.meta("fingerprint") == kFingerprint);
  CHECK(db.meta("format_version") == "7");
  REQUIRE_THROWS_WITH(db.meta("colour"), Contains("no 'colour'"));

  const auto read = db.trials();
  REQUIRE(read.size() == stored.size());
  for (std::size_t i = 0; i < read.size(); ++i) check_equal(read[i], stored[i]);
  CHECK(read[0].best_so_far[0] == kInf);

  const auto done = db.finished();
  CHECK(done.size() == 8);
  CHECK(std::is_sorted(done.begin(), done.end()));
  CHECK(std::binary_search(done.begin(), done.end(), std::tuple{1, mmas, 1}));
  CHECK_FALSE(std::binary_search(done.begin(), done.end(), std::tuple{1, mmas, 2}));

  // The OMPL columns: one experiment per problem, NULLs where a value does not exist.
  CHECK(sql_value(file, "SELECT count(*) FROM experiments") == "2");
  CHECK(sql_value(file, "SELECT totaltime FROM experiments WHERE name = 'map1'") ==
        "0.75");  // 2 configs x (0.125 + 0.25)
  CHECK(sql_value(file, "SELECT count(*) FROM runs WHERE solution_length IS NULL AND gap IS NULL AND solved = 0") ==
        "2");
  CHECK(sql_value(file,
                  "SELECT count(*) FROM runs r JOIN experiments e ON r.experimentid = e.id "
                  "WHERE e.name = 'arena' AND r.gap IS NULL") == "4");  // optimum unknown
  CHECK(std::stod(sql_value(file,
                            "SELECT gap FROM runs r JOIN experiments e ON r.experimentid = e.id "
                            "WHERE e.name = 'map1' AND r.repetition = 0 LIMIT 1")) == Approx(31.25 / 28.38 - 1.0));
  CHECK(sql_value(file, "SELECT count(*) FROM progress") == "48");
  CHECK(sql_value(file, "SELECT count(*) FROM progress WHERE best_cost IS NULL") ==
        "24");  // 6 solved x 2 + 2 unsolved x 6
  // The measured anytime curves: OMPL's time column and the walks.
  CHECK(sql_value(file,
                  "SELECT p.time FROM progress p JOIN runs r ON p.runid = r.id WHERE r.repetition = 1 "
                  "AND p.iteration = 4 LIMIT 1") == "0.125");
  CHECK(sql_value(file, "SELECT count(*) FROM progress WHERE walks != 10 * iteration OR walks IS NULL") == "0");
}

TEST_CASE("a configuration name keeps one set of settings", "[resultsdb]") {
  const fs::path file = fresh_db();
  auto db = open(file);
  const int id = db.add_config({"mmas", R"({"rho":0.02,"p_best":0.05})"});
  CHECK(db.add_config({"mmas", R"({ "p_best": 0.05, "rho": 0.02 })"}) == id);  // the same JSON value
  REQUIRE_THROWS_WITH(db.add_config({"mmas", R"({"rho":0.1,"p_best":0.05})"}),
                      Contains(file.string()) && Contains("configuration 'mmas': {\"rho\":0.02,\"p_best\":0.05} -> "));
  REQUIRE_THROWS_WITH(db.add_config({"broken", "{rho: 1"}), Contains("'broken'") && Contains("not valid JSON"));
  CHECK(db.configs().size() == 1);
}

TEST_CASE("a trial is stored once, and a malformed one not at all", "[resultsdb]") {
  const fs::path file = fresh_db();
  auto db = open(file);
  const int id = db.add_config(config("ant_system", 0.5));
  db.store(trial(0, id, 0));
  REQUIRE_THROWS_WITH(db.store(trial(0, id, 0)),
                      Contains("trial (problem 'map1', config 'ant_system', repetition 0) is already stored"));

  auto bad_curve = trial(0, id, 1);
  bad_curve.best_so_far.pop_back();
  REQUIRE_THROWS_WITH(db.store(bad_curve), Contains("5 best-so-far values for 6 iterations"));
  auto bad_times = trial(0, id, 1);
  bad_times.elapsed_s.pop_back();
  REQUIRE_THROWS_WITH(db.store(bad_times), Contains("5 elapsed times for 6 iterations"));
  auto bad_walks = trial(0, id, 1);
  bad_walks.walks.push_back(70);
  REQUIRE_THROWS_WITH(db.store(bad_walks), Contains("7 walk counts for 6 iterations"));
  auto bad_path = trial(0, id, 1);
  bad_path.path_json = "[[0,0],";
  REQUIRE_THROWS_WITH(db.store(bad_path), Contains("path of trial") && Contains("not valid JSON"));
  REQUIRE_THROWS_WITH(db.store(trial(2, id, 1)), Contains("problem 2, the experiment has 2"));
  REQUIRE_THROWS_WITH(db.store(trial(0, id + 7, 1)), Contains("configuration id " + std::to_string(id + 7)));

  CHECK(db.trials().size() == 1);
  CHECK(sql_value(file, "SELECT count(*) FROM progress") == "6");
}

TEST_CASE("a database of another experiment is refused and left as it was", "[resultsdb]") {
  const fs::path file = fresh_db();
  {
    auto db = open(file);
    db.store(trial(0, db.add_config(config("ant_system", 0.5)), 0));
  }
  const std::string before = bytes(file);
  REQUIRE(!before.empty());

  SECTION("the experiment file changed") {
    REQUIRE_THROWS_WITH(
        open(file, "experiment ablation\nants = 30\nmaps = map1, arena\n"),
        Contains(file.string()) && Contains("experiment 'ablation'") && Contains("the experiment file changed since") &&
            Contains("line 2: stored 'ants = 50', now 'ants = 30'") && Contains("nothing in it was changed"));
  }
  SECTION("another experiment") {
    REQUIRE_THROWS_WITH(aco::studies::ResultsDb(file, "other", kFingerprint, kProblems),
                        Contains("holds the results of experiment 'ablation', not of 'other'"));
  }
  SECTION("the same fingerprint with a problem set up otherwise") {
    auto problems = kProblems;
    problems[1].setup_json = R"({"map":"arena.map","start":[1,2],"goal":[40,40],"neighbourhood":8})";
    REQUIRE_THROWS_WITH(
        aco::studies::ResultsDb(file, kName, kFingerprint, problems),
        Contains("that the experiment file now runs otherwise:\n  problem 'arena': goal [40,41] -> [40,40]\n"));
  }
  CHECK(bytes(file) == before);
  CHECK_FALSE(fs::exists(file.string() + "-wal"));
  auto db = open(file);
  CHECK(db.trials().size() == 1);
}

TEST_CASE("a database of another format version or a bad problem is refused", "[resultsdb]") {
  const fs::path file = fresh_db();
  open(file);  // creates it
  sql_value(file, "UPDATE acobench_meta SET value = '0' WHERE key = 'format_version' RETURNING value");
  REQUIRE_THROWS_WITH(open(file), Contains("format version 0, this acobench reads version 7"));

  const fs::path missing = fresh_db();
  auto problems = kProblems;
  problems[0].setup_json = R"({"map": "map1.txt",)";
  REQUIRE_THROWS_WITH(aco::studies::ResultsDb(missing, kName, kFingerprint, problems),
                      Contains("the setup of problem 'map1' is not valid JSON"));
  CHECK_FALSE(fs::exists(missing));
}

TEST_CASE("simulation and failed trials store their measures, and a format-1 database gains the columns and resumes",
          "[resultsdb]") {
  const fs::path file = fresh_db();
  const int id = with_one_trial(file);
  // What acobench before simulations wrote: no simulation columns, format 1.
  const auto make_format_1 = [&] {
    test::acobench_helpers::downgrade_to_format_6(file);
    for (const char* column :
         {"outcome", "time_to_goal", "collisions", "replans", "clearance", "control_steps", "error", "failure"})
      sql_exec(file, std::string("ALTER TABLE runs DROP COLUMN ") + column);
    sql_exec(file, "ALTER TABLE progress DROP COLUMN walks");
    sql_exec(file, "DROP TABLE properties");
    sql_exec(file, "ALTER TABLE plannerConfigs DROP COLUMN plugins");
    sql_exec(file, "UPDATE acobench_meta SET value = '1' WHERE key = 'format_version'");
  };
  make_format_1();
  CHECK(aco::studies::ResultsDb(file).meta("format_version") == "7");  // a report upgrades it too
  make_format_1();

  auto db = open(file);
  CHECK(db.meta("format_version") == "7");
  auto reached = trial(0, id, 1, true, 0);
  reached.simulation = aco::studies::SimulationRecord{"reached", 87.5, 0, 1, 0.047, 875};
  auto hit = trial(1, id, 0, false, 0);
  hit.simulation = aco::studies::SimulationRecord{"collision", std::nan(""), 1, 0, -0.02, 120};
  db.store(reached);
  db.store(hit);
  auto failed = trial(1, id, 1, false, 0);
  failed.stopped_by = "error";
  failed.error = "plugin update/x failed in update(): an exception of type int";
  db.store(failed);
  const auto read = db.trials();
  REQUIRE(read.size() == 4);
  CHECK(read[3].error == failed.error);
  CHECK(read[0].error.empty());
  CHECK_FALSE(read[0].simulation);  // the format-1 planning run
  REQUIRE(read[1].simulation);
  CHECK(read[1].simulation->outcome == "reached");
  CHECK(read[1].simulation->time_to_goal == 87.5);
  CHECK(read[1].simulation->replans == 1);
  CHECK(read[1].simulation->clearance == 0.047);
  CHECK(read[1].simulation->control_steps == 875);
  REQUIRE(read[2].simulation);
  CHECK(read[2].simulation->outcome == "collision");
  CHECK(std::isnan(read[2].simulation->time_to_goal));
  CHECK(read[2].simulation->collisions == 1);
  CHECK(sql_value(file,
                  "SELECT time_to_goal FROM runs WHERE outcome = (SELECT value FROM enums WHERE name = 'outcome' AND "
                  "description = 'collision')") == "NULL");
}

TEST_CASE("a format-4 database gains runs.failure from how its failed trials stopped", "[resultsdb]") {
  const fs::path file = fresh_db();
  const int id = with_one_trial(file);
  {
    auto db = open(file);
    for (const auto& [repetition, stopped_by] : {std::pair{1, "crashed"}, std::pair{2, "error"}}) {
      auto failed = trial(1, id, repetition, false, 0);
      failed.stopped_by = stopped_by;
      failed.error = std::string(stopped_by) + ": what happened";
      db.store(failed);
    }
  }
  test::acobench_helpers::downgrade_to_format_6(file);
  sql_exec(file, "ALTER TABLE runs DROP COLUMN failure");
  sql_exec(file, "UPDATE acobench_meta SET value = '4' WHERE key = 'format_version'");
  auto db = open(file);
  CHECK(db.meta("format_version") == "7");
  std::map<int, aco::studies::FailureKind> failures;
  for (const auto& t : db.trials()) failures[t.repetition * 10 + t.problem] = t.failure;
  // Which of a plugin or the engine's checks threw was not recorded: "error".
  using aco::studies::FailureKind;
  CHECK(failures ==
        std::map<int, FailureKind>{{0, FailureKind::none}, {11, FailureKind::crashed}, {21, FailureKind::error}});
}

TEST_CASE("a database grows by the problems an experiment adds, and leaves out those it no longer names",
          "[resultsdb]") {
  const fs::path file = fresh_db();
  with_one_trial(file);  // problem map1
  const aco::studies::ProblemRecord extra{"extra", R"({"map":"extra.map","start":[0,0],"goal":[5,5]})", 7.0};
  {
    auto grown = aco::studies::ResultsDb(file, kName, kFingerprint, {kProblems[1], extra, kProblems[0]});
    CHECK(grown.problems().size() == 3);
    const auto trials = grown.trials();
    REQUIRE(trials.size() == 1);
    CHECK(trials[0].problem == 2);  // map1, third of the problems given
    CHECK(grown.finished() == std::vector<std::tuple<int, int, int>>{{2, trials[0].config, 0}});
  }
  CHECK(sql_value(file, "SELECT group_concat(name) FROM experiments") == "map1,arena,extra");
  auto without_map1 = aco::studies::ResultsDb(file, kName, kFingerprint, {extra});
  CHECK(without_map1.trials().empty());
  CHECK(without_map1.finished().empty());
  CHECK(aco::studies::ResultsDb(file).trials().size() == 1);  // a report reads every stored problem
}

TEST_CASE("a format-3 database gains progress.walks: its runs read back without anytime curves, and resume",
          "[resultsdb]") {
  const fs::path file = fresh_db();
  const int id = with_one_trial(file);
  // What acobench before the measured times wrote: no walks, an estimated time, format 3.
  test::acobench_helpers::downgrade_to_format_6(file);
  sql_exec(file, "ALTER TABLE progress DROP COLUMN walks");
  sql_exec(file, "UPDATE progress SET time = iteration * (SELECT time FROM runs WHERE runs.id = progress.runid) / 6");
  sql_exec(file, "UPDATE acobench_meta SET value = '3' WHERE key = 'format_version'");

  auto db = open(file);
  CHECK(db.meta("format_version") == "7");
  db.store(trial(0, id, 1));
  const auto read = db.trials();
  REQUIRE(read.size() == 2);
  CHECK(read[0].best_so_far.size() == 6);
  CHECK(read[0].elapsed_s.empty());  // its times were estimates: not read as measured
  CHECK(read[0].walks.empty());
  check_equal(read[1], trial(0, id, 1));
  CHECK(sql_value(file, "SELECT count(*) FROM progress WHERE walks IS NULL") == "6");

  // Copied on (acobench merge stores what it reads), an old run keeps the older rows.
  const fs::path copy = fresh_db();
  auto out = open(copy);
  const int out_id = out.add_config(config("ant_system", 0.1));
  for (auto t : read) {
    t.config = out_id;
    out.store(t);
  }
  CHECK(sql_value(copy, "SELECT count(*) FROM progress WHERE walks IS NULL") == "6");
  CHECK(sql_value(copy,
                  "SELECT abs(p.time - 0.125) < 1e-12 FROM progress p JOIN runs r ON p.runid = r.id "
                  "WHERE r.repetition = 0 AND p.iteration = 6") == "1");  // the estimate: the run's time
  check_equal(out.trials()[1], trial(0, out_id, 1));
}

TEST_CASE("a file that is not an acobench database is refused and left as it was", "[resultsdb]") {
  SECTION("a text file") {
    const std::string text = "map1, ant_system, 30.5\nmap1, max_min, 29.1\n";
    const fs::path file = test::temp_file("results.csv", text);
    REQUIRE_THROWS_WITH(open(file), Contains(file.string()) && Contains("is not an acobench results database") &&
                                        Contains("file is not a database"));
    CHECK(bytes(file) == text);
  }
  SECTION("another SQLite database") {
    const fs::path file = fresh_db();
    sqlite3* raw = nullptr;
    REQUIRE(sqlite3_open(file.c_str(), &raw) == SQLITE_OK);
    REQUIRE(sqlite3_exec(raw, "CREATE TABLE notes (text TEXT); INSERT INTO notes VALUES ('keep me')", nullptr, nullptr,
                         nullptr) == SQLITE_OK);
    sqlite3_close(raw);
    const std::string before = bytes(file);
    REQUIRE_THROWS_WITH(open(file), Contains("not an acobench results database (it has no acobench_meta table)"));
    CHECK(bytes(file) == before);
    CHECK(sql_value(file, "PRAGMA journal_mode") == "delete");
  }
}

TEST_CASE("every value read back is checked: a bad row is named, left out when asked, never run twice",
          "[resultsdb][bad-input]") {
  struct Case {
    std::string sql, message;
    bool trial_unknown;  // the row's trial cannot be told: a rerun must stop
  };
  const std::vector<Case> cases = {
      {"UPDATE runs SET solution_length = NULL WHERE id = 2",
       "runs row 2, column solution_length: NULL in a solved run", false},
      {"UPDATE runs SET solution_length = 'abc' WHERE id = 2",
       "runs row 2, column solution_length: the text 'abc', not a number", false},
      {"UPDATE runs SET solution_length = X'0102' WHERE id = 2",
       "runs row 2, column solution_length: a blob of 2 bytes, not a number", false},
      {"UPDATE runs SET solution_length = -5 WHERE id = 2",
       "runs row 2, column solution_length: -5, below its least value 0", false},
      {"UPDATE runs SET time = 9e999 WHERE id = 2", "runs row 2, column time: inf, not a finite number", false},
      {"UPDATE runs SET solved = 7 WHERE id = 2", "runs row 2, column solved: 7, not 0 or 1", false},
      {"UPDATE runs SET iterations = 5000000000 WHERE id = 2",
       "runs row 2, column iterations: 5000000000, not a whole number of 32 bits", false},
      {"UPDATE runs SET trial_seed = NULL WHERE id = 2", "runs row 2, column trial_seed: NULL, which it never is",
       false},
      {"UPDATE progress SET best_cost = 'x' WHERE runid = 2 AND iteration = 3",
       "progress row of run 2, column best_cost: the text 'x', not a finite number >= 0", false},
      {"UPDATE run_texts SET path = X'00' WHERE runid = 2",
       "run_texts row of run 2, column path: a blob of 1 bytes, not text", false},
      {"UPDATE runs SET plannerid = NULL WHERE id = 2",
       "runs row 2, column plannerid: NULL, which names no plannerConfigs row", true},
      {"UPDATE runs SET plannerid = 999 WHERE id = 2",
       "runs row 2, column plannerid: 999, which names no plannerConfigs row", true},
      {"UPDATE runs SET experimentid = 999 WHERE id = 2",
       "runs row 2, column experimentid: 999, which names no experiments row", true},
      {"UPDATE runs SET repetition = NULL WHERE id = 2",
       "runs row 2, column repetition: NULL, not a repetition from 0 to 4", true},
      {"UPDATE runs SET repetition = 'x' WHERE id = 2",
       "runs row 2, column repetition: the text 'x', not a repetition from 0 to 4", true},
      {"UPDATE runs SET repetition = 5 WHERE id = 2", "runs row 2, column repetition: 5, not a repetition from 0 to 4",
       true},
      {"UPDATE plannerConfigs SET settings = 'garbage'",
       "runs row 1, column plannerid: 1, a plannerConfigs row whose settings are not JSON", true},
  };
  for (const auto& c : cases) {
    INFO(c.sql);
    const fs::path file = fresh_db();
    {
      auto db = open(file);
      db.record_limits({0.0, 0.0, 5, 1});
      const int id = db.add_config(config("ant_system", 0.1));
      for (int r = 0; r < 3; ++r) db.store(trial(0, id, r));
    }
    sql_exec(file, "PRAGMA foreign_keys = OFF; " + c.sql);
    const aco::studies::ResultsDb db(file);
    CHECK_THROWS_WITH(db.trials(), Contains("results database " + file.string() + ": " + c.message));
    std::vector<aco::studies::BadRow> left_out;
    const auto read = db.trials(&left_out);
    const std::size_t bad = c.sql.find("plannerConfigs") != std::string::npos ? 3 : 1;
    CHECK(read.size() == 3 - bad);
    REQUIRE(left_out.size() == bad);
    CHECK_THAT(describe(left_out.front()), Contains(c.message));
    if (c.trial_unknown)
      CHECK_THROWS_WITH(open(file).finished(),
                        Contains(c.message) && Contains("running the experiment again would run that trial twice"));
    else
      CHECK(open(file).finished().size() == 3);  // stored: not run again
  }
}

TEST_CASE("a results database uses write-ahead logging", "[resultsdb]") {
  const fs::path file = fresh_db();
  auto db = open(file);
  CHECK(sql_value(file, "PRAGMA journal_mode") == "wal");
}

TEST_CASE("a process killed while storing leaves whole trials, and a rerun continues", "[resultsdb]") {
  const fs::path file = fresh_db();
  constexpr int kCommitted = 20;  // trials the child reports before it is killed
  constexpr int kIterations = 2000;  // long transactions, so the kill likely lands inside one
  int pipe_ends[2];
  REQUIRE(pipe(pipe_ends) == 0);
  const pid_t child = fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    // Stores repetitions 0, 1, 2... and reports each commit; _exit skips the parent's cleanup.
    close(pipe_ends[0]);
    try {
      auto db = open(file);
      const int id = db.add_config(config("ant_system", 0.5));
      for (int repetition = 0;; ++repetition) {
        db.store(trial(repetition % 2, id, repetition, true, kIterations));
        const char committed = 1;
        if (write(pipe_ends[1], &committed, 1) != 1) break;
      }
    } catch (...) {}
    _exit(1);
  }
  close(pipe_ends[1]);
  int reported = 0;
  for (char c = 0; reported < kCommitted && read(pipe_ends[0], &c, 1) == 1;) ++reported;
  // Killed right after a report, the child would always die between two trials; a little later,
  // it dies anywhere, mostly inside a trial's transaction.
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  close(pipe_ends[0]);
  REQUIRE(reported == kCommitted);
  CHECK((WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL));

  auto db = open(file);
  CHECK(sql_value(file, "PRAGMA integrity_check") == "ok");
  const auto done = db.finished();
  const int stored = static_cast<int>(done.size());
  CHECK(stored >= kCommitted);
  CHECK(sql_value(file, "SELECT count(*) FROM runs") == std::to_string(stored));
  CHECK(sql_value(file, "SELECT count(*) FROM (SELECT DISTINCT experimentid, plannerid, repetition FROM runs)") ==
        std::to_string(stored));
  CHECK(sql_value(file,
                  "SELECT count(*) FROM runs r WHERE r.iterations != "
                  "(SELECT count(*) FROM progress p WHERE p.runid = r.id)") == "0");
  CHECK(sql_value(file, "SELECT count(*) FROM progress") == std::to_string(stored * kIterations));

  // The rerun: the same command skips what is stored and adds the rest, once each.
  const int id = db.add_config(config("ant_system", 0.5));
  const int wanted = stored + 3;
  for (int repetition = 0; repetition < wanted; ++repetition)
    if (!std::binary_search(done.begin(), done.end(), std::tuple{repetition % 2, id, repetition}))
      db.store(trial(repetition % 2, id, repetition, true, 10));
  CHECK(db.finished().size() == static_cast<std::size_t>(wanted));
  CHECK(sql_value(file, "SELECT max(repetition) FROM runs") == std::to_string(wanted - 1));
}

TEST_CASE(
    "a trial's properties are rows of their own with their types, and a format-4 database gains the table and resumes",
    "[resultsdb][figures]") {
  const fs::path file = fresh_db();
  const int id = with_one_trial(file);
  CHECK(sql_value(file, "SELECT value FROM properties WHERE name = 'update/max_min.restarts'") == "0");
  CHECK(sql_value(file, "SELECT typeof(value) FROM properties WHERE name = 'update/max_min.restarts'") == "integer");
  CHECK(sql_value(file, "SELECT typeof(value) FROM properties WHERE name = 'heuristic/mine.share'") == "real");
  CHECK(sql_value(file, "SELECT value FROM properties WHERE name = 'stopped_by'") == "stagnation");
  // What acobench before the properties wrote: no properties table, no plugins of a configuration.
  test::acobench_helpers::downgrade_to_format_6(file);
  sql_exec(file, "DROP TABLE properties");
  sql_exec(file, "ALTER TABLE plannerConfigs DROP COLUMN plugins");
  sql_exec(file, "UPDATE acobench_meta SET value = '4' WHERE key = 'format_version'");

  auto db = open(file);
  CHECK(db.meta("format_version") == "7");
  aco::studies::ConfigRecord same = config("ant_system", 0.1);
  same.plugins_json = R"({"update":{"name":"ant_system","build":"optimised"}})";
  CHECK(db.add_config(same) == id);  // the same configuration, now with its plugins
  CHECK(db.configs().front().second.plugins_json == same.plugins_json);
  db.store(trial(0, id, 1));
  const auto read = db.trials();
  REQUIRE(read.size() == 2);
  CHECK(read[0].properties.empty());  // stored before properties were
  check_equal(read[1], trial(0, id, 1));
}

TEST_CASE("the database is OMPL's layout: limits, ENUMs, and names its tools and Planner Arena read",
          "[resultsdb][ompl]") {
  const fs::path file = fresh_db();
  int id = 0;
  {
    auto db = open(file);
    id = db.add_config(config("ant_system", 0.1));
    db.store(trial(0, id, 0));
    auto crashed = trial(0, id, 1, false, 0);
    crashed.stopped_by = "crashed";
    crashed.failure = aco::studies::FailureKind::crashed;
    crashed.error = "signal 11";
    db.store(crashed);
    db.store(trial(1, id, 0, false));
    db.record_limits({2.5, 512.0, 10, 42});
    const auto limits = db.limits();
    CHECK(limits.time_limit_s == 2.5);
    CHECK(limits.memory_limit_mib == 512.0);
    CHECK(limits.runs == 10);
    CHECK(limits.seed == 42);
  }
  // What OMPL's script prints on its last page: no NULL.
  CHECK(sql_value(file,
                  "SELECT count(*) FROM experiments WHERE timelimit = 2.5 AND memorylimit = 512 AND "
                  "runcount = 10 AND seed = '42'") == "2");
  // The planner status, as OMPL's PlannerStatus names it.
  const auto status_of = [&](int experiment, int repetition) {
    return sql_value(file,
                     "SELECT e.description FROM runs r JOIN enums e ON e.name = 'status' AND e.value = r.status "
                     "WHERE r.experimentid = " +
                         std::to_string(experiment) + " AND r.repetition = " + std::to_string(repetition));
  };
  CHECK(status_of(1, 0) == "Exact solution");
  CHECK(status_of(1, 1) == "Crash");
  CHECK(status_of(2, 0) == "Timeout");
  CHECK(sql_value(file,
                  "SELECT description FROM enums WHERE name = 'failure' AND value = "
                  "(SELECT failure FROM runs WHERE repetition = 1)") == "crashed");
  CHECK(sql_value(file, "SELECT error FROM run_texts JOIN runs ON runid = id WHERE repetition = 1") == "signal 11");
  // OMPL's script plots every runs column declared BOOLEAN, ENUM, INTEGER or REAL; the identities are INT.
  CHECK(sql_value(file,
                  "SELECT group_concat(name) FROM pragma_table_info('runs') WHERE cid >= 3 AND type NOT IN "
                  "('BOOLEAN', 'ENUM', 'INTEGER', 'REAL')") == "repetition,trial_seed");
  // OMPL's -a inserts plannerConfigs rows by position: three columns.
  CHECK(sql_value(file, "SELECT group_concat(name) FROM pragma_table_info('plannerConfigs')") == "id,name,settings");
  // Planner Arena joins runs with plannerConfigs' name (as planner) and the experiments' columns
  // but totaltime..runcount and hostname..setup (id and name renamed): no runs column may clash.
  CHECK(sql_value(file,
                  "SELECT count(*) FROM pragma_table_info('runs') WHERE name IN ('planner', 'experiment') OR name IN "
                  "(SELECT name FROM pragma_table_info('experiments') WHERE name NOT IN ('id', 'name', 'totaltime', "
                  "'timelimit', 'memorylimit', 'runcount', 'hostname', 'cpuinfo', 'date', 'seed', 'setup'))") == "0");

  // An OMPL log appended as ompl_benchmark_statistics -a does it.
  sql_exec(file,
           "INSERT INTO experiments (name, totaltime, timelimit, memorylimit, runcount, version, hostname, cpuinfo, "
           "date, seed, setup) VALUES ('wall', 1.5, 0.1, 100, 2, 'OMPL 1.5.2', 'vm', 'cpu', '2026-11-27', '7', "
           "'Properties of the state space');"
           "INSERT INTO plannerConfigs VALUES (NULL, 'geometric_RRTConnect', 'range = 0;');"
           "ALTER TABLE runs ADD graph_states INTEGER;"
           "INSERT INTO runs (experimentid, plannerid, solved, time, solution_length, status, memory, graph_states) "
           "VALUES (3, 2, 1, 0.01, 12.5, 6, 0.5, 40), (3, 2, 0, 0.1, NULL, 4, 0.5, 90);"
           "INSERT INTO progress (runid, time, best_cost) VALUES (4, 0.005, 13.0);");
  const aco::studies::ResultsDb report(file);
  CHECK(report.problems().size() == 2);
  CHECK(report.configs().size() == 1);
  CHECK(report.trials().size() == 3);
  const auto appended = report.appended_runs();
  REQUIRE(appended.size() == 2);
  CHECK(appended[0].experiment == "wall");
  CHECK(appended[0].planner == "geometric_RRTConnect");
  CHECK(appended[0].solved);
  CHECK(appended[0].length == 12.5);
  CHECK_FALSE(appended[1].solved);
  CHECK(std::isnan(appended[1].length));
  auto resumed = open(file);  // and the experiment goes on
  resumed.store(trial(1, id, 1));
  CHECK(resumed.trials().size() == 4);
}

TEST_CASE("a format-6 database is migrated to OMPL's layout with the same trials", "[resultsdb][ompl]") {
  const fs::path file = fresh_db();
  std::vector<aco::studies::TrialRecord> stored;
  {
    auto db = open(file);
    const int id = db.add_config(config("ant_system", 0.1));
    stored = {trial(0, id, 0), trial(0, id, 1, false), trial(1, id, 0)};
    stored[2].simulation = aco::studies::SimulationRecord{"stuck", std::nan(""), 0, 3, 0.5, 90};
    for (const auto& t : stored) db.store(t);
  }
  test::acobench_helpers::downgrade_to_format_6(file);
  CHECK(sql_value(file, "SELECT stopped_by FROM runs WHERE repetition = 0 LIMIT 1") == "stagnation");
  sql_exec(file, "UPDATE runs SET stopped_by = 'exhausted' WHERE repetition = 1");
  const std::string before = bytes(file);
  REQUIRE_THROWS_WITH(aco::studies::ResultsDb(file), Contains("runs.stopped_by cannot hold 'exhausted'"));
  CHECK(bytes(file) == before);  // rolled back
  sql_exec(file, "UPDATE runs SET stopped_by = 'iterations' WHERE repetition = 1");

  auto db = open(file);
  CHECK(db.meta("format_version") == "7");
  const auto read = db.trials();
  REQUIRE(read.size() == stored.size());
  for (std::size_t i = 0; i < read.size(); ++i) check_equal(read[i], stored[i]);
  CHECK(read[2].simulation->outcome == "stuck");
  CHECK(sql_value(file, "SELECT count(*) FROM enums WHERE name = 'status'") == "9");
  CHECK(sql_value(file, "SELECT timelimit || ',' || memorylimit || ',' || runcount FROM experiments LIMIT 1") ==
        "0.0,0.0,0");
  CHECK(sql_value(file, "SELECT count(*) FROM pragma_foreign_key_check") == "0");
}
