#include "aco/studies/results_db.hpp"

#include <sqlite3.h>

#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <utility>

#include "aco/error.hpp"
#include "aco/machine.hpp"
#include "aco/studies/growth.hpp"

namespace aco::studies {
namespace {

using aco::Error;

// Bumped whenever the tables change in a way older readers would misread.
// 2: the simulation columns of runs; 3: runs.error; 4: progress.walks, progress.time measured;
// 5: runs.failure; 6: the properties table, plannerConfigs.plugins; 7: OMPL's layout (ENUMs,
// OMPL's column names, run_texts, plannerPlugins, the experiments' limits).
const std::string kFormatVersion = "7";

// This version, or an earlier one upgrade() brings to it.
bool upgradable(const std::string& version) {
  for (const char* v : {"1", "2", "3", "4", "5", "6"})
    if (version == v) return true;
  return version == kFormatVersion;
}

// A runs column holding the index of its value among the field's values (OMPL's ENUM).
bool is_enum(const TrialField& f) { return !f.values.empty() && (f.use & kInRunsTable); }

// The declared type: OMPL's script plots the columns declared BOOLEAN, ENUM, INTEGER or REAL.
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

// The fields of a table (kInRunsTable or kInRunTexts); `read_back`: only those a record is read
// from, not the derived ones.
std::vector<const TrialField*> fields_in(unsigned table, bool read_back = false) {
  std::vector<const TrialField*> fields;
  for (const auto& f : trial_fields())
    if ((f.use & table) && (f.set || !read_back)) fields.push_back(&f);
  return fields;
}

// ", name, name..." of the fields' columns.
std::string column_names(const std::vector<const TrialField*>& fields) {
  std::string names;
  for (const TrialField* f : fields) names += std::string(", ") + f->stored_as;
  return names;
}

std::string column_definition(const TrialField& f) { return std::string(f.stored_as) + " " + sql_type(f); }

// The lines of a CREATE TABLE's columns: at most 100 characters, indented.
std::string wrapped(const std::vector<std::string>& columns) {
  std::string text, line;
  for (const auto& column : columns) {
    if (!line.empty() && line.size() + column.size() + 2 > 100) text += std::exchange(line, "") + "\n";
    line += (line.empty() ? "  " : " ") + column + ",";
  }
  return text + line + "\n";
}

// The runs table (named `table`) with the field columns but those added when used, and the
// columns in `with`.
std::string runs_table(const std::string& table, const std::set<std::string>& with = {}) {
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

// The columns added when used that the trial has a value for.
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

// A field's value as its column holds it: an ENUM's index.
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

// A generic name/value table per run, as OMPL's run properties but as rows, not columns: the
// planners' properties and the figures plugins record vary with the configuration. SQLite keeps
// each value's type (integer, real or text).
const char* const kPropertiesTable = R"(
CREATE TABLE properties (runid INTEGER, name TEXT NOT NULL, value, PRIMARY KEY (runid, name),
  FOREIGN KEY (runid) REFERENCES runs(id) ON DELETE CASCADE);
)";

// 64-bit unsigned values keep their bits in SQLite's signed integers.
std::int64_t to_sql(std::uint64_t v) { return std::bit_cast<std::int64_t>(v); }
std::uint64_t from_sql(std::int64_t v) { return std::bit_cast<std::uint64_t>(v); }

// One connection; every failure becomes an Error naming the file and SQLite's reason.
class Connection {
 public:
  explicit Connection(const std::filesystem::path& file) : file_(file.string()) {
    const int rc = sqlite3_open_v2(file_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    if (rc != SQLITE_OK) {
      const std::string reason = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
      sqlite3_close(db_);
      throw Error("cannot open results database " + file_ + ": " + reason);
    }
  }
  ~Connection() { sqlite3_close(db_); }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  void check(int rc, const std::string& doing) const {
    if (rc != SQLITE_OK && rc != SQLITE_ROW && rc != SQLITE_DONE)
      throw Error("results database " + file_ + ": " + doing + ": " + sqlite3_errmsg(db_));
  }
  void exec(const std::string& sql) { check(sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr), sql); }

