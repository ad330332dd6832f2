// acobench: experiment files, trial seeds, the ablation path, resuming after SIGKILL, reports.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <set>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>
#include <fstream>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "aco/studies/experiment.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/runner.hpp"
#include "aco/error.hpp"
#include "acobench_support.hpp"
#include "support.hpp"

using Catch::Contains;
using Catch::StartsWith;

using namespace test::acobench_helpers;

namespace {

std::size_t count_of(const std::string& text, const std::string& word) {
  std::size_t found = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + word.size())) ++found;
  return found;
}

}  // namespace

TEST_CASE("an experiment file expands into named, factorial and baseline configurations", "[acobench]") {
  const auto e = load(kSmall);
  CHECK(e.name == "small");
  CHECK(e.repetitions == 4);
  REQUIRE(e.problems.size() == 1);
  CHECK(e.problems[0].name == "map1");
  REQUIRE(e.configurations.size() == 4);
  CHECK(e.configurations[0].name == "AS");
  CHECK(e.configurations[1].name == "ACS");
  CHECK(e.configurations[2].name == "beta=3");
  CHECK(e.configurations[3].name == "beta=7");
  // A configuration inherits the common settings; a new update plugin drops the old one's rho.
  CHECK(e.configurations[1].keys.at("ants") == "10");
  CHECK(e.configurations[1].keys.at("update") == "acs");
  CHECK(e.configurations[1].keys.count("update.rho") == 0);
  CHECK(e.configurations[2].keys.at("update.rho") == "0.3");
  const auto s = aco::studies::resolve(e.configurations[1], test::plugins());
  CHECK(s.graph.corner_cutting);
  CHECK(s.pipeline.at("update").parameters.real("xi") == 0.2);
  CHECK(s.colony.q0 == 0.7);
  CHECK(s.colony.ants == 10);
}

TEST_CASE("a factorial over two factors gives every combination", "[acobench]") {
  const auto e = load(std::string(kSmall) + "  update: [ant_system, max_min]\n");
  REQUIRE(e.configurations.size() == 2 + 4);
  CHECK(e.configurations[2].name == "beta=3,update=ant_system");
  CHECK(e.configurations[5].name == "beta=7,update=max_min");
  CHECK(e.configurations[5].keys.count("update.rho") == 0);
}

TEST_CASE("experiment file mistakes name the file, the line and the key", "[acobench][errors]") {
  CHECK_THROWS_WITH(load("name: x\nproblems: [\n"), Contains("experiment.yaml:") && Contains("malformed YAML"));
  std::string bad_plugin = kSmall;
  bad_plugin.replace(bad_plugin.find("plugin: acs"), 11, "plugin: acz");
  CHECK_THROWS_WITH(load(bad_plugin), Contains("experiment.yaml:18") && Contains("unknown update plugin 'acz'"));
  std::string bad_param = kSmall;
  bad_param.replace(bad_param.find("xi: 0.2"), 7, "x1: 0.2");
  CHECK_THROWS_WITH(load(bad_param), Contains("experiment.yaml:18") && Contains("update.xi"));
  std::string out_of_range = kSmall;
  out_of_range.replace(out_of_range.find("rho: 0.3"), 8, "rho: 3");
  CHECK_THROWS_WITH(load(out_of_range), Contains("experiment.yaml:15") && Contains("rho"));
  std::string unknown_key = kSmall;
  unknown_key.replace(unknown_key.find("ants: 10"), 8, "antz: 10");
  CHECK_THROWS_WITH(load(unknown_key), Contains("experiment.yaml:10") && Contains("did you mean 'ants'"));
  CHECK_THROWS_WITH(load(std::string(kSmall) + "ablation: {target: nothing}\n"), Contains("ablation target 'nothing'"));
  CHECK_THROWS_WITH(load(std::string(kSmall) + "colour: blue\n"), Contains("unknown key 'colour'"));
  std::string seeded = kSmall;
  seeded.replace(seeded.find("ants: 10"), 8, "seed: 3");
  CHECK_THROWS_WITH(load(seeded), Contains("set per trial"));
  CHECK_THROWS_WITH(load("problems:\n  - map: {MAP1}\n    start: [0, 0]\n"), Contains("needs map, start and goal"));
}

TEST_CASE("a trial's seed depends on the master seed, the problem and the repetition only", "[acobench]") {
  const auto a = aco::studies::trial_seed(1, "map1", 0);
  CHECK(a == aco::studies::trial_seed(1, "map1", 0));
  CHECK(a != aco::studies::trial_seed(2, "map1", 0));
  CHECK(a != aco::studies::trial_seed(1, "map2", 0));
  CHECK(a != aco::studies::trial_seed(1, "map1", 1));
  CHECK(a < (std::uint64_t{1} << 63));  // within the colony's seed range
}

TEST_CASE("the ablation path flips one component at a time, and a slot's plugin carries its parameters", "[acobench]") {
  aco::studies::Configuration from{{{{"update", "ant_system"}, {"update.rho", "0.3"}, {"beta", "7"}}, {}}, "from", {}};
  aco::studies::Configuration to{
      {{{"update", "acs"}, {"update.xi", "0.2"}, {"beta", "3"}, {"init", "obstacle_density"}}, {}}, "to", {}};
  const auto components = aco::studies::ablation_components(from, to);
  REQUIRE(components.size() == 3);  // beta, init, update (+ update.xi, update.rho)
  const auto update =
      std::find_if(components.begin(), components.end(), [](const auto& c) { return c.front() == "update"; });
  REQUIRE(update != components.end());
  CHECK(update->size() == 3);
  const auto flipped = aco::studies::flip(from, to, *update);
  CHECK(flipped.keys.at("update") == "acs");
  CHECK(flipped.keys.at("update.xi") == "0.2");
  CHECK(flipped.keys.count("update.rho") == 0);
  CHECK(flipped.keys.at("beta") == "7");
}

