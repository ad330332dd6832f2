// Databases of older formats brought to this one when opened (results_db.hpp, "Older formats").
#include "aco/studies/results_db.hpp"

#include <map>
#include <utility>

#include "results_db_impl.hpp"

namespace aco::studies {

using sqlite::Statement;
using sqlite::Transaction;

namespace {

// The fields a format-6 runs table held under their own names (text where ENUMs are now): all
// that are read back (the derived gap and status are computed again).
std::vector<const TrialField*> format_6_fields() { return fields_in(kInRunsTable | kInRunTexts, true); }

}  // namespace

bool upgradable(const std::string& version) {
  for (const char* v : {"1", "2", "3", "4", "5", "6"})
    if (version == v) return true;
  return version == kFormatVersion;
}

// Older formats are brought to format 6, then migrated to 7, in one transaction. A trial
// field's column that a database of format 7 lacks (one made before the field was added) is
// added, NULL for the stored runs: an older acobench of format 7 still reads and continues the
// database (leaving the column NULL), so the format version stays.
void ResultsDb::Impl::upgrade() {
  const std::string version = meta().at("format_version");
  if (read_only && version != kFormatVersion)
    throw Error(file() + " is an acobench results database of format " + version + ", which is read as format " +
                kFormatVersion + " after it is migrated, and it cannot be written (" + *not_writable(file()) +
                "): copy it to a folder that can be written");
  if (read_only) return;  // columns it lacks are read as NULL
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
void ResultsDb::Impl::to_format_6(const std::string& version) {
  if (version == "6") return;
  const auto present = columns_of("runs");
  for (const TrialField* f : format_6_fields())
    if (!present.contains(f->name))
      db.exec("ALTER TABLE runs ADD COLUMN " + std::string(f->name) + " " +
              (f->values.empty() ? sql_type(*f) : "TEXT"));
  if (!columns_of("progress").contains("walks")) db.exec("ALTER TABLE progress ADD COLUMN walks INTEGER");
  if (!columns_of("plannerConfigs").contains("plugins")) db.exec("ALTER TABLE plannerConfigs ADD COLUMN plugins TEXT");
  db.exec(
      "UPDATE runs SET failure = CASE WHEN stopped_by IN ('crashed', 'timed out', 'out of memory') THEN "
      "stopped_by ELSE 'error' END WHERE error IS NOT NULL AND failure IS NULL");
  if (!tables().contains("properties")) db.exec(kPropertiesTable);
}

// Format 6 to 7: the runs table rebuilt in OMPL's layout (each row read as format 6 wrote it
// and written as store() writes it, under its id, which progress and properties name), the free
// text moved to run_texts, the plugins to plannerPlugins, the limits 0 (not recorded), the
// enums rows added. A value the new layout cannot hold is an Error (the transaction rolls back).
void ResultsDb::Impl::to_format_7() {
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

}  // namespace aco::studies
