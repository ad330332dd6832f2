// Issue 24: a plugin that crashes, hangs or fills memory costs its own trial, not the study.
// acobench runs trials in worker processes; acoplan names the plugin hook a crash happened in.
#include <catch2/catch.hpp>
#include <set>

#include "aco/studies/results_db.hpp"
#include "aco/error.hpp"
#include "acobench_support.hpp"

using Catch::Contains;
using namespace test::acobench_helpers;

namespace {

// A baseline and MAX-MIN (healthy) on two problems, 3 repetitions each.
const std::string kHealthy =
    "name: isolation\nseed: 5\nrepetitions: 3\nproblems:\n"
    "  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
    "  - {map: {MAP1}, start: [0, 19], goal: [19, 0], name: across}\n"
    "settings: {ants: 10, iterations: 8}\nbaseline: {name: AS}\n"
    "configurations:\n  - {name: MMAS, update: max_min}\n";

// The same with a crashing, a hanging, a memory-filling and a throwing configuration.
const std::string kHostile = kHealthy +
                             "  - {name: crash, update: crashing, update.at_iteration: 3}\n"
                             "  - {name: hang, update: hanging, update.at_iteration: 3}\n"
                             "  - {name: hog, update: hogging, update.at_iteration: 3}\n"
                             "  - {name: throw, update: throwing, update.at_iteration: 3}\n";

std::vector<std::string> hostile_options(const std::filesystem::path& db) {
  return {"--db",
          db.string(),
          "--plugin-dir",
          ACO_TEST_HOSTILE_PLUGIN_DIR,
          "--plugin-dir",
          ACO_TEST_FAULTY_PLUGIN_DIR,
          "--trial-timeout",
          "3",
          "--trial-memory",
          "128M"};
}

std::vector<std::string> with(std::vector<std::string> first, const std::vector<std::string>& then) {
  first.insert(first.end(), then.begin(), then.end());
  return first;
}

// Rows of trial_rows() of the configurations with ids 1 and 2 (the healthy ones, added first).
std::vector<std::string> healthy_rows(const std::filesystem::path& db) {
  std::vector<std::string> rows;
  for (const auto& t : aco::studies::ResultsDb(db).trials())
    if (t.config <= 2)
      rows.push_back(std::to_string(t.problem) + " " + std::to_string(t.config) + " " + std::to_string(t.repetition) +
                     " " + std::to_string(t.length) + " " + t.path_json);
  return rows;
}

// Each failed trial's configuration, kind and message checked; returns the kinds' counts.
std::map<std::string, int> check_failures(const std::filesystem::path& db) {
  const std::string hostile = ACO_TEST_HOSTILE_PLUGIN_DIR;
  const std::map<int, std::pair<std::string, std::string>> expected{
      {3,
       {"crashed", "crashed: SIGSEGV in plugin update/crashing (" + hostile +
                       "/aco_update_crashing.so) in update() in iteration 3"}},
      {4,
       {"timed out", "timed out after 3 s in plugin update/hanging (" + hostile +
                         "/aco_update_hanging.so) in update() in iteration 3"}},
      {5,
       {"out of memory", "out of memory (over 128 MiB) in plugin update/hogging (" + hostile +
                             "/aco_update_hogging.so) in update() in iteration 3"}},
      {6, {"plugin error", "plugin update/throwing ("}}};
  std::map<std::string, int> kinds;
  for (const auto& t : aco::studies::ResultsDb(db).trials()) {
    INFO("config " << t.config << ": " << t.error);
    if (t.config <= 2) {
      CHECK(t.error.empty());
      continue;
    }
    const auto& [kind, message] = expected.at(t.config);
    CHECK(t.stopped_by == (kind == "plugin error" ? "error" : kind));
    CHECK_FALSE(t.solved);
    CHECK_THAT(t.error, Contains(message));
    ++kinds[aco::studies::to_string(t.failure)];
  }
  return kinds;
}

}  // namespace