TEST_CASE("acobench runs an experiment, resumes it, refuses another one's database and reports", "[acobench][slow]") {
  const auto file = experiment(std::string(kSmall) + "ablation: {target: ACS}\n");
  const auto db = file.parent_path() / "small.db";
  const auto first = run_acobench({"run", file.string(), "--db", db.string(), "--threads", "1"});
  REQUIRE(first.exit_code == 0);
  CHECK_THAT(first.out,
             Contains("28 trials, 0 already in"));  // 4 configs + 2 + 1 ablation candidates (update, q0), 4 repetitions
  // Said before the first trial too, with what makes the count.
  CHECK_THAT(first.out,
             StartsWith("acobench: small: 28 trials: (4 + 3 on the ablation path) configurations x 1 problem "
                        "x 4 repetitions; 0 already in " +
                        db.string() + ", 28 to run\n"));
  const auto again = run_acobench({"run", file.string(), "--db", db.string()});
  REQUIRE(again.exit_code == 0);
  CHECK_THAT(again.out, Contains("28 trials, 28 already in"));
  // The ablation path's stored trials are found as its rounds start.
  CHECK_THAT(again.out, Contains("; 16 already in " + db.string() + ", at most 12 to run\n"));
  CHECK_THAT(again.out, Contains("0 run"));

  // The thread count does not change any result.
  const auto db2 = file.parent_path() / "two_threads.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", db2.string(), "--threads", "2"}).exit_code == 0);
  CHECK(trial_rows(db) == trial_rows(db2));
  // Each trial's anytime curves: a time per iteration, never decreasing, and its ants' walks.
  for (const auto& t : aco::studies::ResultsDb(db).trials()) {
    REQUIRE(t.elapsed_s.size() == static_cast<std::size_t>(t.iterations));
    REQUIRE(t.walks.size() == static_cast<std::size_t>(t.iterations));
    CHECK(t.peak_memory_mib > 0);  // measured in the worker process that ran it
    for (std::size_t i = 0; i < t.walks.size(); ++i) {
      CHECK(t.walks[i] == 10u * (i + 1));
      if (i > 0) CHECK(t.elapsed_s[i] >= t.elapsed_s[i - 1]);
    }
  }

  // Another experiment (more repetitions) must not touch this database.
  std::string other = kSmall;
  other.replace(other.find("repetitions: 4"), 14, "repetitions: 5");
  const auto other_file =
      test::temp_file("experiment.yaml", std::string(other).replace(other.find("{MAP1}"), 6, map1()));
  const std::string before = file_bytes(db);
  const auto refused = run_acobench({"run", other_file.string(), "--db", db.string()});
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.err, Contains("ablation: the stored path was chosen on the stored problems and repetitions"));
  CHECK(file_bytes(db) == before);

  const auto out = file.parent_path() / "report";
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  REQUIRE(report.exit_code == 0);
  const std::string html = file_bytes(out / "report.html");
  CHECK_THAT(html, Contains("class=\"boxplot\""));
  CHECK_THAT(html, Contains("class=\"convergence\""));
  CHECK_THAT(html, Contains("class=\"paths\""));
  CHECK_THAT(html, Contains("Ablation path"));
  // The anytime view: the gap against time and walks for the one problem, an ECDF per target.
  CHECK(count_of(html, "class=\"anytime\"") == 2);
  CHECK(count_of(html, "class=\"ecdf\"") == 2);
  CHECK_THAT(html, Contains("best-so-far gap against time") && Contains("best-so-far gap against walks") &&
                       Contains("runs within 1 % of the optimum, by time (ECDF)") &&
                       Contains("runs within 5 % of the optimum, by time (ECDF)") &&
                       Contains("<h2>Anytime: fixed targets</h2>"));
  CHECK(html.find("http://") == html.find("http://www.w3.org/2000/svg"));  // no link but the SVG namespace
  const std::string md = file_bytes(out / "report.md");
  CHECK_THAT(md, Contains("## Anytime: fixed targets") && Contains("| ACS | gap <= 1 % | 4 |") &&
                     Contains("| ACS | gap <= 5 % | 4 |"));
  CHECK_THAT(md, Contains("| ACS | 4 | 100 % |"));
  CHECK_THAT(md, Contains("## Ranking across problems"));
  const std::string csv = file_bytes(out / "runs.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 28);
  // Each plot of the page is also a file of its own (docs/results.md shows them as images), named
  // once on stdout with its folder.
  std::set<std::string> plots;
  for (const auto& entry : std::filesystem::directory_iterator(out / "plots")) {
    const std::string svg = file_bytes(entry.path());
    INFO(entry.path());
    CHECK(svg.starts_with("<svg") == true);
    CHECK_THAT(svg, Contains("xmlns=\"http://www.w3.org/2000/svg\""));
    CHECK_THAT(html, Contains(svg));
    plots.insert(entry.path().filename().string());
  }
  CHECK(plots.count("ecdf-1pct.svg") == 1);
  CHECK(plots.count("ecdf-5pct.svg") == 1);
  CHECK(plots.count("ablation.svg") == 1);
  for (const char* kind : {"box-", "convergence-", "anytime-time-", "anytime-walks-", "paths-"})
    CHECK(std::count_if(plots.begin(), plots.end(), [&](const std::string& f) { return f.starts_with(kind); }) == 1);
  CHECK_THAT(report.out, Contains((out / "plots").string() + "/ (" + std::to_string(plots.size()) + " SVG plots)"));
  CHECK_THAT(report.out, !Contains(".svg"));
}

