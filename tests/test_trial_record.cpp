// The trial record's field table: every field reaches the messages, the runs table, runs.csv
// (and Python, python/tests/test_studies.py) from the table alone.
#include <catch2/catch.hpp>

#include <sqlite3.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "aco/studies/results_db.hpp"
#include "aco/studies/trial_record.hpp"
#include "aco/studies/trial_runner.hpp"
#include "support.hpp"
#include "trial_messages.hpp"

namespace fs = std::filesystem;

namespace {

const std::vector<aco::studies::ProblemRecord> kProblems{{"map1", R"({"map":"map1.txt"})", 28.5}};

// A value of `type` that no field has by default and that tells fields apart.
aco::studies::TrialCell sample(aco::studies::TrialCellType type, int index) {
  switch (type) {
    case aco::studies::TrialCellType::boolean:
      return true;
    case aco::studies::TrialCellType::integer:
      return std::int64_t{100 + index};
    case aco::studies::TrialCellType::count:
      return std::uint64_t{0x8000'0000'0000'0000ULL} + static_cast<std::uint64_t>(index);
    case aco::studies::TrialCellType::real:
      return 30.25 + index;
    case aco::studies::TrialCellType::text:
      break;
  }
  return "[\"field, " + std::to_string(index) + "\"]";  // valid JSON (the path must be), with a comma
}

// A trial whose every field that can be set holds a sample, set through the table alone.
aco::studies::TrialRecord sample_trial(int config) {
  aco::studies::TrialRecord t;
  t.config = config;
  const auto& fields = aco::studies::trial_fields();
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].set)
      fields[i].set(t, fields[i].values.empty()
                           ? sample(fields[i].type, static_cast<int>(i))
                           : aco::studies::TrialCell(fields[i].values[i % fields[i].values.size()]));
  t.best_so_far.assign(static_cast<std::size_t>(t.iterations), 40.0);
  t.properties = {
      {"ant_steps", std::int64_t{7}}, {"stopped_by", std::string("time")}, {"update/x.restarts", std::int64_t{2}}};
  return t;
}

// A table's columns and their declared types.
std::map<std::string, std::string> table_columns(const fs::path& file, const std::string& table = "runs") {
  sqlite3* raw = nullptr;
  REQUIRE(sqlite3_open_v2(file.c_str(), &raw, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
  std::unique_ptr<sqlite3, decltype(&sqlite3_close)> db(raw, sqlite3_close);
  sqlite3_stmt* raw_statement = nullptr;
  const std::string sql = "SELECT name, type FROM pragma_table_info('" + table + "')";
  REQUIRE(sqlite3_prepare_v2(raw, sql.c_str(), -1, &raw_statement, nullptr) == SQLITE_OK);
  std::unique_ptr<sqlite3_stmt, decltype(&sqlite3_finalize)> statement(raw_statement, sqlite3_finalize);
  std::map<std::string, std::string> columns;
  while (sqlite3_step(raw_statement) == SQLITE_ROW)
    columns[reinterpret_cast<const char*>(sqlite3_column_text(raw_statement, 0))] =
        reinterpret_cast<const char*>(sqlite3_column_text(raw_statement, 1));
  return columns;
}

bool has_column(const fs::path& file, const std::string& name) { return table_columns(file).contains(name); }

std::vector<std::string> csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (const char c : line) {
    if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      cells.push_back(std::exchange(cell, ""));
    else
      cell += c;
  }
  cells.push_back(cell);
  return cells;
}

}  // namespace

