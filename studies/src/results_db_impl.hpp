#pragma once
// ResultsDb's state and the steps its files share: opening (results_db.cpp), migrating older
// formats (results_db_migrations.cpp), writing (results_db_writes.cpp) and reading
// (results_db_reads.cpp).
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "aco/studies/growth.hpp"
#include "aco/studies/results_db.hpp"
#include "results_db_schema.hpp"
#include "sqlite.hpp"

namespace aco::studies {

// This format version, or an earlier one ResultsDb::Impl::upgrade() brings to it.
bool upgradable(const std::string& version);

// `text` parsed; an Error naming `what` if it is not JSON.
nlohmann::json parse_json(const std::string& text, const std::string& what);
inline std::string in_quotes(const std::string& s) { return "'" + s + "'"; }
// Why `file` (or its folder, where SQLite writes the -wal and -shm files) cannot be written, if it
// cannot: "Read-only file system", "Permission denied".
std::optional<std::string> not_writable(const std::filesystem::path& file);

struct ResultsDb::Impl {
  explicit Impl(const std::filesystem::path& file, sqlite::Access access = sqlite::Access::write)
      : db(file, access), read_only(access != sqlite::Access::write) {}

  sqlite::Connection db;
  bool read_only;  // opened for reports where the file cannot be written
  mutable std::mutex mutex;
  std::vector<std::int64_t> experiment_ids;  // by problem index
  std::map<std::int64_t, int> problem_of;  // by experiment id
  std::vector<ProblemRecord> problems;
  std::map<int, std::string> config_names;  // by id
  std::optional<sqlite::Statement> find_run, insert_run, insert_text, insert_progress, insert_property, add_time;
  // The runs columns insert_run fills: those the table has (a column added when used may not be there).
  std::vector<const TrialField*> run_columns;
  Growth growth;  // what the experiment added to the database when it was opened

  std::string file() const { return db.file(); }

  // What the file holds (results_db.cpp).
  std::set<std::string> tables();
  std::map<std::string, std::string> meta();
  std::vector<ProblemRecord> stored_problems();
  std::set<std::string> columns_of(const std::string& table);
  // The fields of the runs table whose columns it has now.
  std::vector<const TrialField*> present_run_fields(bool read_back);

  // Opening (results_db.cpp).
  // Only reads: a file that is not ours, or whose trials the experiment would run otherwise, stays
  // as it was.
  void check_is_ours(const std::string& experiment_name, const std::string& fingerprint,
                     const std::vector<ProblemRecord>& given);
  // The experiment grown by what `fingerprint` adds: its new problems' rows, the fingerprint of
  // both. Stored rows are left as they were.
  void grow(const std::string& fingerprint, const std::vector<ProblemRecord>& given);
  void add_problem(const ProblemRecord& p);
  // Creates the tables and rows of a new database; false if another process did it first.
  bool create(const std::string& experiment_name, const std::string& fingerprint,
              const std::vector<ProblemRecord>& given);
  // The problems (`given`, in their order, or all stored ones), configurations and statements of
  // an opened database.
  void load(const std::vector<ProblemRecord>* given);

  // Reading (results_db_reads.cpp).
  struct RunRow {
    std::int64_t id = 0;
    int problem = 0, config = 0, repetition = 0;
  };
  // The runs rows of the experiment's problems (not those of appended OMPL logs, nor of problems
  // the experiment no longer names) whose trial can be told, ordered by id; the others in `bad`.
  std::vector<RunRow> run_rows(std::vector<BadRow>& bad);
  // An Error naming the first of `bad` (and how many more), saying what `consequence` is.
  [[noreturn]] void refuse(const std::vector<BadRow>& bad, const std::string& consequence) const;

  // Older formats (results_db_migrations.cpp). A read-only file of an older format is an Error.
  void upgrade();
  void to_format_6(const std::string& version);
  void to_format_7();

  // Writing (results_db_writes.cpp).
  // Prepares the INSERT of a runs row (?1 its id, NULL for a new one) for the columns there are.
  void prepare_insert_run();
  // A trial's runs row and its run_texts row (if it has a text); `id` nullopt: a new row. The id.
  std::int64_t insert_trial(std::optional<std::int64_t> id, std::int64_t experiment, std::int64_t planner,
                            const TrialRecord& t, double optimal_length);
  // The columns added when used that the trial has a value for: added if missing (in the
  // caller's transaction), and the INSERT prepared again.
  void add_used_columns(const TrialRecord& t);
  // The rows describing every ENUM column's values (OMPL's -a adds its own only for names it
  // does not find).
  void add_enums();
  std::string trial_label(const TrialRecord& t) const;
  void check_trial(const TrialRecord& t) const;
};

}  // namespace aco::studies
