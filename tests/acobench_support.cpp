// Helpers of the acobench tests (acobench_support.hpp).
#include "acobench_support.hpp"

#include <catch2/catch.hpp>
#include <memory>

#include <sqlite3.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "aco/studies/results_db.hpp"

namespace test::acobench_helpers {

std::string map1() { return (test::data_dir() / "maps/classic20/map1.txt").string(); }

std::filesystem::path experiment(const std::string& text) {
  std::string yaml = text;
  for (const auto& [key, value] : {std::pair<std::string, std::string>{"{MAP1}", map1()},
                                   {"{ARENA}", (test::data_dir() / "maps/movingai/arena.map.scen").string()}})
    for (auto at = yaml.find(key); at != std::string::npos; at = yaml.find(key)) yaml.replace(at, key.size(), value);
  return test::temp_file("experiment.yaml", yaml);
}

aco::studies::Experiment load(const std::string& text) {
  return aco::studies::load_experiment(experiment(text), test::plugins());
}

const char* const kSmall = R"(name: small
seed: 7
repetitions: 4
problems:
  - map: {MAP1}
    start: [0, 0]
    goal: [19, 19]
settings:
  preset: ant-system
  ants: 10
  iterations: 15
  corner-cutting: true
baseline:
  name: AS
  update: {plugin: ant_system, rho: 0.3}
configurations:
  - name: ACS
    update: {plugin: acs, xi: 0.2}
    q0: 0.7
factorial:
  beta: [3, 7]
)";

std::string kill_me_text() {
  std::string text = kSmall;
  text.replace(text.find("repetitions: 4"), 14, "repetitions: 150");
  text.replace(text.find("ants: 10"), 8, "ants: 40");
  text.replace(text.find("iterations: 15"), 14, "iterations: 60");
  text.resize(text.find("factorial:"));
  return text;
}