  sqlite3* handle() const { return db_; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  sqlite3* db_ = nullptr;
};

// A prepared statement, reset before each use so it can be kept and reused.
class Statement {
 public:
  Statement(const Connection& db, std::string sql) : db_(db), sql_(std::move(sql)) {
    db_.check(sqlite3_prepare_v3(db_.handle(), sql_.c_str(), -1, SQLITE_PREPARE_PERSISTENT, &stmt_, nullptr),
              "preparing " + sql_);
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  // Starts a new execution with these parameters (?1, ?2, ...).
  template <class... Values>
  Statement& run(const Values&... values) {
    sqlite3_reset(stmt_);
    db_.check(sqlite3_clear_bindings(stmt_), sql_);
    int index = 0;
    (bind(++index, values), ...);
    return *this;
  }
  // The next row: true if there is one, false when done.
  bool next() {
    const int rc = sqlite3_step(stmt_);
    db_.check(rc, sql_);
    return rc == SQLITE_ROW;
  }
  // Binds `cells` to the parameters from `first` on, after those run() bound.
  Statement& and_cells(int first, const std::vector<TrialCell>& cells) {
    for (const auto& cell : cells) bind(first++, cell);
    return *this;
  }
  void finish() {
    while (next()) {}
  }
  // Whether the statement yields a row; reset at once so it holds no read open.
  bool any() {
    const bool found = next();
    sqlite3_reset(stmt_);
    return found;
  }

  bool null(int column) const { return sqlite3_column_type(stmt_, column) == SQLITE_NULL; }
  // A value of a column without a declared type, as SQLite stored it.
  aco::ParamValue value(int column) const {
    switch (sqlite3_column_type(stmt_, column)) {
      case SQLITE_INTEGER:
        return integer(column);
      case SQLITE_FLOAT:
        return real(column);
      default:
        return text(column);
    }
  }
  // A column holding a trial field of `type`.
  TrialCell cell(int column, TrialCellType type) const {
    if (null(column)) return {};
    switch (type) {
      case TrialCellType::boolean:
        return integer(column) != 0;
      case TrialCellType::integer:
        return integer(column);
      case TrialCellType::count:
        return from_sql(integer(column));
      case TrialCellType::real:
        return real(column);
      case TrialCellType::text:
        break;
    }
    return text(column);
  }
  // A column holding `field`: an ENUM's index is its value's text.
  TrialCell cell(int column, const TrialField& field) const {
    if (!is_enum(field) || null(column)) return cell(column, field.type);
    const std::int64_t index = integer(column);
    if (index < 0 || index >= static_cast<std::int64_t>(field.values.size()))
      throw Error("results database " + db_.file() + ": runs." + field.stored_as + " holds " + std::to_string(index) +
                  ", which is not one of its " + std::to_string(field.values.size()) + " ENUM values");
    return field.values[static_cast<std::size_t>(index)];
  }
  std::int64_t integer(int column) const { return sqlite3_column_int64(stmt_, column); }
  double real(int column) const { return sqlite3_column_double(stmt_, column); }
  std::string text(int column) const {
    const auto* bytes = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
    return bytes ? std::string(bytes, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column))) : std::string();
  }

 private:
  void bind(int i, std::int64_t v) { db_.check(sqlite3_bind_int64(stmt_, i, v), sql_); }
  void bind(int i, int v) { bind(i, static_cast<std::int64_t>(v)); }
  void bind(int i, bool v) { bind(i, static_cast<std::int64_t>(v)); }
  void bind(int i, double v) {
    db_.check(std::isnan(v) ? sqlite3_bind_null(stmt_, i) : sqlite3_bind_double(stmt_, i, v), sql_);
  }
  void bind(int i, const std::string& v) {
    db_.check(sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT), sql_);
  }
  void bind(int i, std::uint64_t v) { bind(i, to_sql(v)); }
  void bind(int i, std::monostate) { db_.check(sqlite3_bind_null(stmt_, i), sql_); }
  void bind(int i, const TrialCell& v) {
    std::visit([&](const auto& value) { bind(i, value); }, v);
  }
  template <class T>
  void bind(int i, const std::optional<T>& v) {
    if (v)
      bind(i, *v);
    else
      db_.check(sqlite3_bind_null(stmt_, i), sql_);
  }

  const Connection& db_;
  std::string sql_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN IMMEDIATE takes the write lock at once, so a check and the write it guards are atomic
// even against another process. Rolled back unless committed.
class Transaction {
 public:
  explicit Transaction(Connection& db) : db_(db) { db_.exec("BEGIN IMMEDIATE"); }
  ~Transaction() {
    if (!committed_) sqlite3_exec(db_.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit() {
    db_.exec("COMMIT");
    committed_ = true;
  }

 private:
  Connection& db_;
  bool committed_ = false;
};

// The rows acobench wrote, not those of OMPL logs appended by ompl_benchmark_statistics -a:
// experiments whose version is ours, planner configurations whose settings are JSON.
constexpr const char* kOurs = "version LIKE 'aco %'";
constexpr const char* kOurConfigs = "json_valid(settings)";

// A real that binds as SQL NULL.
constexpr double kNull = std::numeric_limits<double>::quiet_NaN();

double finite_or_null(double v) { return std::isfinite(v) ? v : kNull; }

nlohmann::json parse_json(const std::string& text, const std::string& what) {
  auto value = nlohmann::json::parse(text, nullptr, false);
  if (value.is_discarded()) throw Error(what + " is not valid JSON: " + text.substr(0, 200));
  return value;
}

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

const TrialField& failure_field() {
  for (const auto& f : trial_fields())
    if (std::string_view(f.name) == "failure") return f;
  throw Error("no trial field 'failure'");
}

// Opening would create a missing file: a report of a mistyped name must not.
const std::filesystem::path& existing(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) throw Error(file.string() + ": no such results database");
  return file;
}

// Bad problems are refused before opening, which would create the file.
const std::filesystem::path& checked_before_opening(const std::filesystem::path& file,
                                                    const std::vector<ProblemRecord>& problems) {
  for (const auto& p : problems) parse_json(p.setup_json, "the setup of problem " + in_quotes(p.name));
  return file;
}

}  // namespace

struct ResultsDb::Impl {
  explicit Impl(const std::filesystem::path& file) : db(file) {}