TEST_CASE("a crash an endless loop a memory hog and a throw each cost only their own trials and the study finishes",
          "[acobench][isolation][slow]") {
  const auto file = experiment(kHostile);
  const auto db = file.parent_path() / "hostile.db", healthy_db = file.parent_path() / "healthy.db";
  const auto r = run_acobench(with({"run", file.string()}, hostile_options(db)));
  INFO(r.out << r.err);
  CHECK(r.exit_code == 3);  // trials failed
  CHECK_THAT(r.out, Contains("36 trials, 0 already in"));
  CHECK_THAT(r.err, Contains("24 of 36 trials failed, by reason and configuration:") &&
                        Contains("  crashed (a signal): 6\n    'crash': 6, e.g. problem 'across', "
                                 "repetition 0: crashed: SIGSEGV in plugin update/crashing") &&
                        Contains("  over the trial time limit: 6\n    'hang': 6, e.g.") &&
                        Contains("  out of memory: 6\n    'hog': 6, e.g.") &&
                        Contains("  a plugin threw: 6\n    'throw': 6, e.g."));
  CHECK(count_runs(db) == 36);
  CHECK(check_failures(db) ==
        std::map<std::string, int>{{"crashed", 6}, {"plugin error", 6}, {"out of memory", 6}, {"timed out", 6}});
  // The healthy configurations' trials are those of an experiment without the hostile ones.
  const auto healthy = experiment(kHealthy);
  REQUIRE(run_acobench({"run", healthy.string(), "--db", healthy_db.string()}).exit_code == 0);
  CHECK(healthy_rows(db) == healthy_rows(healthy_db));
  CHECK(healthy_rows(db).size() == 12);
  // Failed trials are results: a rerun has nothing to do, and gives the same verdict.
  const auto rerun = run_acobench(with({"run", file.string()}, hostile_options(db)));
  CHECK_THAT(rerun.out, Contains("36 already in"));
  CHECK(rerun.exit_code == 3);
  CHECK_THAT(rerun.err, Contains("24 of 36 trials failed (24 stored as failed by an earlier run)"));
  // The report counts them per configuration and kind.
  const auto out = file.parent_path() / "report";
  REQUIRE(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
  const std::string md = file_bytes(out / "report.md");
  CHECK_THAT(md, Contains("| crash | 6 | 6 | 0 | 6 | 0 | 0 |") && Contains("| hang | 6 | 6 | 0 | 0 | 6 | 0 |") &&
                     Contains("| hog | 6 | 6 | 0 | 0 | 0 | 6 |") && Contains("| throw | 6 | 6 | 6 | 0 | 0 | 0 |"));
}

#ifdef ACO_TEST_MPIEXEC
TEST_CASE("under mpirun -n 3 the hostile trials are contained the same way and the database is the single-process one",
          "[acobench][isolation][mpi][slow]") {
  const auto file = experiment(kHostile);
  const auto single = file.parent_path() / "single.db", ranks = file.parent_path() / "ranks.db";
  REQUIRE(run_acobench(with({"run", file.string()}, hostile_options(single))).exit_code == 3);
  const auto r =
      test::run(mpirun(3, with({"run", file.string(), "--threads", "1"}, hostile_options(ranks))), kMpiEnvironment);
  INFO(r.out << r.err);
  CHECK(r.exit_code == 3);  // rank 0's verdict: trials failed
  CHECK_THAT(r.err, Contains("24 of 36 trials failed") && Contains("crashed (a signal): 6"));
  CHECK_THAT(r.out, Contains("36 trials, 0 already in") && Contains("2 worker ranks"));
  CHECK(check_failures(ranks).size() == 4);
  CHECK(database_rows(ranks) == database_rows(single));
}
#endif

TEST_CASE("worker processes and --in-process give the same database", "[acobench][isolation]") {
  const auto file = experiment(kSmall);
  const auto workers = file.parent_path() / "workers.db", in_process = file.parent_path() / "in_process.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", workers.string(), "--threads", "2"}).exit_code == 0);
  REQUIRE(run_acobench({"run", file.string(), "--db", in_process.string(), "--in-process"}).exit_code == 0);
  CHECK(database_rows(workers) == database_rows(in_process));
  // Limits need workers: said, not silently ignored.
  const auto warned =
      run_acobench({"run", file.string(), "--db", in_process.string(), "--in-process", "--trial-timeout", "5"});
  CHECK_THAT(warned.err, Contains("--in-process: the trial time and memory limits are not enforced"));
}

