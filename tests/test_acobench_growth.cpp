// Studies that tell the truth and grow: the warning for configurations that are one run (the exit
// code and failures by reason: test_acobench.cpp), and experiments that gain configurations, problems and
// repetitions into their database.
#include <sqlite3.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "aco/studies/experiment.hpp"
#include "aco/studies/results_db.hpp"
#include "acobench_support.hpp"
#include "support.hpp"

using Catch::Contains;
using namespace test::acobench_helpers;

namespace {

// Every column of every runs and progress row, ids and times included, ordered by id: a stored
// trial kept by a grown experiment is this, byte for byte.
std::vector<std::string> raw_rows(const std::filesystem::path& db) {
  sqlite3* handle = nullptr;
  std::vector<std::string> rows;
  REQUIRE(sqlite3_open_v2(db.c_str(), &handle, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  for (const char* sql :
       {"SELECT * FROM runs ORDER BY id", "SELECT * FROM progress ORDER BY runid, iteration",
        "SELECT * FROM plannerConfigs ORDER BY id",
        // Not totaltime: the sum of the problem's trials' times grows with them.
        "SELECT id, name, version, hostname, cpuinfo, date, setup, optimal_length FROM experiments"}) {
    sqlite3_stmt* statement = nullptr;
    REQUIRE(sqlite3_prepare_v2(handle, sql, -1, &statement, nullptr) == SQLITE_OK);
    while (sqlite3_step(statement) == SQLITE_ROW) {
      std::string row = sql;
      for (int c = 0; c < sqlite3_column_count(statement); ++c) {
        const auto* bytes = static_cast<const char*>(sqlite3_column_blob(statement, c));
        const auto size = static_cast<std::size_t>(sqlite3_column_bytes(statement, c));
        row += "|";
        row += bytes ? std::string(bytes, size) : std::string("NULL");
      }
      rows.push_back(row);
    }
    sqlite3_finalize(statement);
  }
  sqlite3_close(handle);
  return rows;
}

// trial_rows() with the problem's and the configuration's names for their positions: databases
// that list their problems in another order compare equal when they hold the same trials.
std::vector<std::string> named_trial_rows(const std::filesystem::path& db) {
  const aco::studies::ResultsDb read(db);
  std::map<int, std::string> configs;
  for (const auto& [id, config] : read.configs()) configs[id] = config.name;
  const auto problems = read.problems();
  std::vector<std::string> rows;
  for (const auto& t : read.trials()) {
    std::ostringstream row;
    row.precision(17);
    row << problems[static_cast<std::size_t>(t.problem)].name << " " << configs[t.config] << " " << t.repetition << " "
        << t.seed << " " << t.solved << " " << t.length << " " << t.best_iteration << " " << t.ant_steps << " "
        << t.path_json;
    for (double b : t.best_so_far) row << " " << b;
    rows.push_back(row.str());
  }
  std::sort(rows.begin(), rows.end());
  return rows;
}

// Every row of `earlier` is in `later`, as it was.
bool keeps(const std::vector<std::string>& later, const std::vector<std::string>& earlier) {
  for (const auto& row : earlier)
    if (std::find(later.begin(), later.end(), row) == later.end()) return false;
  return true;
}

// Not REQUIRE: it also makes the experiment texts below, before any test runs.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("no '" + from + "' in the experiment text");
  return text.replace(at, from.size(), to);
}

// Two configurations on one problem, 2 repetitions: 4 quick trials.
const std::string kGrowing = R"(name: growing
seed: 7
repetitions: 2
problems:
  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}
settings: {preset: ant-system, ants: 10, iterations: 15}
baseline: {name: AS, update: {plugin: ant_system, rho: 0.3}}
configurations:
  - {name: ACS, update: {plugin: acs, xi: 0.2}, q0: 0.7}
)";

const std::string kMoreConfig = kGrowing + "  - {name: MMAS, update: max_min}\n";
const std::string kMoreProblem =
    replaced(kMoreConfig, "problems:\n", "problems:\n  - {map: {MAP1}, start: [0, 19], goal: [19, 0], name: across}\n");
const std::string kMoreRepetitions = replaced(kMoreProblem, "repetitions: 2", "repetitions: 3");