  Connection db;
  mutable std::mutex mutex;
  std::vector<std::int64_t> experiment_ids;  // by problem index
  std::map<std::int64_t, int> problem_of;  // by experiment id
  std::vector<ProblemRecord> problems;
  std::map<int, std::string> config_names;  // by id
  std::optional<Statement> find_run, insert_run, insert_text, insert_progress, insert_property, add_time;
  // The runs columns insert_run fills: those the table has (a column added when used may not be there).
  std::vector<const TrialField*> run_columns;

  std::string file() const { return db.file(); }
  // The problems (`given`, in their order, or all stored ones), configurations and statements of
  // an opened database.
  void load(const std::vector<ProblemRecord>* given);
  Growth growth;  // what the experiment added to the database when it was opened

  std::set<std::string> tables() {
    std::set<std::string> names;
    Statement list(db, "SELECT name FROM sqlite_master WHERE type = 'table'");
    list.run();
    while (list.next()) names.insert(list.text(0));
    return names;
  }

  std::map<std::string, std::string> meta() {
    std::map<std::string, std::string> values;
    Statement read(db, "SELECT key, value FROM acobench_meta");
    read.run();
    while (read.next()) values[read.text(0)] = read.text(1);
    return values;
  }

  std::vector<ProblemRecord> stored_problems() {
    std::vector<ProblemRecord> stored;
    // Read before an older format is upgraded (to check the file is the experiment's).
    const std::string any_angle = columns_of("experiments").contains("anyangle_length") ? "anyangle_length" : "NULL";
    Statement read(db, "SELECT name, setup, optimal_length, " + any_angle + " FROM experiments WHERE " +
                           std::string(kOurs) + " ORDER BY id");
    read.run();
    while (read.next())
      stored.push_back(
          {read.text(0), read.text(1), read.null(2) ? -1.0 : read.real(2), read.null(3) ? -1.0 : read.real(3)});
    return stored;
  }

  std::set<std::string> columns_of(const std::string& table) {
    std::set<std::string> present;
    Statement columns(db, "SELECT name FROM pragma_table_info('" + table + "')");
    columns.run();
    while (columns.next()) present.insert(columns.text(0));
    return present;
  }

  // The fields of the runs table whose columns it has now.
  std::vector<const TrialField*> present_run_fields(bool read_back) {
    const auto present = columns_of("runs");
    std::vector<const TrialField*> fields;
    for (const TrialField* f : fields_in(kInRunsTable, read_back))
      if (present.contains(f->stored_as)) fields.push_back(f);
    return fields;
  }

  // Prepares the INSERT of a runs row (?1 its id, NULL for a new one) for the columns there are.
  void prepare_insert_run() {
    run_columns = present_run_fields(false);
    std::string parameters = "?1, ?2, ?3";  // id, experimentid, plannerid
    for (std::size_t i = 0; i < run_columns.size(); ++i) parameters += ", ?" + std::to_string(4 + i);
    insert_run.emplace(db, "INSERT INTO runs (id, experimentid, plannerid" + column_names(run_columns) + ") VALUES (" +
                               parameters + ")");
    const auto texts = fields_in(kInRunTexts);
    parameters = "?1";
    for (std::size_t i = 0; i < texts.size(); ++i) parameters += ", ?" + std::to_string(2 + i);
    insert_text.emplace(db, "INSERT INTO run_texts (runid" + column_names(texts) + ") VALUES (" + parameters + ")");
  }

  // A trial's runs row and its run_texts row (if it has a text); `id` nullopt: a new row. The id.
  std::int64_t insert_trial(std::optional<std::int64_t> id, std::int64_t experiment, std::int64_t planner,
                            const TrialRecord& t, double optimal_length) {
    std::vector<TrialCell> cells;
    for (const TrialField* f : run_columns) cells.push_back(to_column(*f, f->get(t, optimal_length)));
    insert_run->run(id, experiment, planner).and_cells(4, cells).finish();
    const std::int64_t run = sqlite3_last_insert_rowid(db.handle());
    std::vector<TrialCell> texts;
    for (const TrialField* f : fields_in(kInRunTexts)) texts.push_back(f->get(t, optimal_length));
    if (std::any_of(texts.begin(), texts.end(),
                    [](const TrialCell& c) { return !std::holds_alternative<std::monostate>(c); }))
      insert_text->run(run).and_cells(2, texts).finish();
    return run;
  }

  // The columns added when used that the trial has a value for: added if missing (in the
  // caller's transaction), and the INSERT prepared again.
  void add_used_columns(const TrialRecord& t) {
    const auto used = used_columns(t);
    if (used.empty()) return;
    const auto present = columns_of("runs");
    bool added = false;
    for (const TrialField* f : used)
      if (!present.contains(f->stored_as)) {
        db.exec("ALTER TABLE runs ADD COLUMN " + column_definition(*f));
        added = true;
      }
    // Another process may have added them: the statement is prepared whenever it lacks one.
    if (added || run_columns.size() != present_run_fields(false).size()) prepare_insert_run();
  }