TEST_CASE("a run killed with SIGKILL continues on rerun with every trial exactly once", "[acobench][slow]") {
  const auto file = experiment(kill_me_text());
  const auto killed = file.parent_path() / "killed.db", whole = file.parent_path() / "whole.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", whole.string()}).exit_code == 0);

  const pid_t child =
      test::start({ACO_TEST_ACOBENCH, "run", file.string(), "--db", killed.string(), "--threads", "1"}, "/dev/null");
  // Kill once some trials are committed.
  wait_for_trials(killed, 10);
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  REQUIRE(WIFSIGNALED(status));
  const int at_kill = count_runs(killed);
  INFO("trials stored when killed: " << at_kill);
  CHECK(at_kill >= 10);
  CHECK(at_kill < 300);

  const auto rerun = run_acobench({"run", file.string(), "--db", killed.string()});
  REQUIRE(rerun.exit_code == 0);
  CHECK_THAT(rerun.out, Contains(std::to_string(at_kill) + " already in"));
  CHECK(count_runs(killed) == 300);
  CHECK(trial_rows(killed) == trial_rows(whole));
}

TEST_CASE("a run stopped with SIGTERM says what is stored and the command that goes on", "[acobench][slow]") {
  const auto file = experiment(kill_me_text());
  const auto db = file.parent_path() / "stopped.db", log = file.parent_path() / "stopped.log";
  const pid_t child =
      test::start({ACO_TEST_ACOBENCH, "run", file.string(), "--db", db.string(), "--threads", "1"}, log);
  wait_for_trials(db, 10);
  kill(child, SIGTERM);
  int status = 0;
  waitpid(child, &status, 0);
  CHECK((WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM));
  CHECK_THAT(file_bytes(log), Contains("acobench: stopped by a signal; every trial finished before it is stored in " +
                                       db.string() + ": run `acobench run " + file.string() + " --db " + db.string() +
                                       " --threads 1` again to run the others"));
}

// The highest resident memory of a running process so far (VmHWM), in KiB.
long peak_memory_kib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

TEST_CASE("a study of four billion trials stores its first ones at once in little memory and resumes",
          "[acobench][slow]") {
  std::string text = kSmall;
  text.replace(text.find("repetitions: 4"), 14, "repetitions: 1000000000");
  const auto file = experiment(text);
  const auto db = file.parent_path() / "huge.db", log = file.parent_path() / "huge.log";
  for (int round = 0; round < 2; ++round) {
    const int before = round == 0 ? 0 : count_runs(db);
    const pid_t child =
        test::start({ACO_TEST_ACOBENCH, "run", file.string(), "--db", db.string(), "--threads", "1"}, log);
    // A list of the trials made before the first runs (96 GB) never gets here within the minute.
    wait_for_trials(db, before + 20);
    const long peak = peak_memory_kib(child);
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    INFO("round " << round << ", stored before " << before << ", peak " << peak << " KiB");
    CHECK(count_runs(db) >= before + 20);
    CHECK(peak > 0);
    CHECK(peak < 256 * 1024);
    CHECK_THAT(file_bytes(log), Contains("4000000000 trials: 4 configurations x 1 problem x 1000000000 repetitions; " +
                                         std::to_string(before) + " already in"));
  }
  // Resumed, not rerun: the second run's trials are others than the first's.
  CHECK(sql_value(db, "SELECT count(*) - count(DISTINCT plannerid || ':' || repetition) FROM runs") == "0");
}

TEST_CASE("a report counts the runs it cannot read, and a rerun stops at a row whose trial it cannot tell",
          "[acobench][bad-input]") {
  const auto file = experiment(kSmall);
  const auto db = file.parent_path() / "small.db", out = file.parent_path() / "report";
  REQUIRE(run_acobench({"run", file.string(), "--db", db.string()}).exit_code == 0);
  const std::string row = "(SELECT min(id) FROM runs WHERE solved = 1)";
  const std::string id = sql_value(db, "SELECT " + row);
  sql_exec(db, "UPDATE runs SET solution_length = 'abc' WHERE id = " + row);
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  REQUIRE(report.exit_code == 0);
  const std::string left_out =
      "1 run is left out of every table and figure: its rows do not hold what the database's "
      "tables declare (runs row " +
      id + ", column solution_length: the text 'abc', not a number)";
  CHECK_THAT(report.err, Contains(left_out));
  const std::string md = file_bytes(out / "report.md");
  CHECK_THAT(md, Contains("`: 15 runs (1 left out), 4 configurations") && Contains(left_out));
  const std::string csv = file_bytes(out / "runs.csv");
  CHECK(std::count(csv.begin(), csv.end(), '\n') == 1 + 15);
  // Stored is stored: the rerun runs nothing.
  const auto again = run_acobench({"run", file.string(), "--db", db.string()});
  CHECK(again.exit_code == 0);
  CHECK_THAT(again.out, Contains("16 already in"));
  CHECK(count_runs(db) == 16);

  sql_exec(db, "UPDATE runs SET plannerid = NULL WHERE id = " + id);
  const std::string before = file_bytes(db);
  const auto refused = run_acobench({"run", file.string(), "--db", db.string()});
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.err, Contains("runs row " + id + ", column plannerid: NULL, which names no plannerConfigs row") &&
                              Contains("DELETE FROM runs WHERE id = " + id));
  CHECK(count_runs(db) == 16);
  CHECK(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
}