void wait_for_trials(const std::filesystem::path& db, int count) {
  for (int i = 0; i < 60000; ++i) {
    if (std::filesystem::exists(db) && count_runs(db) >= count) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

test::CommandResult run_acobench(const std::vector<std::string>& args, const std::vector<std::string>& env) {
  std::vector<std::string> argv{ACO_TEST_ACOBENCH};
  argv.insert(argv.end(), args.begin(), args.end());
  return test::run(argv, env);
}

std::string file_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> trial_rows(const std::filesystem::path& db) {
  std::vector<std::string> rows;
  for (const auto& t : aco::studies::ResultsDb(db).trials()) {
    std::ostringstream row;
    row.precision(17);
    row << t.problem << " " << t.config << " " << t.repetition << " " << t.seed << " " << t.solved << " " << t.length
        << " " << t.best_iteration << " " << t.ant_steps << " " << t.path_json;
    for (double b : t.best_so_far) row << " " << b;
    row << " walks";
    for (auto w : t.walks) row << " " << w;
    rows.push_back(row.str());
  }
  return rows;
}

namespace {

// Every row of a query, its columns as text (reals with all their digits), sorted.
std::vector<std::string> query_rows(sqlite3* handle, const std::string& sql) {
  std::vector<std::string> rows;
  sqlite3_stmt* statement = nullptr;
  if (sqlite3_prepare_v2(handle, sql.c_str(), -1, &statement, nullptr) != SQLITE_OK)
    throw std::runtime_error(std::string("cannot query ") + sql + ": " + sqlite3_errmsg(handle));
  while (sqlite3_step(statement) == SQLITE_ROW) {
    std::ostringstream row;
    row.precision(17);
    for (int c = 0; c < sqlite3_column_count(statement); ++c) {
      switch (sqlite3_column_type(statement, c)) {
        case SQLITE_NULL:
          row << "NULL";
          break;
        case SQLITE_INTEGER:
          row << sqlite3_column_int64(statement, c);
          break;
        case SQLITE_FLOAT:
          row << sqlite3_column_double(statement, c);
          break;
        default:
          row << '"' << reinterpret_cast<const char*>(sqlite3_column_text(statement, c)) << '"';
      }
      row << '|';
    }
    rows.push_back(row.str());
  }
  sqlite3_finalize(statement);
  std::sort(rows.begin(), rows.end());
  return rows;
}

}  // namespace

std::vector<std::string> database_rows(const std::filesystem::path& db) {
  sqlite3* handle = nullptr;
  if (sqlite3_open_v2(db.c_str(), &handle, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
    sqlite3_close(handle);
    throw std::runtime_error("cannot open " + db.string());
  }
  const std::string trial = "e.name, c.name, r.repetition";
  // Every column of runs (those added when used included) but the ids and what a rerun measures
  // anew; memorylimit is each worker's share of the machine.
  std::string run_columns;
  for (const auto& row : query_rows(handle,
                                    "SELECT name FROM pragma_table_info('runs') WHERE name NOT IN "
                                    "('id', 'experimentid', 'plannerid', 'repetition', 'time', 'memory')"))
    run_columns += ", r." + row.substr(1, row.size() - 3);  // "name"| -> name
  std::vector<std::string> all;
  for (const std::string& sql : std::vector<std::string>{
           "SELECT 'problem', name, version, setup, optimal_length, timelimit, runcount, seed "
           "FROM experiments",
           "SELECT 'config', id, name, settings FROM plannerConfigs",
           "SELECT 'run', " + trial + run_columns +
               ", t.path, t.error FROM runs r JOIN experiments e ON e.id = r.experimentid "
               "JOIN plannerConfigs c ON c.id = r.plannerid LEFT JOIN run_texts t ON t.runid = r.id",
           "SELECT 'progress', " + trial +
               ", p.iteration, p.best_cost, p.walks FROM progress p JOIN runs r ON r.id = p.runid "
               "JOIN experiments e ON e.id = r.experimentid JOIN plannerConfigs c ON c.id = r.plannerid",
           "SELECT 'property', " + trial +
               ", p.name, p.value, typeof(p.value) FROM properties p JOIN runs r ON r.id = p.runid "
               "JOIN experiments e ON e.id = r.experimentid JOIN plannerConfigs c ON c.id = r.plannerid",
           "SELECT 'enum', name, value, description FROM enums",
           "SELECT 'meta', key, value FROM acobench_meta WHERE key NOT IN ('experiment_file', 'shard')"}) {
    const auto rows = query_rows(handle, sql);
    all.insert(all.end(), rows.begin(), rows.end());
  }
  sqlite3_close(handle);
  return all;
}

void downgrade_to_format_6(const std::filesystem::path& db) {
  sqlite3* handle = nullptr;
  if (sqlite3_open_v2(db.c_str(), &handle, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
    sqlite3_close(handle);
    throw std::runtime_error("cannot open " + db.string());
  }
  std::string sql = R"(
ALTER TABLE runs RENAME COLUMN trial_seed TO seed;
ALTER TABLE runs RENAME COLUMN solution_length TO length;
ALTER TABLE runs RENAME COLUMN memory TO peak_memory_mib;
ALTER TABLE runs DROP COLUMN status;
)";
  const auto columns = query_rows(handle, "SELECT name FROM pragma_table_info('runs')");
  const auto has = [&](const std::string& c) {
    return std::find(columns.begin(), columns.end(), '"' + c + "\"|") != columns.end();
  };
  for (const char* added : {"outcome TEXT", "time_to_goal REAL", "collisions INTEGER", "replans INTEGER",
                            "clearance REAL", "control_steps INTEGER", "failure TEXT"}) {
    const std::string name = std::string(added).substr(0, std::string(added).find(' '));
    if (!has(name)) sql += "ALTER TABLE runs ADD COLUMN " + std::string(added) + ";\n";
  }
  // Format 6 kept the text of what are ENUMs now.
  for (const char* text : {"stopped_by", "outcome", "failure"})
    sql += std::string("UPDATE runs SET ") + text + " = (SELECT description FROM enums WHERE name = '" + text +
           "' AND value = runs." + text + ");\n";
  sql += R"(
ALTER TABLE runs ADD COLUMN path TEXT;
ALTER TABLE runs ADD COLUMN error TEXT;
UPDATE runs SET path = (SELECT path FROM run_texts WHERE runid = runs.id),
  error = (SELECT error FROM run_texts WHERE runid = runs.id);
DROP TABLE run_texts;
ALTER TABLE plannerConfigs ADD COLUMN plugins TEXT;
UPDATE plannerConfigs SET plugins = (SELECT plugins FROM plannerPlugins WHERE plannerid = plannerConfigs.id);
DROP TABLE plannerPlugins;
DELETE FROM enums;
UPDATE experiments SET timelimit = NULL, memorylimit = NULL, runcount = NULL, seed = NULL;
ALTER TABLE experiments DROP COLUMN anyangle_length;
UPDATE acobench_meta SET value = '6' WHERE key = 'format_version';
)";
  char* error = nullptr;
  const int rc = sqlite3_exec(handle, sql.c_str(), nullptr, nullptr, &error);
  const std::string message = error ? error : "";
  sqlite3_free(error);
  sqlite3_close(handle);
  if (rc != SQLITE_OK) throw std::runtime_error("downgrading " + db.string() + ": " + message);
}

std::string sql_value(const std::filesystem::path& db, const std::string& sql) {
  sqlite3* handle = nullptr;
  std::string value = "(no row)";
  if (sqlite3_open_v2(db.c_str(), &handle, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK) {
    sqlite3_stmt* statement = nullptr;
    if (sqlite3_prepare_v2(handle, sql.c_str(), -1, &statement, nullptr) == SQLITE_OK &&
        sqlite3_step(statement) == SQLITE_ROW)
      value =
          sqlite3_column_text(statement, 0) ? reinterpret_cast<const char*>(sqlite3_column_text(statement, 0)) : "NULL";
    sqlite3_finalize(statement);
  }
  sqlite3_close(handle);
  return value;
}

void sql_exec(const std::filesystem::path& db, const std::string& sql) {
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(db.c_str(), &raw, SQLITE_OPEN_READWRITE, nullptr);
  std::unique_ptr<sqlite3, decltype(&sqlite3_close)> handle(raw, sqlite3_close);
  REQUIRE(rc == SQLITE_OK);
  INFO(sql << ": " << sqlite3_errmsg(raw));
  REQUIRE(sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
}

int count_runs(const std::filesystem::path& db) {
  const std::string count = sql_value(db, "SELECT count(*) FROM runs");
  return count == "(no row)" ? -1 : std::stoi(count);
}

#ifdef ACO_TEST_MPIEXEC
const std::vector<std::string> kMpiEnvironment{"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1",
                                               "OMPI_MCA_rmaps_base_oversubscribe=1"};

std::vector<std::string> mpirun(int ranks, const std::vector<std::string>& args) {
  std::vector<std::string> argv{ACO_TEST_MPIEXEC, "--oversubscribe", "-n", std::to_string(ranks), ACO_TEST_ACOBENCH};
  argv.insert(argv.end(), args.begin(), args.end());
  return argv;
}
#endif

}  // namespace test::acobench_helpers