TEST_CASE("every trial field reaches the messages, the runs table and runs.csv from the table alone", "[trialrecord]") {
  const fs::path file = test::temp_file("unused", "").parent_path() / "fields.db";
  aco::studies::ResultsDb db(file, "fields", "fingerprint", kProblems);
  const aco::studies::TrialRecord trial = sample_trial(db.add_config({"mine", "{}"}));
  db.store(trial);
  const aco::studies::TrialRecord sent = aco::studies::record_from(aco::studies::record_json(trial));
  const aco::studies::TrialRecord stored = db.trials().at(0);
  const auto columns = table_columns(file), texts = table_columns(file, "run_texts");

  std::istringstream csv(aco::studies::runs_csv({trial}, kProblems, db.configs()));
  std::string header_line, row_line;
  std::getline(csv, header_line);
  std::getline(csv, row_line);
  const auto header = csv_line(header_line), row = csv_line(row_line);
  REQUIRE(header.size() == row.size());
  CHECK(header.back() == "update/x.restarts");  // ant_steps and stopped_by are fields: no second column

  const double optimal = kProblems[0].optimal_length;
  for (const auto& f : aco::studies::trial_fields()) {
    INFO("field " << f.name);
    const aco::studies::TrialCell value = f.get(trial, optimal);
    CHECK_FALSE(std::holds_alternative<std::monostate>(value));
    CHECK(bool(f.use & aco::studies::kInMessage) == bool(f.set));  // a derived field is not sent
    if (f.use & aco::studies::kInMessage) CHECK(f.get(sent, optimal) == value);
    CHECK(columns.contains(f.stored_as) == bool(f.use & aco::studies::kInRunsTable));
    CHECK(texts.contains(f.stored_as) == bool(f.use & aco::studies::kInRunTexts));
    if ((f.use & (aco::studies::kInRunsTable | aco::studies::kInRunTexts)) && f.set)
      CHECK(f.get(stored, optimal) == value);
    // OMPL's types: its script plots BOOLEAN, ENUM, INTEGER and REAL columns, and an identity is none of them.
    if (columns.contains(f.stored_as)) {
      const std::string type = columns.at(f.stored_as);
      if (!f.values.empty())
        CHECK(type == "ENUM");
      else if (!f.measure)
        CHECK(type == "INT");
      else
        CHECK((type == "BOOLEAN" || type == "INTEGER" || type == "REAL"));
    }
    const auto at = std::find(header.begin(), header.end(), f.column);
    CHECK((at != header.end()) == bool(f.use & aco::studies::kInRunsCsv));
    if (at != header.end()) CHECK_FALSE(row[static_cast<std::size_t>(at - header.begin())].empty());
  }
  CHECK(header == [] {
    auto names = aco::studies::runs_csv_columns();
    names.push_back("update/x.restarts");
    return names;
  }());
}

TEST_CASE("a database made before a field was added gains its column, NULL for its runs, and resumes",
          "[trialrecord]") {
  const fs::path file = test::temp_file("unused", "").parent_path() / "older.db";
  // The newest field read back from a column every database has.
  const auto& fields = aco::studies::trial_fields();
  const auto& newest = *std::find_if(fields.rbegin(), fields.rend(), [](const aco::studies::TrialField& f) {
    return (f.use & aco::studies::kInRunsTable) && !(f.use & aco::studies::kWhenUsed) && f.set;
  });
  int config = 0;
  {
    aco::studies::ResultsDb db(file, "older", "fingerprint", kProblems);
    config = db.add_config({"mine", "{}"});
    db.store(sample_trial(config));
  }
  {
    sqlite3* raw = nullptr;
    REQUIRE(sqlite3_open_v2(file.c_str(), &raw, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK);
    std::unique_ptr<sqlite3, decltype(&sqlite3_close)> db(raw, sqlite3_close);
    const std::string drop = std::string("ALTER TABLE runs DROP COLUMN ") + newest.stored_as;
    REQUIRE(sqlite3_exec(raw, drop.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK);
  }
  REQUIRE_FALSE(has_column(file, newest.stored_as));

  const aco::studies::ResultsDb report(file);  // a report reads it
  CHECK(has_column(file, newest.stored_as));
  CHECK(report.meta("format_version") == "7");  // an older acobench reads it still
  CHECK(std::holds_alternative<std::monostate>(newest.get(report.trials().at(0), -1)));

  aco::studies::ResultsDb resumed(file, "older", "fingerprint", kProblems);
  auto next = sample_trial(config);
  next.repetition += 1;
  resumed.store(next);
  const auto trials = resumed.trials();
  REQUIRE(trials.size() == 2);
  CHECK(newest.get(trials[1], -1) == newest.get(next, -1));
}

TEST_CASE("a failure's kind is an enum in C++ and its text at the edges", "[trialrecord]") {
  using aco::studies::FailureKind;
  for (FailureKind kind : {FailureKind::none, FailureKind::crashed, FailureKind::timed_out, FailureKind::out_of_memory,
                           FailureKind::plugin_error, FailureKind::invalid_value, FailureKind::error})
    CHECK(aco::studies::failure_kind(aco::studies::to_string(kind)) == kind);
  CHECK(std::string(aco::studies::to_string(FailureKind::timed_out)) == "timed out");
  CHECK_THROWS_WITH(aco::studies::failure_kind("exploded"),
                    Catch::Matchers::Contains("unknown failure 'exploded'") &&
                        Catch::Matchers::Contains("'crashed', 'timed out', 'out of memory'"));
}
