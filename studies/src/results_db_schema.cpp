#include "results_db_schema.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "aco/error.hpp"

namespace aco::studies {
namespace {

// A runs column holding the index of its value among the field's values (OMPL's ENUM).
bool is_enum(const TrialField& f) { return !f.values.empty() && (f.use & kInRunsTable); }

// The lines of a CREATE TABLE's columns: at most 100 characters, indented.
std::string wrapped(const std::vector<std::string>& columns) {
  std::string text, line;
  for (const auto& column : columns) {
    if (!line.empty() && line.size() + column.size() + 2 > 100) text += std::exchange(line, "") + "\n";
    line += (line.empty() ? "  " : " ") + column + ",";
  }
  return text + line + "\n";
}

}  // namespace

std::string sql_type(const TrialField& f) {
  if (is_enum(f)) return "ENUM";
  switch (f.type) {
    case TrialCellType::boolean:
      return "BOOLEAN";
    case TrialCellType::integer:
    case TrialCellType::count:
      return f.measure ? "INTEGER" : "INT";
    case TrialCellType::real:
      return "REAL";
    case TrialCellType::text:
      break;
  }
  return "TEXT";
}

std::vector<const TrialField*> fields_in(unsigned table, bool read_back) {
  std::vector<const TrialField*> fields;
  for (const auto& f : trial_fields())
    if ((f.use & table) && (f.set || !read_back)) fields.push_back(&f);
  return fields;
}

std::string column_names(const std::vector<const TrialField*>& fields) {
  std::string names;
  for (const TrialField* f : fields) names += std::string(", ") + f->stored_as;
  return names;
}

std::string column_definition(const TrialField& f) { return std::string(f.stored_as) + " " + sql_type(f); }

std::string runs_table(const std::string& table, const std::set<std::string>& with) {
  std::vector<std::string> columns;
  for (const TrialField* f : fields_in(kInRunsTable))
    if (!(f->use & kWhenUsed) || with.contains(f->stored_as)) columns.push_back(column_definition(*f));
  return "CREATE TABLE " + table +
         " (id INTEGER PRIMARY KEY AUTOINCREMENT, experimentid INTEGER, plannerid INTEGER,\n" + wrapped(columns) +
         R"(  FOREIGN KEY (experimentid) REFERENCES experiments(id) ON DELETE CASCADE,
  FOREIGN KEY (plannerid) REFERENCES plannerConfigs(id) ON DELETE CASCADE,
  UNIQUE (experimentid, plannerid, repetition));
)";
}

std::vector<const TrialField*> used_columns(const TrialRecord& t) {
  std::vector<const TrialField*> used;
  for (const TrialField* f : fields_in(kInRunsTable))
    if ((f->use & kWhenUsed) && !std::holds_alternative<std::monostate>(f->get(t, -1.0))) used.push_back(f);
  return used;
}

std::string run_texts_table() {
  std::vector<std::string> columns;
  for (const TrialField* f : fields_in(kInRunTexts)) columns.push_back(column_definition(*f));
  return "CREATE TABLE run_texts (runid INTEGER PRIMARY KEY,\n" + wrapped(columns) +
         "  FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);\n";
}

const char* const kPlannerPluginsTable = R"(
CREATE TABLE plannerPlugins (plannerid INTEGER PRIMARY KEY, plugins TEXT,
  FOREIGN KEY (plannerid) REFERENCES plannerConfigs(id) ON DELETE CASCADE);
)";

// OMPL's tables (as ompl_benchmark_statistics creates them, plannerConfigs with its three
// columns, which its -a fills by position) with our run and progress attributes as columns; see
// the header for what each holds.
std::string schema() {
  return R"(
CREATE TABLE experiments (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512), totaltime REAL,
  timelimit REAL, memorylimit REAL, runcount INTEGER, version VARCHAR(128), hostname VARCHAR(1024),
  cpuinfo TEXT, date DATETIME, seed VARCHAR(24), setup TEXT, optimal_length REAL, anyangle_length REAL);