TEST_CASE("trial limits come from experiment keys or the command line which wins and bad values are refused",
          "[acobench][isolation]") {
  const auto e = load(kHealthy + "trial-timeout: 2.5\ntrial-memory: 1G\n");
  CHECK(e.trial_timeout_s == 2.5);
  CHECK(e.trial_memory_bytes == std::uint64_t(1) << 30);
  CHECK_THROWS_WITH(load(kHealthy + "trial-timeout: -1\n"), Contains("trial-timeout: '-1' is not a time in seconds"));
  CHECK_THROWS_WITH(load(kHealthy + "trial-timeout: soon\n"), Contains("trial-timeout: 'soon' is not a time"));
  CHECK_THROWS_WITH(load(kHealthy + "trial-memory: lots\n"), Contains("trial-memory"));
  // The file's limit applies unless the command line gives another: a hang stopped after the
  // file's 1 s, and the command line's 0.5 s named instead when given.
  const auto file = experiment(
      "name: hang\nrepetitions: 1\ntrial-timeout: 1\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 5, iterations: 5}\nbaseline: {name: hang, update: hanging, update.at_iteration: 2}\n");
  const auto db = file.parent_path() / "hang.db", db2 = file.parent_path() / "hang2.db";
  const auto r = run_acobench({"run", file.string(), "--db", db.string(), "--plugin-dir", ACO_TEST_HOSTILE_PLUGIN_DIR});
  REQUIRE(r.exit_code == 3);
  CHECK_THAT(r.err, Contains("timed out after 1 s in plugin update/hanging"));
  const auto r2 = run_acobench({"run", file.string(), "--db", db2.string(), "--plugin-dir", ACO_TEST_HOSTILE_PLUGIN_DIR,
                                "--trial-timeout", "0.5"});
  CHECK_THAT(r2.err, Contains("timed out after 0.5 s in plugin update/hanging"));
  CHECK_THAT(
      run_acobench({"run", file.string(), "--trial-timeout", "0", "--plugin-dir", ACO_TEST_HOSTILE_PLUGIN_DIR}).err,
      Contains("--trial-timeout: '0' is not a time"));
}

TEST_CASE("acoplan names the plugin and hook a crash happened in and ends as the signal does", "[acoplan][isolation]") {
  const std::vector<std::string> args{"--map",
                                      map1(),
                                      "--start",
                                      "0,0",
                                      "--goal",
                                      "19,19",
                                      "--plugin-dir",
                                      ACO_TEST_HOSTILE_PLUGIN_DIR,
                                      "--update",
                                      "crashing",
                                      "--update.at_iteration",
                                      "2"};
  const auto segv = test::acoplan(args);
  CHECK(segv.exit_code == 139);
  CHECK_THAT(segv.err, Contains("acoplan: error: crashed: SIGSEGV in plugin update/crashing (") &&
                           Contains("aco_update_crashing.so) in update() in iteration 2"));
  const auto abort = test::acoplan(with(args, {"--update.abort", "true", "--threads", "2"}));
  CHECK(abort.exit_code == 134);
  CHECK_THAT(abort.err, Contains("acoplan: error: crashed: SIGABRT in plugin update/crashing ("));
}