TEST_CASE("a results database that cannot be written is reported as it is, and named so by a run",
          "[acobench][bad-input]") {
  const auto file = experiment(kSmall);
  const auto folder = file.parent_path() / "locked";
  std::filesystem::create_directories(folder);
  const auto db = folder / "small.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", db.string()}).exit_code == 0);
  const auto out = file.parent_path() / "report";
  std::filesystem::create_directories(out);
  using std::filesystem::perms;
  std::filesystem::permissions(db, perms::owner_read | perms::group_read | perms::others_read);
  std::filesystem::permissions(folder, perms::owner_read | perms::owner_exec | perms::group_read | perms::group_exec |
                                           perms::others_read | perms::others_exec);
  std::filesystem::permissions(out, perms::all);
  std::filesystem::permissions(file.parent_path(), perms::all);
  // Root writes whatever the permissions say: run as nobody there.
  std::vector<std::string> as_reader;
  if (::geteuid() == 0) as_reader = {"/usr/bin/setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"};
  const auto acobench = [&](std::vector<std::string> args) {
    args.insert(args.begin(), ACO_TEST_ACOBENCH);
    args.insert(args.begin(), as_reader.begin(), as_reader.end());
    return test::run(args);
  };
  const std::string before = file_bytes(db);
  const auto report = acobench({"report", db.string(), "--out", (out / "read-only").string()});
  INFO(report.err);
  REQUIRE(report.exit_code == 0);
  CHECK_THAT(file_bytes(out / "read-only" / "report.md"), Contains("`small.db`: 16 runs, 4 configurations"));
  const auto refused = acobench({"run", file.string(), "--db", db.string()});
  CHECK(refused.exit_code == 1);
  CHECK_THAT(refused.err, Contains("results database " + db.string() + " cannot be written (its folder " +
                                   folder.string() + ": Permission denied), and a run stores its trials there"));
  CHECK(file_bytes(db) == before);
  CHECK_FALSE(std::filesystem::exists(db.string() + "-wal"));
  std::filesystem::permissions(folder, perms::owner_all);
}

TEST_CASE("acobench refuses a blocked start, a missing database and an unknown command", "[acobench][errors]") {
  std::string blocked = kSmall;
  blocked.replace(blocked.find("start: [0, 0]"), 13, "start: [6, 0]");  // an obstacle of map1
  const auto file = experiment(blocked);
  const auto run = run_acobench({"run", file.string(), "--db", (file.parent_path() / "x.db").string()});
  CHECK(run.exit_code == 1);
  CHECK_THAT(run.err, Contains("problem 'map1': start (6,0) is blocked: an obstacle"));
  CHECK_FALSE(std::filesystem::exists(file.parent_path() / "x.db"));
  const auto report = run_acobench({"report", (file.parent_path() / "none.db").string()});
  CHECK(report.exit_code == 1);
  CHECK_THAT(report.err, Contains("no such results database"));
  const auto unknown = run_acobench({"rn", file.string()});
  CHECK(unknown.exit_code == 1);
  CHECK_THAT(unknown.err, Contains("unknown command 'rn'"));
}

TEST_CASE("a configuration starts from an acoplan config file with 'config', its own keys win", "[acobench]") {
  const auto file = experiment(
      "name: presets\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\nsettings: {iterations: 5}\n"
      "baseline: {name: preset, config: preset.ini}\n"
      "configurations:\n"
      "  - {name: fewer ants, ants: 6}\n"
      "  - {name: other heuristic, heuristic: distance}\n"
      "  - {name: from the preset again, config: preset.ini, update.rho: 0.4}\n");
  std::ofstream(file.parent_path() / "preset.ini")
      << "ants = 12   # a comment\nheuristic = progress\nupdate = acs\nq0 = 0.7\n"
         "[heuristic]\nfloor = 0.5\n[update]\nrho = 0.2\n";
  const auto e = aco::studies::load_experiment(file, test::plugins());
  REQUIRE(e.configurations.size() == 4);
  const auto& preset = *e.configurations[0].run;
  CHECK(preset.colony.ants == 12);
  CHECK(preset.colony.iterations == 5);
  CHECK(preset.colony.q0 == 0.7);
  CHECK(preset.pipeline.at("heuristic").plugin == "progress");
  CHECK(preset.pipeline.at("heuristic").parameters.real("floor") == 0.5);
  CHECK(preset.pipeline.at("update").parameters.real("rho") == 0.2);
  CHECK(e.configurations[1].run->colony.ants == 6);
  CHECK(e.configurations[1].run->pipeline.at("heuristic").plugin == "progress");
  // Another plugin in a slot drops the preset's parameters of that slot.
  CHECK(e.configurations[2].run->pipeline.at("heuristic").plugin == "distance");
  CHECK(e.configurations[2].run->pipeline.at("update").parameters.real("rho") == 0.2);
  CHECK(e.configurations[3].run->pipeline.at("update").parameters.real("rho") == 0.4);
  CHECK(e.configurations[3].run->colony.ants == 12);

  SECTION("a missing config file is named with the line that asks for it") {
    std::filesystem::remove(file.parent_path() / "preset.ini");
    CHECK_THROWS_WITH(aco::studies::load_experiment(file, test::plugins()),
                      Contains("experiment.yaml:5") && Contains("preset.ini: cannot open the config file"));
  }
  SECTION("a bad key in the config file is named with the file") {
    std::ofstream(file.parent_path() / "preset.ini") << "antz = 12\n";
    CHECK_THROWS_WITH(aco::studies::load_experiment(file, test::plugins()),
                      Contains("preset.ini: configuration 'preset'") && Contains("antz") && Contains("ants"));
  }
  SECTION("a bad line in the config file is named with its file and line") {
    std::ofstream(file.parent_path() / "preset.ini") << "ants = 12\n%invalid_line%x\n";
    CHECK_THROWS_WITH(
        aco::studies::load_experiment(file, test::plugins()),
        Contains("experiment.yaml:5") && Contains("preset.ini:2: '%invalid_line%x' is not a 'key = value' line"));
  }
}

