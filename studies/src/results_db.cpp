// Opening a results database: creating a new one, or checking that a stored one is the
// experiment's, bringing it to this format and growing it by the experiment's new problems.
#include "aco/studies/results_db.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

#include "aco/error.hpp"
#include "aco/machine.hpp"
#include "results_db_impl.hpp"

namespace aco::studies {

using sqlite::Statement;
using sqlite::Transaction;

namespace {

// Opening would create a missing file: a report of a mistyped name must not.
const std::filesystem::path& existing(const std::filesystem::path& file) {
  if (!std::filesystem::is_regular_file(file)) throw Error(file.string() + ": no such results database");
  return file;
}

// Bad problems and a file that cannot be written are refused before opening, which would create the file.
const std::filesystem::path& checked_before_opening(const std::filesystem::path& file,
                                                    const std::vector<ProblemRecord>& problems) {
  for (const auto& p : problems) parse_json(p.setup_json, "the setup of problem " + in_quotes(p.name));
  if (const auto why = not_writable(file))
    throw Error(std::filesystem::exists(file)
                    ? "results database " + file.string() + " cannot be written (" + *why +
                          "), and a run stores its trials there: give another file (a report reads this one as it is)"
                    : "results database " + file.string() + " cannot be created (" + *why +
                          "): give a file in a folder that can be written");
  return file;
}

// How a report opens a file: to be written where it can (an older format is migrated), else read only.
sqlite::Access access_to_read(const std::filesystem::path& file) {
  if (!not_writable(file)) return sqlite::Access::write;
  // A WAL database without its -shm file: SQLite cannot make one here, and nothing is writing it.
  return std::filesystem::exists(file.string() + "-shm") ? sqlite::Access::read : sqlite::Access::read_unchanging;
}

}  // namespace

std::optional<std::string> not_writable(const std::filesystem::path& file) {
  const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
  // SQLite writes the -wal and -shm files beside the database.
  if (::access(folder.c_str(), W_OK) != 0) return "its folder " + folder.string() + ": " + std::strerror(errno);
  if (std::filesystem::exists(file) && ::access(file.c_str(), W_OK) != 0) return std::strerror(errno);
  return std::nullopt;
}

nlohmann::json parse_json(const std::string& text, const std::string& what) {
  auto value = nlohmann::json::parse(text, nullptr, false);
  if (value.is_discarded()) throw Error(what + " is not valid JSON: " + text.substr(0, 200));
  return value;
}

std::set<std::string> ResultsDb::Impl::tables() {
  std::set<std::string> names;
  Statement list(db, "SELECT name FROM sqlite_master WHERE type = 'table'");
  list.run();
  while (list.next()) names.insert(list.text(0));
  return names;
}

std::map<std::string, std::string> ResultsDb::Impl::meta() {
  std::map<std::string, std::string> values;
  Statement read(db, "SELECT key, value FROM acobench_meta");
  read.run();
  while (read.next()) values[read.text(0)] = read.text(1);
  return values;
}

std::vector<ProblemRecord> ResultsDb::Impl::stored_problems() {
  std::vector<ProblemRecord> stored;
  // Read before an older format is upgraded (to check the file is the experiment's).
  const std::string any_angle = columns_of("experiments").contains("anyangle_length") ? "anyangle_length" : "NULL";
  Statement read(db, "SELECT name, setup, optimal_length, " + any_angle +
                         ", id, json_valid(setup) FROM experiments WHERE " + std::string(kOurs) + " ORDER BY id");
  read.run();
  while (read.next()) {
    const auto refuse = [&](const char* column, const std::string& problem) {
      throw Error("results database " + file() + ": " + describe({"experiments", read.integer(4), column, problem}) +
                  "; correct the row");
    };
    if (read.type(0) != SQLITE_TEXT) refuse("name", read.shown(0) + ", not a problem's name");
    if (read.integer(5) == 0) refuse("setup", read.shown(1) + ", not the problem's JSON");
    // A length: NULL (unknown) or a finite number > 0.
    for (const int column : {2, 3})
      if (!read.null(column) && (read.type(column) == SQLITE_TEXT || read.type(column) == SQLITE_BLOB ||
                                 !std::isfinite(read.real(column)) || !(read.real(column) > 0)))
        refuse(column == 2 ? "optimal_length" : "anyangle_length",
               read.shown(column) + ", not a length (a finite number > 0, or NULL: unknown)");
    stored.push_back(
        {read.text(0), read.text(1), read.null(2) ? -1.0 : read.real(2), read.null(3) ? -1.0 : read.real(3)});
  }
  return stored;
}

std::set<std::string> ResultsDb::Impl::columns_of(const std::string& table) {
  std::set<std::string> present;
  Statement columns(db, "SELECT name FROM pragma_table_info('" + table + "')");
  columns.run();
  while (columns.next()) present.insert(columns.text(0));
  return present;
}

std::vector<const TrialField*> ResultsDb::Impl::present_run_fields(bool read_back) {
  const auto present = columns_of("runs");
  std::vector<const TrialField*> fields;
  for (const TrialField* f : fields_in(kInRunsTable, read_back))
    if (present.contains(f->stored_as)) fields.push_back(f);
  return fields;
}

void ResultsDb::Impl::check_is_ours(const std::string& experiment_name, const std::string& fingerprint,
                                    const std::vector<ProblemRecord>& given) {
  if (!tables().contains("acobench_meta"))
    throw Error(file() +
                " is an SQLite database but not an acobench results database (it has no acobench_meta "
                "table); nothing in it was changed: give another results file");
  const auto stored = meta();
  const auto value = [&](const std::string& key) { return stored.contains(key) ? stored.at(key) : "(missing)"; };
  const std::string reuse = "; nothing in it was changed: give another results file, or delete this one to start again";
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

void ResultsDb::Impl::grow(const std::string& fingerprint, const std::vector<ProblemRecord>& given) {
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

void ResultsDb::Impl::add_problem(const ProblemRecord& p) {
  Statement add(db,
                "INSERT INTO experiments (name, totaltime, timelimit, memorylimit, runcount, version, hostname, "
                "cpuinfo, date, seed, setup, optimal_length, anyangle_length) "
                "VALUES (?1, 0, 0, 0, 0, ?2, ?3, ?4, datetime('now'), '', ?5, ?6, ?7)");
  add.run(p.name, std::string("aco ") + ACOBENCH_VERSION, aco::hostname(), aco::cpu_description(), p.setup_json,
          p.optimal_length >= 0 ? p.optimal_length : sqlite::kNull,
          p.anyangle_length >= 0 ? p.anyangle_length : sqlite::kNull)
      .finish();
}

bool ResultsDb::Impl::create(const std::string& experiment_name, const std::string& fingerprint,
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

ResultsDb::ResultsDb(const std::filesystem::path& file)
    : impl_(std::make_unique<Impl>(existing(file), access_to_read(file))) {
  auto& d = *impl_;
  d.db.check(sqlite3_busy_timeout(d.db.handle(), 10000), "setting the busy timeout");
  bool ours = false;
  try {
    ours = d.tables().contains("acobench_meta");
  } catch (const Error&) {}
  if (!ours)
    throw Error(file.string() + " is not an acobench results database" +
                (d.read_only
                     ? std::string(" (read only, as it cannot be written: ") + sqlite3_errmsg(d.db.handle()) + ")"
                     : std::string()));
  const auto stored = d.meta();
  if (!stored.contains("format_version") || !upgradable(stored.at("format_version")))
    throw Error(file.string() + " is an acobench results database of another format version");
  d.upgrade();
  d.load(nullptr);
}

ResultsDb::~ResultsDb() = default;

}  // namespace aco::studies