  // The rows describing every ENUM column's values (OMPL's -a adds its own only for names it
  // does not find).
  void add_enums() {
    Statement add(db, "INSERT OR IGNORE INTO enums (name, value, description) VALUES (?1, ?2, ?3)");
    for (const TrialField* f : fields_in(kInRunsTable))
      for (std::size_t i = 0; i < f->values.size(); ++i)
        add.run(std::string(f->stored_as), static_cast<std::int64_t>(i), f->values[i]).finish();
  }

  // Older formats are brought to format 6, then migrated to 7, in one transaction. A trial
  // field's column that a database of format 7 lacks (one made before the field was added) is
  // added, NULL for the stored runs: an older acobench of format 7 still reads and continues the
  // database (leaving the column NULL), so the format version stays.
  void upgrade() {
    const std::string version = meta().at("format_version");
    if (version != kFormatVersion) {
      Transaction transaction(db);
      to_format_6(version);
      to_format_7();
      Statement set(db, "UPDATE acobench_meta SET value = ?1 WHERE key = 'format_version'");
      set.run(kFormatVersion).finish();
      transaction.commit();
      return;
    }
    std::vector<std::string> missing;
    for (const auto& [table, use] :
         {std::pair<std::string, unsigned>{"runs", kInRunsTable}, {"run_texts", kInRunTexts}}) {
      const auto present = columns_of(table);
      for (const TrialField* f : fields_in(use))
        if (!(f->use & kWhenUsed) && !present.contains(f->stored_as))
          missing.push_back("ALTER TABLE " + table + " ADD COLUMN " + column_definition(*f));
    }
    if (missing.empty()) return;
    Transaction transaction(db);
    for (const auto& statement : missing) db.exec(statement);
    transaction.commit();
  }

  // Formats 1 to 5 lack columns (1: the simulation measures of runs, 2: runs.error, 3:
  // progress.walks, 4: runs.failure, 5: plannerConfigs.plugins) or the properties table: they
  // are added, NULL or empty for the stored rows, so results of earlier runs are resumed and
  // reported. Their progress times stay the estimates they were; a NULL walks marks them. Their
  // runs have no properties but ant_steps and stopped_by, which the runs table holds. A failed
  // trial's failure is its stopped_by, or "error" for one that threw: which of the plugin or the
  // engine's checks threw was not recorded.
  void to_format_6(const std::string& version) {
    if (version == "6") return;
    const auto present = columns_of("runs");
    for (const TrialField* f : format_6_fields())
      if (!present.contains(f->name))
        db.exec("ALTER TABLE runs ADD COLUMN " + std::string(f->name) + " " +
                (f->values.empty() ? sql_type(*f) : "TEXT"));
    if (!columns_of("progress").contains("walks")) db.exec("ALTER TABLE progress ADD COLUMN walks INTEGER");
    if (!columns_of("plannerConfigs").contains("plugins"))
      db.exec("ALTER TABLE plannerConfigs ADD COLUMN plugins TEXT");
    db.exec(
        "UPDATE runs SET failure = CASE WHEN stopped_by IN ('crashed', 'timed out', 'out of memory') THEN "
        "stopped_by ELSE 'error' END WHERE error IS NOT NULL AND failure IS NULL");
    if (!tables().contains("properties")) db.exec(kPropertiesTable);
  }

  // The fields a format-6 runs table held under their own names (text where ENUMs are now): all
  // that are read back (the derived gap and status are computed again).
  static std::vector<const TrialField*> format_6_fields() { return fields_in(kInRunsTable | kInRunTexts, true); }