// Boost.ProgramOptions' message for these never came back (aco/hosts/program_options_error.hpp).
TEST_CASE("acobench shows '%' placeholders in its options as typed", "[acobench][bad-input]") {
  const auto error = [](const std::vector<std::string>& args) {
    const auto r = run_acobench(args);
    CHECK(r.exit_code == 1);
    return r.err;
  };
  CHECK(error({"run", "x.yaml", "--threads", "%value%"}) ==
        "acobench: error: the argument ('%value%') for option '--threads' is invalid\n");
  CHECK(error({"run", "x.yaml", "--%canonical_option%"}) ==
        "acobench: error: unrecognised option '--%canonical_option%'\n");
}

TEST_CASE("an experiment sets terrain keys per configuration: max-slope limits the paths", "[acobench][terrain]") {
  const auto file = test::temp_file("terrain.yaml", "name: slopes\nseed: 3\nrepetitions: 2\nproblems:\n  - {scen: " +
                                                        (test::data_dir() / "terrain/epf30.asc.scen").string() +
                                                        ", count: 1}\nsettings: {ants: 20, iterations: 20}\n"
                                                        "configurations:\n  - {name: slope60, max-slope: 60}\n"
                                                        "  - {name: slope50, max-slope: 50}\n");
  const auto e = aco::studies::load_experiment(file, test::plugins());
  REQUIRE(e.configurations.size() == 3);
  CHECK(aco::studies::resolve(e.configurations[1], test::plugins()).problem.terrain.max_slope_deg == 60.0);
  const auto db_file = file.parent_path() / "slopes.db";
  aco::studies::RunOptions options;
  options.database = db_file;
  options.threads = 2;
  const auto summary = aco::studies::run_experiment(e, test::plugins(), options);
  CHECK(summary.ran == 6);
  const aco::studies::ResultsDb db(db_file);
  const auto configs = db.configs();
  REQUIRE(configs.size() == 3);
  CHECK_THAT(configs[1].second.settings_json, Contains("\"max-slope\":60.0"));
  int solved[3] = {0, 0, 0};
  double steepest = 0;
  for (const auto& t : db.trials()) {
    const int c = t.config - configs[0].first;
    solved[c] += t.solved;
    if (c != 1 || !t.solved) continue;
    const auto path = nlohmann::json::parse(t.path_json);
    for (std::size_t i = 1; i < path.size(); ++i) {
      const double dx = path[i][0].get<double>() - path[i - 1][0].get<double>();
      const double dy = path[i][1].get<double>() - path[i - 1][1].get<double>();
      const double dz = path[i][2].get<double>() - path[i - 1][2].get<double>();
      steepest = std::max(steepest, std::atan2(std::abs(dz), std::hypot(dx, dy)) * 180.0 / M_PI);
    }
  }
  CHECK(solved[0] == 2);
  CHECK(solved[1] == 2);
  CHECK(solved[2] == 0);  // at 50 degrees the goal cannot be reached from the start
  CHECK(steepest > 0.0);
  CHECK(steepest <= 60.0);
}

TEST_CASE("acobench runs acosim scenarios as problems: local-planner keys per configuration, same variations for all",
          "[acobench][acosim]") {
  // An open 12 x 5 map; the scenario's robot drives from (0, 2) to (11, 2) past an unknown cell.
  const auto dir = test::temp_file("open.txt", "").parent_path();
  {
    std::ofstream open(dir / "open.txt");
    for (int y = 0; y < 5; ++y) open << "0 0 0 0 0 0 0 0 0 0 0 0\n";
  }
  std::ofstream(dir / "scenario.yaml") << "run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa}\n"
                                          "unknown: [[6, 2]]\n";
  const auto file = dir / "sim.yaml";
  std::ofstream(file) << "name: sim\nseed: 5\nrepetitions: 3\nproblems:\n"
                         "  - {simulation: scenario.yaml}\n"
                         "  - {simulation: scenario.yaml, variations: true, name: varied}\n"
                         "baseline: {name: dwa}\n"
                         "configurations:\n  - {name: follow, local.follow: 0.5}\n  - {name: blind, local: track}\n";
  const auto e = aco::studies::load_experiment(file, test::plugins());
  REQUIRE(e.problems.size() == 2);
  CHECK(e.problems[0].start == aco::Cell{0, 2});
  CHECK(e.problems[1].variations);
  // local.follow is a parameter of the scenario's dwa, not of the default local planner.
  CHECK(e.configurations[1].run->pipeline.at("local").parameters.real("follow") == 0.5);

  const auto run = [&](const std::string& name, int threads) {
    const auto db_file = file.parent_path() / name;
    aco::studies::RunOptions options;
    options.database = db_file;
    options.threads = threads;
    aco::studies::run_experiment(e, test::plugins(), options);
    return aco::studies::ResultsDb(db_file).trials();
  };
  const auto trials = run("sim1.db", 1);
  REQUIRE(trials.size() == 18);
  const auto configs = aco::studies::ResultsDb(file.parent_path() / "sim1.db").configs();
  for (const auto& t : trials) {
    INFO("problem " << t.problem << ", config " << t.config << ", repetition " << t.repetition);
    REQUIRE(t.simulation);
    const std::string config =
        std::find_if(configs.begin(), configs.end(), [&](auto& c) { return c.first == t.config; })->second.name;
    if (config == "blind" && t.problem == 0) {
      CHECK(t.simulation->outcome == "collision");  // the unknown cell is on its line
      CHECK(t.simulation->collisions == 1);
    }
    if (config != "blind") {
      CHECK(t.solved);
      CHECK(t.simulation->collisions == 0);
      CHECK(t.simulation->clearance > 0.0);
      CHECK(t.length > 10.0);  // the distance driven
      CHECK(std::isfinite(t.simulation->time_to_goal));
    }
    CHECK(t.solved == (t.simulation->outcome == "reached"));
  }
  // Every configuration meets the same variation in a repetition: the trial seeds agree.
  for (const auto& a : trials)
    for (const auto& b : trials)
      if (a.problem == b.problem && a.repetition == b.repetition) CHECK(a.seed == b.seed);
  // Results do not depend on the thread count.
  const auto two = run("sim2.db", 2);
  REQUIRE(two.size() == trials.size());
  for (std::size_t i = 0; i < trials.size(); ++i) {
    CHECK(two[i].length == trials[i].length);
    CHECK(two[i].simulation->outcome == trials[i].simulation->outcome);
    CHECK(two[i].simulation->control_steps == trials[i].simulation->control_steps);
    CHECK(two[i].path_json == trials[i].path_json);
  }
  // A key the scenario's plugins do not have is an error naming the configuration.
  std::ofstream(file)
      << "name: sim\nproblems:\n  - {simulation: scenario.yaml}\nconfigurations:\n  - {name: bad, local.folow: 1}\n";
  CHECK_THROWS_WITH(aco::studies::load_experiment(file, test::plugins()),
                    Contains("configuration 'bad'") && Contains("local.follow"));
  std::ofstream(file) << "name: sim\nproblems:\n  - {simulation: missing.yaml}\n";
  CHECK_THROWS_WITH(aco::studies::load_experiment(file, test::plugins()),
                    Contains("sim.yaml:3") && Contains("cannot open the scenario file"));
  // Found by the experiment fuzz harness: a folder given as the scenario escaped as the stream
  // library's std::ios_base::failure (acobench printed "basic_filebuf::underflow error").
  std::ofstream(file) << "name: sim\nproblems:\n  - {simulation: ../}\n";
  CHECK_THROWS_WITH(aco::studies::load_experiment(file, test::plugins()),
                    Contains("sim.yaml:3") && Contains("is a directory, not a scenario file"));
  CHECK_THROWS_WITH(aco::studies::load_experiment(file.parent_path(), test::plugins()),
                    Contains("is a directory, not an experiment file"));
}

