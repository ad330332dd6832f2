#pragma once
// The results database's layout (results_db.hpp says what each table holds): its format version,
// the tables' definitions, the runs columns made from the trial fields (trial_record.hpp), and how
// a field's value is stored in its column.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "aco/studies/trial_record.hpp"
#include "sqlite.hpp"

namespace aco::studies {

// Bumped whenever the tables change in a way older readers would misread.
// 2: the simulation columns of runs; 3: runs.error; 4: progress.walks, progress.time measured;
// 5: runs.failure; 6: the properties table, plannerConfigs.plugins; 7: OMPL's layout (ENUMs,
// OMPL's column names, run_texts, plannerPlugins, the experiments' limits).
inline const std::string kFormatVersion = "7";

// Every table of a new database but properties (kPropertiesTable).
std::string schema();
// The runs table (named `table`) with the field columns but those added when used, and the
// columns in `with`.
std::string runs_table(const std::string& table, const std::set<std::string>& with = {});
std::string run_texts_table();
extern const char* const kPlannerPluginsTable;
extern const char* const kPropertiesTable;

// The rows acobench wrote, not those of OMPL logs appended by ompl_benchmark_statistics -a:
// experiments whose version is ours, planner configurations whose settings are JSON.
inline constexpr const char* kOurs = "version LIKE 'aco %'";
inline constexpr const char* kOurConfigs = "json_valid(settings)";

// The fields of a table (kInRunsTable or kInRunTexts); `read_back`: only those a record is read
// from, not the derived ones.
std::vector<const TrialField*> fields_in(unsigned table, bool read_back = false);
// ", name, name..." of the fields' columns.
std::string column_names(const std::vector<const TrialField*>& fields);
// "name TYPE", as ALTER TABLE ADD COLUMN takes it.
std::string column_definition(const TrialField& f);
// The declared type: OMPL's script plots the columns declared BOOLEAN, ENUM, INTEGER or REAL.
std::string sql_type(const TrialField& f);
// The columns added when used that the trial has a value for.
std::vector<const TrialField*> used_columns(const TrialRecord& t);

// A field's value as its column holds it: an ENUM's index (an Error for a value the ENUM lacks).
TrialCell to_column(const TrialField& f, TrialCell value);
// What is wrong with the value of `field` in a column of `row`, or nothing when it is what the
// field declares (trial_record.hpp): of its type (a real: a finite number; an integer: within
// its member's type; an ENUM: one of its indices), not below its least value, NULL only where allowed
// (unless_solved: pass whether the row is solved).
std::optional<std::string> stored_value_problem(const sqlite::Statement& row, int column, const TrialField& field,
                                                bool solved);
// The value of `field` in a column of `row` that stored_value_problem() found right: an ENUM's
// index is its value's text.
TrialCell from_column(const sqlite::Statement& row, int column, const TrialField& field);

}  // namespace aco::studies