  // Format 6 to 7: the runs table rebuilt in OMPL's layout (each row read as format 6 wrote it
  // and written as store() writes it, under its id, which progress and properties name), the free
  // text moved to run_texts, the plugins to plannerPlugins, the limits 0 (not recorded), the
  // enums rows added. A value the new layout cannot hold is an Error (the transaction rolls back).
  void to_format_7() {
    std::map<std::int64_t, double> optimum;
    Statement optima(db, "SELECT id, optimal_length FROM experiments");
    optima.run();
    while (optima.next()) optimum[optima.integer(0)] = optima.null(1) ? -1.0 : optima.real(1);
    struct Row {
      std::int64_t id, experiment, planner;
      TrialRecord trial;
    };
    std::vector<Row> rows;
    // A field added after format 6 (optimal_corridor) has no column to read: it stays unknown.
    auto fields = format_6_fields();
    std::erase_if(fields, [present = columns_of("runs")](const TrialField* f) { return !present.contains(f->name); });
    std::string names;
    for (const TrialField* f : fields) names += std::string(", ") + f->name;
    Statement read(db, "SELECT id, experimentid, plannerid" + names + " FROM runs ORDER BY id");
    read.run();
    while (read.next()) {
      Row row{read.integer(0), read.integer(1), read.integer(2), {}};
      for (std::size_t i = 0; i < fields.size(); ++i)
        fields[i]->set(row.trial, read.cell(static_cast<int>(3 + i), fields[i]->type));
      rows.push_back(std::move(row));
    }
    std::set<std::string> used;  // the columns added when used that some row has a value for
    for (const Row& r : rows)
      for (const TrialField* f : used_columns(r.trial)) used.insert(f->stored_as);
    db.exec(runs_table("runs_7", used) + run_texts_table() + kPlannerPluginsTable);
    db.exec("DROP TABLE runs");
    db.exec("ALTER TABLE runs_7 RENAME TO runs");
    prepare_insert_run();
    for (const Row& r : rows) insert_trial(r.id, r.experiment, r.planner, r.trial, optimum[r.experiment]);
    db.exec(
        "INSERT INTO plannerPlugins (plannerid, plugins) SELECT id, plugins FROM plannerConfigs WHERE plugins IS NOT "
        "NULL");
    db.exec("ALTER TABLE plannerConfigs DROP COLUMN plugins");
    if (!columns_of("experiments").contains("anyangle_length"))
      db.exec("ALTER TABLE experiments ADD COLUMN anyangle_length REAL");
    db.exec(
        "UPDATE experiments SET timelimit = COALESCE(timelimit, 0), memorylimit = COALESCE(memorylimit, 0), "
        "runcount = COALESCE(runcount, 0), seed = COALESCE(seed, '')");
    add_enums();
  }

  // Only reads: a file that is not ours, or whose trials the experiment would run otherwise, stays
  // as it was.
  void check_is_ours(const std::string& experiment_name, const std::string& fingerprint,
                     const std::vector<ProblemRecord>& given) {
    if (!tables().contains("acobench_meta"))
      throw Error(file() +
                  " is an SQLite database but not an acobench results database (it has no acobench_meta "
                  "table); nothing in it was changed: give another results file");
    const auto stored = meta();
    const auto value = [&](const std::string& key) { return stored.contains(key) ? stored.at(key) : "(missing)"; };
    const std::string reuse =
        "; nothing in it was changed: give another results file, or delete this one to start again";
    if (!upgradable(value("format_version")))
      throw Error(file() + " is an acobench results database of format version " + value("format_version") +
                  ", this acobench reads version " + kFormatVersion + reuse);
    if (value("experiment_name") != experiment_name)
      throw Error(file() + " holds the results of experiment " + in_quotes(value("experiment_name")) + ", not of " +
                  in_quotes(experiment_name) + reuse);
    auto conflicts = fingerprint_conflicts(value("fingerprint"), fingerprint);
    for (auto& line : problem_conflicts(stored_problems(), given)) conflicts.push_back(std::move(line));
    if (!conflicts.empty()) throw Error(conflicts_message(file(), experiment_name, conflicts));
  }

  // The experiment grown by what `fingerprint` adds: its new problems' rows, the fingerprint of
  // both. Stored rows are left as they were.
  void grow(const std::string& fingerprint, const std::vector<ProblemRecord>& given) {
    Transaction transaction(db);
    const std::string stored = meta().at("fingerprint");
    growth = aco::studies::growth(stored, fingerprint);
    std::set<std::string> names;
    for (const auto& p : stored_problems()) names.insert(p.name);
    for (const auto& p : given)
      if (!names.contains(p.name)) add_problem(p);
    // A problem stored before its any-angle optimum was (by format 6) gets it.
    Statement any_angle(db,
                        "UPDATE experiments SET anyangle_length = ?2 WHERE name = ?1 AND anyangle_length IS NULL "
                        "AND " +
                            std::string(kOurs));
    for (const auto& p : given)
      if (p.anyangle_length >= 0) any_angle.run(p.name, p.anyangle_length).finish();
    Statement set(db, "UPDATE acobench_meta SET value = ?1 WHERE key = 'fingerprint'");
    set.run(merged_fingerprint(stored, fingerprint)).finish();
    transaction.commit();
  }

  void add_problem(const ProblemRecord& p) {
    Statement add(db,
                  "INSERT INTO experiments (name, totaltime, timelimit, memorylimit, runcount, version, hostname, "
                  "cpuinfo, date, seed, setup, optimal_length, anyangle_length) "
                  "VALUES (?1, 0, 0, 0, 0, ?2, ?3, ?4, datetime('now'), '', ?5, ?6, ?7)");
    add.run(p.name, std::string("aco ") + ACOBENCH_VERSION, aco::hostname(), aco::cpu_description(), p.setup_json,
            p.optimal_length >= 0 ? p.optimal_length : kNull, p.anyangle_length >= 0 ? p.anyangle_length : kNull)
        .finish();
  }

  // Creates the tables and rows of a new database; false if another process did it first.
  bool create(const std::string& experiment_name, const std::string& fingerprint,
              const std::vector<ProblemRecord>& given) {
    Transaction transaction(db);
    if (!tables().empty()) return false;
    db.exec(schema());
    db.exec(kPropertiesTable);
    add_enums();
    Statement set(db, "INSERT INTO acobench_meta (key, value) VALUES (?1, ?2)");
    set.run(std::string("format_version"), kFormatVersion).finish();
    set.run(std::string("experiment_name"), experiment_name).finish();
    set.run(std::string("fingerprint"), fingerprint).finish();
    for (const auto& p : given) add_problem(p);
    transaction.commit();
    return true;
  }