TEST_CASE("failed trials are stored named and counted by reason and acobench exits 3 now and on a rerun",
          "[acobench][boundary][failures]") {
  const auto file = experiment(
      "name: throws\nseed: 3\nrepetitions: 3\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 10, iterations: 5}\nbaseline: {name: AS}\n"
      "configurations:\n  - {name: thrower, update: throwing, update.at_iteration: 2}\n"
      "  - {name: nan, update: bad_value, update.at_iteration: 4}\n");
  const auto db = file.parent_path() / "throws.db";
  const std::vector<std::string> args{"run",       file.string(),  "--db",
                                      db.string(), "--plugin-dir", ACO_TEST_FAULTY_PLUGIN_DIR};
  const auto r = run_acobench(args);
  INFO(r.out << r.err);
  CHECK(r.exit_code == 3);
  CHECK_THAT(r.out, Contains("9 trials, 0 already in"));
  CHECK_THAT(r.out,
             StartsWith("acobench: throws: 9 trials: 3 configurations x 1 problem x 3 repetitions; 0 already in " +
                        db.string() + ", 9 to run\n"));
  CHECK_THAT(r.err, Contains("6 of 9 trials failed, by reason and configuration:\n"));
  CHECK_THAT(
      r.err,
      Contains("  a plugin threw: 3\n    'thrower': 3, e.g. problem 'map1', "
               "repetition 0: plugin update/throwing (") &&
          Contains("failed in update() in iteration 2 (0-based, as Context::iteration): an exception of type int"));
  CHECK_THAT(r.err, Contains("  a plugin wrote an invalid value: 3\n    'nan': 3, e.g. problem "
                             "'map1', repetition 0: plugin update/bad_value ("));
  CHECK_THAT(r.err, Contains("acobench: exit 3: trials failed") && Contains("--allow-failures accepts them"));
  int solved = 0;
  std::map<std::string, int> failures;
  for (const auto& t : aco::studies::ResultsDb(db).trials()) {
    if (!t.error.empty()) {
      ++failures[aco::studies::to_string(t.failure)];
      CHECK_FALSE(t.solved);
      CHECK(t.stopped_by == "error");
    }
    solved += t.solved;
  }
  CHECK(failures == std::map<std::string, int>{{"invalid value", 3}, {"plugin error", 3}});
  CHECK(solved == 3);  // the other configuration's trials all ran
  // A failed trial is a result: a rerun does not repeat it, and gives the same verdict.
  const auto again = run_acobench(args);
  CHECK(again.exit_code == 3);
  CHECK_THAT(again.out, Contains("9 trials, 9 already in") && Contains("0 run"));
  CHECK_THAT(again.out, Contains("; 9 already in " + db.string() + ", 0 to run\n"));
  CHECK_THAT(again.err, Contains("6 of 9 trials failed (6 stored as failed by an earlier run)") &&
                            Contains("a plugin threw: 3") && Contains("a plugin wrote an invalid value: 3"));
  auto allowed_args = args;
  allowed_args.push_back("--allow-failures");
  const auto allowed = run_acobench(allowed_args);
  CHECK(allowed.exit_code == 0);
  CHECK_THAT(allowed.err, Contains("6 of 9 trials failed") && Contains("--allow-failures: exit 0 all the same"));
  const auto out = file.parent_path() / "report";
  REQUIRE(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
  const std::string md = file_bytes(out / "report.md");
  CHECK_THAT(md,
             Contains("## Failed trials") && Contains("| thrower | 3 | 3 | 3 | 0 | 0 | 0 | configuration 'thrower'"));
}

TEST_CASE("an experiment given by a relative path, with absolute map paths, stores and draws its maps", "[acobench]") {
  const auto file = experiment(
      "name: rel\nrepetitions: 1\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 5, iterations: 3}\n");
  const auto before = std::filesystem::current_path();
  std::filesystem::current_path(file.parent_path());
  const auto run = run_acobench({"run", file.filename().string(), "--db", "rel.db"});
  const auto report = run_acobench({"report", "rel.db", "--out", "report"});
  std::filesystem::current_path(before);
  REQUIRE(run.exit_code == 0);
  REQUIRE(report.exit_code == 0);
  const aco::studies::ResultsDb db(file.parent_path() / "rel.db");
  const auto map = nlohmann::json::parse(db.problems().at(0).setup_json).at("map").get<std::string>();
  CHECK(std::filesystem::equivalent(file.parent_path() / map, map1()));
  const std::string html = file_bytes(file.parent_path() / "report/report.html");
  CHECK(html.find("map not drawn") == std::string::npos);
  CHECK_THAT(html, Contains("class=\"paths\""));
}

TEST_CASE("every plot of a report of many long-named configurations holds its text inside its picture",
          "[acobench][report][svg]") {
  // Twenty configurations with long names, an ablation path, a map drawn with every best path:
  // box plot, convergence, anytime and ECDF charts, paths and the ablation chart.
  std::string yaml =
      "name: long-names\nseed: 3\nrepetitions: 2\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 5, iterations: 4}\nbaseline: {name: ant_system}\nconfigurations:\n";
  for (int k = 1; k <= 20; ++k)
    yaml += "  - {name: \"configuration " + std::to_string(k) + " with alpha " + std::to_string(k) +
            " and a rather long descriptive name (MMAS)\", alpha: " + std::to_string(k) + "}\n";
  yaml += "  - {name: target, alpha: 2, beta: 3, update: max_min}\nablation: {target: target}\n";
  const auto file = experiment(yaml);
  const auto db = file.parent_path() / "long-names.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", db.string()}).exit_code == 0);
  const auto out = file.parent_path() / "report";
  REQUIRE(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
  const std::string html = file_bytes(out / "report.html");
  std::set<std::string> kinds;
  for (auto at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) {
    const std::string svg = html.substr(at, html.find("</svg>", at) + 6 - at);
    const auto kind = svg.find("class=\"");
    kinds.insert(svg.substr(kind + 7, svg.find('"', kind + 7) - kind - 7));
    for (const auto& text : test::texts_outside_view_box(svg)) FAIL_CHECK(svg.substr(0, 60) << ": " << text);
  }
  CHECK(kinds == std::set<std::string>{"boxplot", "convergence", "anytime", "ecdf", "paths"});
}

