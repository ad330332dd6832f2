// Writing a results database: configurations, trials (each in one transaction with its progress
// and properties rows), the experiment's limits and acobench_meta's keys.
#include "aco/studies/results_db.hpp"

#include <algorithm>
#include <cmath>

#include "aco/error.hpp"
#include "results_db_impl.hpp"

namespace aco::studies {

using sqlite::Statement;
using sqlite::Transaction;

namespace {

double finite_or_null(double v) { return std::isfinite(v) ? v : sqlite::kNull; }

}  // namespace

void ResultsDb::Impl::prepare_insert_run() {
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

std::int64_t ResultsDb::Impl::insert_trial(std::optional<std::int64_t> id, std::int64_t experiment,
                                           std::int64_t planner, const TrialRecord& t, double optimal_length) {
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

void ResultsDb::Impl::add_used_columns(const TrialRecord& t) {
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

void ResultsDb::Impl::add_enums() {
  Statement add(db, "INSERT OR IGNORE INTO enums (name, value, description) VALUES (?1, ?2, ?3)");
  for (const TrialField* f : fields_in(kInRunsTable))
    for (std::size_t i = 0; i < f->values.size(); ++i)
      add.run(std::string(f->stored_as), static_cast<std::int64_t>(i), f->values[i]).finish();
}

std::string ResultsDb::Impl::trial_label(const TrialRecord& t) const {
  return "trial (problem " + in_quotes(problems.at(static_cast<std::size_t>(t.problem)).name) + ", config " +
         in_quotes(config_names.at(t.config)) + ", repetition " + std::to_string(t.repetition) + ")";
}

void ResultsDb::Impl::check_trial(const TrialRecord& t) const {
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

bool ResultsDb::store(const TrialRecord& t, IfStored if_stored) {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  d.check_trial(t);
  const std::int64_t experiment = d.experiment_ids[static_cast<std::size_t>(t.problem)];
  Transaction transaction(d.db);
  if (d.find_run->run(experiment, t.config, t.repetition).any()) {
    if (if_stored == IfStored::skip) return false;
    throw Error(d.file() + ": " + d.trial_label(t) + " is already stored");
  }

  d.add_used_columns(t);
  const std::int64_t run = d.insert_trial(std::nullopt, experiment, t.config, t,
                                          d.problems[static_cast<std::size_t>(t.problem)].optimal_length);
  const bool measured = !t.elapsed_s.empty();
  const double seconds_per_iteration = t.iterations > 0 ? t.time_s / t.iterations : 0.0;  // an older trial's estimate
  for (int i = 1; i <= t.iterations; ++i) {
    const auto at = static_cast<std::size_t>(i - 1);
    d.insert_progress
        ->run(run, measured ? t.elapsed_s[at] : i * seconds_per_iteration, i, finite_or_null(t.best_so_far[at]),
              measured ? std::optional(sqlite::to_sql(t.walks[at])) : std::nullopt)
        .finish();
  }
  // Not a structured binding: clang 14 (the fuzz preset) cannot capture one in the lambda.
  for (const auto& property : t.properties)
    std::visit([&](const auto& v) { d.insert_property->run(run, property.first, v).finish(); }, property.second);
  d.add_time->run(experiment, t.time_s).finish();
  transaction.commit();
  return true;
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

void ResultsDb::set_meta(const std::string& key, const std::string& value) {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  Statement set(d.db, "INSERT OR REPLACE INTO acobench_meta (key, value) VALUES (?1, ?2)");
  set.run(key, value).finish();
}

}  // namespace aco::studies