  std::string trial_label(const TrialRecord& t) const {
    return "trial (problem " + in_quotes(problems.at(static_cast<std::size_t>(t.problem)).name) + ", config " +
           in_quotes(config_names.at(t.config)) + ", repetition " + std::to_string(t.repetition) + ")";
  }

  void check_trial(const TrialRecord& t) const {
    if (t.problem < 0 || t.problem >= static_cast<int>(problems.size()))
      throw Error(file() + ": a trial names problem " + std::to_string(t.problem) + ", the experiment has " +
                  std::to_string(problems.size()));
    if (!config_names.contains(t.config))
      throw Error(file() + ": a trial names configuration id " + std::to_string(t.config) +
                  ", which add_config() did not return");
    const std::string label = trial_label(t);
    const auto check_curve = [&](std::size_t size, const char* what) {
      if (size != static_cast<std::size_t>(t.iterations))
        throw Error(file() + ": " + label + " has " + std::to_string(size) + " " + what + " for " +
                    std::to_string(t.iterations) + " iterations");
    };
    check_curve(t.best_so_far.size(), "best-so-far values");
    if (!t.elapsed_s.empty() || !t.walks.empty()) {
      check_curve(t.elapsed_s.size(), "elapsed times");
      check_curve(t.walks.size(), "walk counts");
    }
    if (!nlohmann::json::accept(t.path_json))
      throw Error(file() + ": the path of " + label + " is not valid JSON: " + t.path_json.substr(0, 200));
  }
};

ResultsDb::ResultsDb(const std::filesystem::path& file, const std::string& experiment_name,
                     const std::string& fingerprint, const std::vector<ProblemRecord>& problems)
    : impl_(std::make_unique<Impl>(checked_before_opening(file, problems))) {
  auto& d = *impl_;
  d.db.check(sqlite3_busy_timeout(d.db.handle(), 10000), "setting the busy timeout");
  std::set<std::string> tables;
  try {
    tables = d.tables();
  } catch (const Error&) {
    throw Error(file.string() + " is not an acobench results database (" + sqlite3_errmsg(d.db.handle()) +
                "); nothing in it was changed: give another results file");
  }
  // WAL is switched on only once the file is known to be ours: switching rewrites its header.
  bool created = false;
  if (tables.empty()) {
    d.db.exec("PRAGMA journal_mode = WAL");
    created = d.create(experiment_name, fingerprint, problems);
  }
  if (!created) {
    d.check_is_ours(experiment_name, fingerprint, problems);
    d.upgrade();
    d.grow(fingerprint, problems);
  }
  Statement wal(d.db, "PRAGMA journal_mode = WAL");
  wal.run();
  if (!wal.next() || wal.text(0) != "wal")
    throw Error("results database " + d.file() + ": cannot use write-ahead logging (journal mode " + wal.text(0) +
                "), which resuming after a crash needs");
  wal.finish();
  d.db.exec("PRAGMA synchronous = NORMAL");
  d.db.exec("PRAGMA foreign_keys = ON");
  d.load(&problems);
}

ResultsDb::ResultsDb(const std::filesystem::path& file) : impl_(std::make_unique<Impl>(existing(file))) {
  auto& d = *impl_;
  d.db.check(sqlite3_busy_timeout(d.db.handle(), 10000), "setting the busy timeout");
  bool ours = false;
  try {
    ours = d.tables().contains("acobench_meta");
  } catch (const Error&) {}
  if (!ours) throw Error(file.string() + " is not an acobench results database");
  const auto stored = d.meta();
  if (!stored.contains("format_version") || !upgradable(stored.at("format_version")))
    throw Error(file.string() + " is an acobench results database of another format version");
  d.upgrade();
  d.load(nullptr);
}

void ResultsDb::Impl::load(const std::vector<ProblemRecord>* given) {
  problems = given ? *given : stored_problems();
  std::map<std::string, std::int64_t> id_of;
  Statement ids(db, "SELECT id, name FROM experiments ORDER BY id");
  ids.run();
  while (ids.next()) id_of.emplace(ids.text(1), ids.integer(0));
  for (const auto& p : problems) {
    problem_of[id_of.at(p.name)] = static_cast<int>(experiment_ids.size());
    experiment_ids.push_back(id_of.at(p.name));
  }
  Statement names(db, "SELECT id, name FROM plannerConfigs WHERE " + std::string(kOurConfigs));
  names.run();
  while (names.next()) config_names[static_cast<int>(names.integer(0))] = names.text(1);

  find_run.emplace(db, "SELECT id FROM runs WHERE experimentid = ?1 AND plannerid = ?2 AND repetition = ?3");
  prepare_insert_run();
  insert_progress.emplace(
      db, "INSERT INTO progress (runid, time, iteration, best_cost, walks) VALUES (?1, ?2, ?3, ?4, ?5)");
  insert_property.emplace(db, "INSERT INTO properties (runid, name, value) VALUES (?1, ?2, ?3)");
  add_time.emplace(db, "UPDATE experiments SET totaltime = totaltime + ?2 WHERE id = ?1");
}

ResultsDb::~ResultsDb() = default;

int ResultsDb::add_config(const ConfigRecord& config) {
  auto& d = *impl_;
  parse_json(config.settings_json, "the settings of configuration " + in_quotes(config.name));
  std::lock_guard lock(d.mutex);
  Transaction transaction(d.db);
  Statement find(d.db, "SELECT id, settings FROM plannerConfigs WHERE name = ?1 AND " + std::string(kOurConfigs));
  find.run(config.name);
  // The plugin files as this run found them: a rerun from another build folder updates them.
  const auto plugins = config.plugins_json.empty() ? std::nullopt : std::optional(config.plugins_json);
  if (find.next()) {
    parse_json(find.text(1), "the stored settings of configuration " + in_quotes(config.name));
    if (const auto conflicts = config_conflicts(config.name, find.text(1), config.settings_json); !conflicts.empty())
      throw Error(conflicts_message(d.file(), d.meta().at("experiment_name"), conflicts));
    const auto id = static_cast<int>(find.integer(0));
    if (plugins) {
      Statement update(d.db, "INSERT OR REPLACE INTO plannerPlugins (plannerid, plugins) VALUES (?1, ?2)");
      update.run(id, *plugins).finish();
      transaction.commit();
    }
    return id;
  }
  Statement add(d.db, "INSERT INTO plannerConfigs (name, settings) VALUES (?1, ?2)");
  add.run(config.name, config.settings_json).finish();
  const auto id = static_cast<int>(sqlite3_last_insert_rowid(d.db.handle()));
  if (plugins) {
    Statement add_plugins(d.db, "INSERT INTO plannerPlugins (plannerid, plugins) VALUES (?1, ?2)");
    add_plugins.run(id, *plugins).finish();
  }
  transaction.commit();
  d.config_names[id] = config.name;
  return id;
}

std::set<std::tuple<int, int, int>> ResultsDb::finished() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::set<std::tuple<int, int, int>> done;
  Statement read(d.db, "SELECT experimentid, plannerid, repetition FROM runs");
  read.run();
  while (read.next())
    if (const auto problem = d.problem_of.find(read.integer(0)); problem != d.problem_of.end())
      done.emplace(problem->second, static_cast<int>(read.integer(1)), static_cast<int>(read.integer(2)));
  return done;
}

std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> ResultsDb::failed() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> failures;
  if (!d.columns_of("runs").contains(failure_field().stored_as)) return failures;  // none failed yet
  Statement read(d.db,
                 "SELECT experimentid, plannerid, repetition, failure, error FROM runs JOIN run_texts ON runid = id "
                 "WHERE error IS NOT NULL");
  read.run();
  while (read.next())
    if (const auto problem = d.problem_of.find(read.integer(0)); problem != d.problem_of.end()) {
      TrialRecord t;
      failure_field().set(t, read.cell(3, failure_field()));
      failures[{problem->second, static_cast<int>(read.integer(1)), static_cast<int>(read.integer(2))}] = {
          t.failure, read.text(4)};
    }
  return failures;
}