TEST_CASE("acobench measures the gap of a smoothed run on its grid path against the grid optimum",
          "[acobench][report]") {
  const auto file = experiment(R"(name: smoothed
seed: 5
repetitions: 3
problems:
  - map: {MAP1}
    start: [0, 0]
    goal: [19, 19]
settings: {ants: 10, iterations: 15}
baseline: {name: pruned, smoother: prune}
configurations:
  - {name: grid, smoother: none}
  - {name: A* pruned, planner: astar, smoother: prune}
)");
  const auto db = file.parent_path() / "smoothed.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", db.string()}).exit_code == 0);
  const auto out = file.parent_path() / "report";
  REQUIRE(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
  CHECK_THAT(file_bytes(out / "report.md"), Contains("gap is the mean excess of the grid path (before smoothing)"));

  const double optimal = aco::studies::ResultsDb(db).problems().at(0).optimal_length;
  std::istringstream csv(file_bytes(out / "runs.csv"));
  std::string line;
  std::getline(csv, line);
  int solved = 0, shorter_than_grid_optimum = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() >= 8);
    if (cells[4] != "1") continue;
    ++solved;
    const double length = std::stod(cells[5]), grid_length = std::stod(cells[6]), gap = std::stod(cells[7]);
    CHECK(gap >= 0.0);
    CHECK(gap == Approx(100.0 * (grid_length / optimal - 1.0)).margin(1e-4));
    if (length < optimal - 1e-9) ++shorter_than_grid_optimum;
  }
  CHECK(solved == 9);
  // The pruned paths are any-angle: A*'s, pruned, is shorter than the grid optimum, which is why
  // gaps are not measured on them.
  CHECK(shorter_than_grid_optimum > 0);
}