CREATE TABLE plannerConfigs (id INTEGER PRIMARY KEY AUTOINCREMENT, name VARCHAR(512) NOT NULL, settings TEXT);
CREATE TABLE enums (name VARCHAR(512), value INTEGER, description TEXT, PRIMARY KEY (name, value));
)" + runs_table("runs") +
         run_texts_table() + kPlannerPluginsTable + R"(
CREATE TABLE progress (runid INTEGER, time REAL, iteration INTEGER, best_cost REAL, walks INTEGER,
  PRIMARY KEY (runid, iteration), FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);
CREATE TABLE acobench_meta (key TEXT PRIMARY KEY, value TEXT);
)";
}

// A generic name/value table per run, as OMPL's run properties but as rows, not columns: the
// planners' properties and the figures plugins record vary with the configuration. SQLite keeps
// each value's type (integer, real or text).
const char* const kPropertiesTable = R"(
CREATE TABLE properties (runid INTEGER, name TEXT NOT NULL, value, PRIMARY KEY (runid, name),
  FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);
)";

TrialCell to_column(const TrialField& f, TrialCell value) {
  if (!is_enum(f)) return value;
  const auto* text = std::get_if<std::string>(&value);
  if (!text) return value;
  const auto at = std::find(f.values.begin(), f.values.end(), *text);
  if (at == f.values.end()) {
    std::string known;
    for (const auto& v : f.values) known += (known.empty() ? "'" : ", '") + v + "'";
    throw Error(std::string("runs.") + f.stored_as + " cannot hold '" + *text + "' (its values: " + known + ")");
  }
  return static_cast<std::int64_t>(at - f.values.begin());
}

std::optional<std::string> stored_value_problem(const sqlite::Statement& row, int column, const TrialField& field,
                                                bool solved) {
  using Null = TrialField::Null;
  const int type = row.type(column);
  if (type == SQLITE_NULL) {
    if (field.null == Null::never) return "NULL, which it never is";
    if (field.null == Null::unless_solved && solved) return "NULL in a solved run";
    return std::nullopt;
  }
  if ((field.null == Null::unless_solved || field.null == Null::solved_only) && !solved)
    return row.shown(column) + " in an unsolved run (NULL there)";
  const auto wrong = [&](const std::string& wanted) { return row.shown(column) + ", not " + wanted; };
  if (is_enum(field)) {
    if (type != SQLITE_INTEGER) return wrong("the index of an ENUM value");
    const std::int64_t index = row.integer(column);
    if (index < 0 || index >= static_cast<std::int64_t>(field.values.size()))
      return row.shown(column) + ", which is not one of its " + std::to_string(field.values.size()) + " ENUM values";
    return std::nullopt;
  }
  double value = 0;
  switch (field.type) {
    case TrialCellType::text:
      return type == SQLITE_TEXT ? std::nullopt : std::optional(wrong("text"));
    case TrialCellType::boolean:
      return type == SQLITE_INTEGER && (row.integer(column) == 0 || row.integer(column) == 1)
                 ? std::nullopt
                 : std::optional(wrong("0 or 1"));
    case TrialCellType::count:
      return type == SQLITE_INTEGER ? std::nullopt : std::optional(wrong("a whole number"));
    case TrialCellType::integer:
      if (type != SQLITE_INTEGER || row.integer(column) < std::numeric_limits<int>::min() ||
          row.integer(column) > std::numeric_limits<int>::max())
        return wrong("a whole number of 32 bits");
      value = static_cast<double>(row.integer(column));
      break;
    case TrialCellType::real:
      if (type != SQLITE_FLOAT && type != SQLITE_INTEGER) return wrong("a number");
      value = row.real(column);
      if (!std::isfinite(value)) return wrong("a finite number");
      break;
  }
  if (value < field.low) return row.shown(column) + ", below its least value " + aco::to_string(ParamValue(field.low));
  return std::nullopt;
}

TrialCell from_column(const sqlite::Statement& row, int column, const TrialField& field) {
  if (!is_enum(field) || row.null(column)) return row.cell(column, field.type);
  return field.values[static_cast<std::size_t>(row.integer(column))];
}

}  // namespace aco::studies