// An experiment file written in place of another (the database's experiment_file stays valid).
void rewrite(const std::filesystem::path& file, std::string text) {
  for (auto at = text.find("{MAP1}"); at != std::string::npos; at = text.find("{MAP1}")) text.replace(at, 6, map1());
  std::ofstream(file) << text;
}

// kGrowing run into its database: the file, the database and the command's arguments.
std::tuple<std::filesystem::path, std::filesystem::path, std::vector<std::string>> run_growing() {
  const auto file = experiment(kGrowing);
  const auto db = file.parent_path() / "growing.db";
  const std::vector<std::string> args{"run", file.string(), "--db", db.string()};
  REQUIRE(run_acobench(args).exit_code == 0);
  return {file, db, args};
}

}  // namespace

TEST_CASE("two configurations that resolve to the same run are named before any trial runs", "[acobench][failures]") {
  const std::string text =
      "name: twins\nseed: 3\nrepetitions: 1\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {preset: ant-system, ants: 10, iterations: 3}\nbaseline: {name: AS}\n"
      "configurations:\n  - {name: MMAS}\n  - {name: ACS, update: acs}\n";
  const auto experiment_loaded = load(text);
  CHECK(experiment_loaded.same_runs() == std::vector<std::pair<std::string, std::string>>{{"AS", "MMAS"}});
  const auto file = experiment(text);
  const auto r = run_acobench({"run", file.string(), "--db", (file.parent_path() / "twins.db").string()});
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.err,
             Contains("acobench: warning: configurations 'AS' and 'MMAS' resolve to the same run (the same "
                      "plugins and parameters), so comparing them compares a run with itself: did 'MMAS' forget a "
                      "key (its plugin, say)?"));
  CHECK(r.err.find("'ACS' resolve") == std::string::npos);
  CHECK(load(replaced(text, "{name: MMAS}", "{name: MMAS, update: max_min}")).same_runs().empty());
}

TEST_CASE(
    "an experiment grown by a configuration a problem and repetitions runs only the new trials and keeps the stored "
    "rows",
    "[acobench][growth][slow]") {
  const auto [file, db, args] = run_growing();
  auto before = raw_rows(db);
  REQUIRE(count_runs(db) == 4);

  // Each step grows the file by one kind of thing: only its trials run, the stored rows stay.
  const std::vector<std::tuple<std::string, std::string, std::string>> steps{
      {kMoreConfig, "(configurations 'MMAS')", "6 trials, 4 already in " + db.string() + ", 2 run"},
      {kMoreProblem, "(problems 'across')", "12 trials, 6 already in " + db.string() + ", 6 run"},
      {kMoreRepetitions, "(repetitions 2 -> 3)", "18 trials, 12 already in " + db.string() + ", 6 run"}};
  for (const auto& [text, grew, counts] : steps) {
    rewrite(file, text);
    const auto r = run_acobench(args);
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("the experiment grew " + grew + ": only the new trials run, the stored ones are kept"));
    CHECK_THAT(r.out, Contains(counts));
    CHECK(keeps(raw_rows(db), before));
    before = raw_rows(db);
  }

  const auto rerun = run_acobench(args);
  REQUIRE(rerun.exit_code == 0);
  CHECK_THAT(rerun.out, Contains("18 trials, 18 already in " + db.string() + ", 0 run"));
  CHECK(rerun.out.find("grew") == std::string::npos);

  // The grown database holds what one run of the final experiment stores: the kept trials'
  // seeds and results are those the final experiment gives them.
  const auto whole = file.parent_path() / "whole.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", whole.string()}).exit_code == 0);
  CHECK(named_trial_rows(db) == named_trial_rows(whole));

  const auto out = file.parent_path() / "report";
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  INFO(report.err);
  REQUIRE(report.exit_code == 0);
  CHECK_THAT(file_bytes(out / "report.md"), Contains("| MMAS |") && Contains("across"));
}