TEST_CASE("a report of a database from before the measured times leaves its runs out of the anytime view",
          "[acobench][report]") {
  const auto file = experiment(
      "name: old\nrepetitions: 2\nproblems:\n  - {map: {MAP1}, start: [0, 0], goal: [19, 19]}\n"
      "settings: {ants: 5, iterations: 4}\n");
  const auto db = file.parent_path() / "old.db";
  REQUIRE(run_acobench({"run", file.string(), "--db", db.string()}).exit_code == 0);
  // What an acobench of format 3 wrote: no walks column (and estimated times).
  downgrade_to_format_6(db);
  sqlite3* handle = nullptr;
  REQUIRE(sqlite3_open(db.c_str(), &handle) == SQLITE_OK);
  CHECK(sqlite3_exec(handle,
                     "ALTER TABLE progress DROP COLUMN walks; UPDATE acobench_meta SET value = '3' WHERE key = "
                     "'format_version'",
                     nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(handle);
  const auto out = file.parent_path() / "report";
  const auto report = run_acobench({"report", db.string(), "--out", out.string()});
  INFO(report.err);
  REQUIRE(report.exit_code == 0);
  const std::string md = file_bytes(out / "report.md"), html = file_bytes(out / "report.html");
  CHECK_THAT(md, Contains("## Anytime: fixed targets") &&
                     Contains("2 runs stored by an older acobench (format 3 or earlier) have no measured times"));
  CHECK(count_of(html, "class=\"anytime\"") == 0);
  CHECK(count_of(html, "class=\"ecdf\"") == 0);
  CHECK_THAT(html, Contains("class=\"convergence\""));  // the per-iteration view is still there
  // Reading it for the report brought it to the current format.
  CHECK(aco::studies::ResultsDb(db).meta("format_version") == "7");
}

TEST_CASE("a problem written as a single value is refused with the problem format, not yaml-cpp's exception",
          "[acobench][bad-input]") {
  // Found by the experiment fuzz harness (tests/fuzz/regressions/experiment/scalar_problem_found).
  REQUIRE_THROWS_AS(load("name: x\nproblems:\n  - 'scen: map1.txt.scen, name: map1}'\nbaseline: {name: b}\n"),
                    aco::Error);
  REQUIRE_THROWS_WITH(load("name: x\nproblems:\n  - 'scen: map1.txt.scen, name: map1}'\nbaseline: {name: b}\n"),
                      Contains("experiment.yaml:3: a problem is a mapping"));
}

// Every experiment the project ships must load: each configuration resolved over each problem
// (for a simulation problem, over the scenario's own keys), as `acobench run` does before a trial.
TEST_CASE("every bundled experiment file loads and resolves each configuration over each problem", "[acobench]") {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::data_dir() / "experiments")) {
    if (entry.path().extension() != ".yaml") continue;
    INFO(entry.path().string());
    ++files;
    const auto e = aco::studies::load_experiment(entry.path(), test::plugins());
    CHECK(e.configurations.size() >= 1);
    // No configuration of ours compares a run with itself (acobench would warn).
    CHECK(e.same_runs().empty());
  }
  CHECK(files >= 10);
}

TEST_CASE("a simulation experiment has one fingerprint whichever path names it", "[acobench]") {
  // acobench's worker processes load the experiment by its absolute path; the scenario's map in
  // each configuration's run must not make that another experiment than the parent's (it did:
  // `acobench run data/experiments/dwa.yaml` from the root was refused by its workers).
  const auto file = test::data_dir() / "experiments" / "dwa.yaml";
  const auto before = std::filesystem::current_path();
  std::filesystem::current_path(test::data_dir().parent_path());
  const auto relative = aco::studies::load_experiment("data/experiments/dwa.yaml", test::plugins());
  std::filesystem::current_path(before);
  const auto absolute = aco::studies::load_experiment(std::filesystem::absolute(file), test::plugins());
  CHECK(relative.fingerprint(test::plugins()) == absolute.fingerprint(test::plugins()));
}

TEST_CASE("an experiment's problem in a voxel world names voxels, and 2D problems keep their fingerprint",
          "[acobench][voxel]") {
  const std::string simple = (test::data_dir() / "maps/voxel/warframe/Simple.3dmap").string();
  const std::string problems = "name: voxels\nproblems:\n  - {name: list, map: " + simple +
                               ", start: [56, 76, 52], goal: [48, 85, 45]}\n  - {name: text, map: " + simple +
                               ", start: '56,76,52', goal: '48,85,0'}\n";
  const auto e = load(problems + "baseline: {name: b, iterations: 2}\n");
  REQUIRE(e.problems.size() == 2);
  CHECK(e.problems[0].start == aco::Cell{56, 76, 52});
  CHECK(e.problems[1].start == aco::Cell{56, 76, 52});
  CHECK(e.problems[1].goal == aco::Cell{48, 85, 0});
  // z where it is not 0; a 2D problem's cells as stored before voxel worlds.
  const std::string fingerprint = e.fingerprint(test::plugins());
  CHECK_THAT(fingerprint,
             Contains("\"start\":[56,76,52]") && Contains("\"goal\":[48,85,45]") && Contains("\"goal\":[48,85],"));
  CHECK_THAT(load(kSmall).fingerprint(test::plugins()), Contains("\"goal\":[19,19]") && Contains("\"start\":[0,0]"));
  // No run plans both: a voxel world takes 6, 18 or 26 moves, a 2D map 4, 8 or 16.
  CHECK_THROWS_WITH(load(problems + "  - {map: " + map1() + ", start: [0, 0], goal: [19, 19]}\nbaseline: {name: b}\n"),
                    Contains("the problems mix voxel worlds and 2D maps"));
  CHECK_THROWS_WITH(load("name: x\nproblems:\n  - {map: " + map1() +
                         ", start: [0, 0, 0, 1], goal: [1, 1]}\n"
                         "baseline: {name: b}\n"),
                    Contains("'start' must be a cell [x, y]"));
  // A voxel world's cell without its z, and a 2D map's with one, are refused, not read as layer 0.
  CHECK_THROWS_WITH(load("name: x\nproblems:\n  - {map: " + simple + ", start: [56, 76], goal: [48, 85, 45]}\n" +
                         "baseline: {name: b}\n"),
                    Contains("'start' has no z, but the problem's map is a voxel world: give its cells as [x, y, z]"));
  CHECK_THROWS_WITH(load("name: x\nproblems:\n  - {map: " + simple + ", start: [56, 76, 52], goal: '48,85'}\n" +
                         "baseline: {name: b}\n"),
                    Contains("'goal' has no z"));
  CHECK_THROWS_WITH(load("name: x\nproblems:\n  - {map: " + map1() + ", start: [0, 0, 0], goal: [19, 19]}\n" +
                         "baseline: {name: b}\n"),
                    Contains("'start' has a z, but the problem's map is a 2D map: give its cells as [x, y]"));
}