Growth ResultsDb::growth() const { return impl_->growth; }

void ResultsDb::store(const TrialRecord& t) {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  d.check_trial(t);
  const std::int64_t experiment = d.experiment_ids[static_cast<std::size_t>(t.problem)];
  Transaction transaction(d.db);
  if (d.find_run->run(experiment, t.config, t.repetition).any())
    throw Error(d.file() + ": " + d.trial_label(t) + " is already stored");

  d.add_used_columns(t);
  const std::int64_t run = d.insert_trial(std::nullopt, experiment, t.config, t,
                                          d.problems[static_cast<std::size_t>(t.problem)].optimal_length);
  const bool measured = !t.elapsed_s.empty();
  const double seconds_per_iteration = t.iterations > 0 ? t.time_s / t.iterations : 0.0;  // an older trial's estimate
  for (int i = 1; i <= t.iterations; ++i) {
    const auto at = static_cast<std::size_t>(i - 1);
    d.insert_progress
        ->run(run, measured ? t.elapsed_s[at] : i * seconds_per_iteration, i, finite_or_null(t.best_so_far[at]),
              measured ? std::optional(to_sql(t.walks[at])) : std::nullopt)
        .finish();
  }
  // Not a structured binding: clang 14 (the fuzz preset) cannot capture one in the lambda.
  for (const auto& property : t.properties)
    std::visit([&](const auto& v) { d.insert_property->run(run, property.first, v).finish(); }, property.second);
  d.add_time->run(experiment, t.time_s).finish();
  transaction.commit();
}

std::vector<ProblemRecord> ResultsDb::problems() const {
  std::lock_guard lock(impl_->mutex);
  return impl_->problems;
}