TEST_CASE("an experiment whose stored trials would run otherwise is refused one line per difference",
          "[acobench][growth]") {
  // Named, not bound: the lambda below captures them (clang 14 cannot capture a structured binding).
  const auto started = run_growing();
  const auto& file = std::get<0>(started);
  const auto& db = std::get<1>(started);
  const auto& args = std::get<2>(started);
  const std::string before = file_bytes(db);
  const auto refused = [&](const std::string& text) {
    rewrite(file, text);
    const auto r = run_acobench(args);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Contains(db.string() + " holds trials of experiment 'growing' that the experiment file now runs "
                                             "otherwise:\n") &&
                          Contains("nothing in it was changed: give a changed configuration or problem a new name"));
    CHECK(file_bytes(db) == before);
    return r.err;
  };
  CHECK_THAT(refused(replaced(kGrowing, "xi: 0.2", "xi: 0.25")),
             Contains("\n  configuration 'ACS': update.xi 0.2 -> 0.25\n"));
  CHECK_THAT(refused(replaced(kGrowing, "iterations: 15", "iterations: 20")),
             Contains("\n  every configuration: iterations 15 -> 20\n"));
  CHECK_THAT(refused(replaced(kGrowing, "seed: 7", "seed: 8")),
             Contains("\n  seed 7 -> 8 (every trial's seed derives from it)\n"));
  CHECK_THAT(refused(replaced(kGrowing, "goal: [19, 19]", "goal: [19, 18]")),
             Contains("\n  problem 'map1': goal [19,19] -> [19,18]\n"));
  // Two differences, two lines; a configuration renamed is another one, which the database takes.
  const std::string two = refused(replaced(replaced(kGrowing, "xi: 0.2", "xi: 0.25"), "q0: 0.7", "q0: 0.8"));
  CHECK_THAT(two, Contains("\n  configuration 'ACS': q0 0.7 -> 0.8\n  configuration 'ACS': update.xi 0.2 -> 0.25\n"));
  rewrite(file, replaced(replaced(kGrowing, "xi: 0.2", "xi: 0.25"), "name: ACS", "name: ACS-0.25"));
  const auto renamed = run_acobench(args);
  CHECK(renamed.exit_code == 0);
  CHECK_THAT(renamed.out, Contains("4 trials, 2 already in") &&
                              Contains("also holds 'ACS', which the experiment file no "
                                       "longer names: their trials are kept (and reported), not run"));
}

TEST_CASE("shards of a grown experiment merge into the database of one run of it", "[acobench][growth][shards][slow]") {
  const auto file = experiment(kGrowing);
  const auto one = file.parent_path() / "one.db", two = file.parent_path() / "two.db";
  const auto shard = [&](const std::filesystem::path& db, const std::string& k) {
    const auto r = run_acobench({"run", file.string(), "--shard", k + "/2", "--db", db.string()});
    INFO(r.err);
    CHECK(r.exit_code == 0);
    return r.out;
  };
  shard(one, "1");
  shard(two, "2");
  rewrite(file, kMoreConfig);
  // A shard of the grown experiment runs the trials it now holds; its database keeps its others.
  CHECK_THAT(shard(one, "1"), Contains("3 trials, 2 already in"));
  const auto merged = file.parent_path() / "merged.db", whole = file.parent_path() / "whole.db";
  // The grown shard 1 with the not yet grown shard 2: one experiment, at two sizes.
  const auto m = run_acobench({"merge", one.string(), two.string(), "--db", merged.string()});
  INFO(m.err);
  REQUIRE(m.exit_code == 0);
  CHECK_THAT(m.err, Contains("1 of 3 trials missing"));
  shard(two, "2");
  std::filesystem::remove(merged);
  REQUIRE(run_acobench({"merge", one.string(), two.string(), "--db", merged.string()}).exit_code == 0);
  REQUIRE(run_acobench({"run", file.string(), "--db", whole.string()}).exit_code == 0);
  CHECK(named_trial_rows(merged) == named_trial_rows(whole));
  // A database of the same experiment run otherwise is refused, naming the difference.
  rewrite(file, replaced(kMoreConfig, "xi: 0.2", "xi: 0.25"));
  const auto other = file.parent_path() / "other.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", other.string()}).exit_code == 0);
  const auto refused =
      run_acobench({"merge", merged.string(), other.string(), "--db", (file.parent_path() / "m2.db").string()});
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.err,
             Contains("cannot merge " + other.string()) && Contains("configuration 'ACS': update.xi 0.2 -> 0.25"));
}
