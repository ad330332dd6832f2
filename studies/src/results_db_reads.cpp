// Reading a results database: what a rerun skips, and what reports show.
#include "aco/studies/results_db.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "aco/error.hpp"
#include "results_db_impl.hpp"

namespace aco::studies {

using sqlite::Statement;

namespace {

const TrialField& failure_field() {
  for (const auto& f : trial_fields())
    if (std::string_view(f.name) == "failure") return f;
  throw Error("no trial field 'failure'");
}

}  // namespace

std::vector<std::tuple<int, int, int>> ResultsDb::finished() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::vector<std::tuple<int, int, int>> done;
  Statement read(d.db, "SELECT experimentid, plannerid, repetition FROM runs");
  read.run();
  while (read.next())
    if (const auto problem = d.problem_of.find(read.integer(0)); problem != d.problem_of.end())
      done.emplace_back(problem->second, static_cast<int>(read.integer(1)), static_cast<int>(read.integer(2)));
  std::sort(done.begin(), done.end());
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
      failure_field().set(t, from_column(read, 3, failure_field()));
      failures[{problem->second, static_cast<int>(read.integer(1)), static_cast<int>(read.integer(2))}] = {
          t.failure, read.text(4)};
    }
  return failures;
}

Growth ResultsDb::growth() const { return impl_->growth; }

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
    for (std::size_t i = 0; i < fields.size(); ++i)
      fields[i]->set(t, from_column(runs, static_cast<int>(3 + i), *fields[i]));
    progress.run(runs.integer(0));
    bool measured = true;
    while (progress.next()) {
      t.best_so_far.push_back(progress.null(0) ? std::numeric_limits<double>::infinity() : progress.real(0));
      t.elapsed_s.push_back(progress.real(1));
      t.walks.push_back(sqlite::from_sql(progress.integer(2)));
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

}  // namespace aco::studies