std::vector<std::pair<int, ConfigRecord>> ResultsDb::configs() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::vector<std::pair<int, ConfigRecord>> all;
  Statement read(d.db,
                 "SELECT id, name, settings, plugins FROM plannerConfigs LEFT JOIN plannerPlugins ON plannerid = id "
                 "WHERE " +
                     std::string(kOurConfigs) + " ORDER BY id");
  read.run();
  while (read.next()) all.push_back({static_cast<int>(read.integer(0)), {read.text(1), read.text(2), read.text(3)}});
  return all;
}

std::vector<TrialRecord> ResultsDb::trials() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::vector<TrialRecord> all;
  auto fields = d.present_run_fields(true);
  for (const TrialField* f : fields_in(kInRunTexts, true)) fields.push_back(f);
  Statement runs(d.db, "SELECT id, experimentid, plannerid" + column_names(fields) +
                           " FROM runs LEFT JOIN run_texts ON runid = id ORDER BY experimentid, plannerid, repetition");
  // Rows of appended OMPL logs have no iteration.
  Statement progress(d.db,
                     "SELECT best_cost, time, walks FROM progress WHERE runid = ?1 AND iteration IS NOT NULL "
                     "ORDER BY iteration");
  Statement properties(d.db, "SELECT name, value FROM properties WHERE runid = ?1");
  runs.run();
  while (runs.next()) {
    const auto problem = d.problem_of.find(runs.integer(1));
    // A problem the experiment no longer names, or an appended OMPL log's.
    if (problem == d.problem_of.end() || !d.config_names.contains(static_cast<int>(runs.integer(2)))) continue;
    TrialRecord t;
    t.problem = problem->second;
    t.config = static_cast<int>(runs.integer(2));
    for (std::size_t i = 0; i < fields.size(); ++i) fields[i]->set(t, runs.cell(static_cast<int>(3 + i), *fields[i]));
    progress.run(runs.integer(0));
    bool measured = true;
    while (progress.next()) {
      t.best_so_far.push_back(progress.null(0) ? std::numeric_limits<double>::infinity() : progress.real(0));
      t.elapsed_s.push_back(progress.real(1));
      t.walks.push_back(from_sql(progress.integer(2)));
      measured = measured && !progress.null(2);
    }
    if (!measured) {
      t.elapsed_s.clear();
      t.walks.clear();
    }
    properties.run(runs.integer(0));
    while (properties.next()) t.properties[properties.text(0)] = properties.value(1);
    all.push_back(std::move(t));
  }
  return all;
}

std::vector<AppendedRun> ResultsDb::appended_runs() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::vector<AppendedRun> all;
  Statement read(
      d.db,
      "SELECT experiments.name, plannerConfigs.name, solved, time, solution_length FROM runs "
      "JOIN experiments ON experiments.id = experimentid JOIN plannerConfigs ON plannerConfigs.id = plannerid "
      "WHERE NOT experiments." +
          std::string(kOurs) + " ORDER BY experimentid, plannerid, runs.id");
  read.run();
  while (read.next())
    all.push_back({read.text(0), read.text(1), !read.null(2) && read.integer(2) != 0, read.null(3) ? 0.0 : read.real(3),
                   read.null(4) ? std::nan("") : read.real(4)});
  return all;
}

void ResultsDb::record_limits(const ExperimentLimits& limits) {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  Transaction transaction(d.db);
  Statement set(d.db,
                "UPDATE experiments SET timelimit = ?2, memorylimit = ?3, runcount = ?4, seed = ?5 WHERE id = ?1");
  for (const std::int64_t id : d.experiment_ids)
    set.run(id, limits.time_limit_s, limits.memory_limit_mib, limits.runs, std::to_string(limits.seed)).finish();
  transaction.commit();
}

ExperimentLimits ResultsDb::limits() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  ExperimentLimits limits;
  if (d.experiment_ids.empty()) return limits;
  Statement read(d.db, "SELECT timelimit, memorylimit, runcount, seed FROM experiments WHERE id = ?1");
  read.run(d.experiment_ids.front());
  if (read.next()) {
    limits.time_limit_s = read.real(0);
    limits.memory_limit_mib = read.real(1);
    limits.runs = static_cast<int>(read.integer(2));
    limits.seed = std::strtoull(read.text(3).c_str(), nullptr, 10);
  }
  return limits;
}

std::string ResultsDb::meta(const std::string& key) const {
  const auto value = find_meta(key);
  if (!value) throw Error(impl_->file() + ": no " + in_quotes(key) + " in acobench_meta");
  return *value;
}

std::optional<std::string> ResultsDb::find_meta(const std::string& key) const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  Statement read(d.db, "SELECT value FROM acobench_meta WHERE key = ?1");
  read.run(key);
  if (!read.next()) return std::nullopt;
  return read.text(0);
}

void ResultsDb::set_meta(const std::string& key, const std::string& value) {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  Statement set(d.db, "INSERT OR REPLACE INTO acobench_meta (key, value) VALUES (?1, ?2)");
  set.run(key, value).finish();
}

}  // namespace aco::studies
