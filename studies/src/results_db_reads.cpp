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

std::string describe(const BadRow& row) {
  // A progress or run_texts row is its run's.
  return row.table + (row.table == "progress" || row.table == "run_texts" ? " row of run " : " row ") +
         std::to_string(row.id) + ", column " + row.column + ": " + row.problem;
}

std::vector<ResultsDb::Impl::RunRow> ResultsDb::Impl::run_rows(std::vector<BadRow>& bad) {
  std::vector<RunRow> rows;
  Statement read(
      db, "SELECT r.id, r.experimentid, r.plannerid, r.repetition, e.id IS NOT NULL, e." + std::string(kOurs) +
              ", c.id IS NOT NULL, json_valid(c.settings), e.runcount FROM runs r "
              "LEFT JOIN experiments e ON e.id = r.experimentid LEFT JOIN plannerConfigs c ON c.id = r.plannerid "
              "ORDER BY r.id");
  read.run();
  while (read.next()) {
    const std::int64_t id = read.integer(0);
    const auto wrong = [&](const char* column, const std::string& problem) {
      bad.push_back({"runs", id, column, problem});
    };
    if (read.type(1) != SQLITE_INTEGER || read.integer(4) == 0) {
      wrong("experimentid", read.shown(1) + ", which names no experiments row");
      continue;
    }
    const auto problem = problem_of.find(read.integer(1));
    // An appended OMPL log's, or a problem the experiment no longer names.
    if (read.integer(5) == 0 || problem == problem_of.end()) continue;
    if (read.type(2) != SQLITE_INTEGER || read.integer(6) == 0) {
      wrong("plannerid", read.shown(2) + ", which names no plannerConfigs row");
      continue;
    }
    if (read.integer(7) == 0) {
      wrong("plannerid", read.shown(2) + ", a plannerConfigs row whose settings are not JSON");
      continue;
    }
    const std::int64_t runs = read.integer(8);  // 0: not recorded (before format 7)
    if (read.type(3) != SQLITE_INTEGER || read.integer(3) < 0 || (runs > 0 && read.integer(3) >= runs)) {
      wrong("repetition", read.shown(3) + ", not a repetition from 0 to " +
                              (runs > 0 ? std::to_string(runs - 1) : std::string("the repetitions less one")));
      continue;
    }
    rows.push_back({id, problem->second, static_cast<int>(read.integer(2)), static_cast<int>(read.integer(3))});
  }
  return rows;
}

void ResultsDb::Impl::refuse(const std::vector<BadRow>& bad, const std::string& consequence) const {
  throw Error("results database " + file() + ": " + describe(bad.front()) +
              (bad.size() > 1 ? " (and " + std::to_string(bad.size() - 1) + " more rows that cannot be read)" : "") +
              "; " + consequence);
}

std::vector<std::tuple<int, int, int>> ResultsDb::finished() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::vector<BadRow> bad;
  std::vector<std::tuple<int, int, int>> done;
  for (const auto& row : d.run_rows(bad)) done.emplace_back(row.problem, row.config, row.repetition);
  if (!bad.empty())
    d.refuse(bad,
             "which trial it holds cannot be told, so running the experiment again would run that trial "
             "twice: correct the row, or delete it (DELETE FROM " +
                 bad.front().table + " WHERE id = " + std::to_string(bad.front().id) + ") to run its trial again");
  std::sort(done.begin(), done.end());
  return done;
}

std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> ResultsDb::failed() const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> failures;
  if (!d.columns_of("runs").contains(failure_field().stored_as)) return failures;  // none failed yet
  std::vector<BadRow> bad;
  std::map<std::int64_t, Impl::RunRow> rows;
  for (const auto& row : d.run_rows(bad)) rows.emplace(row.id, row);
  Statement read(d.db, "SELECT id, failure, error FROM runs JOIN run_texts ON runid = id WHERE error IS NOT NULL");
  read.run();
  while (read.next())
    if (const auto row = rows.find(read.integer(0));
        row != rows.end() && !stored_value_problem(read, 1, failure_field(), false)) {
      TrialRecord t;
      failure_field().set(t, from_column(read, 1, failure_field()));
      failures[{row->second.problem, row->second.config, row->second.repetition}] = {t.failure, read.text(2)};
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

std::vector<TrialRecord> ResultsDb::trials(std::vector<BadRow>* left_out) const {
  auto& d = *impl_;
  std::lock_guard lock(d.mutex);
  std::vector<BadRow> bad;
  std::map<std::int64_t, Impl::RunRow> rows;
  for (const auto& row : d.run_rows(bad)) rows.emplace(row.id, row);
  auto fields = d.present_run_fields(true);
  const std::size_t in_runs = fields.size();
  for (const TrialField* f : fields_in(kInRunTexts, true)) fields.push_back(f);
  const auto solved_at = std::find_if(fields.begin(), fields.end(),
                                      [](const TrialField* f) { return f->name == std::string_view("solved"); }) -
                         fields.begin();
  Statement runs(d.db, "SELECT id" + column_names(fields) +
                           " FROM runs LEFT JOIN run_texts ON runid = id ORDER BY experimentid, plannerid, repetition");
  // Rows of appended OMPL logs have no iteration.
  Statement progress(d.db,
                     "SELECT best_cost, time, walks FROM progress WHERE runid = ?1 AND iteration IS NOT NULL "
                     "ORDER BY iteration");
  Statement properties(d.db, "SELECT name, value FROM properties WHERE runid = ?1");
  std::vector<TrialRecord> all;
  runs.run();
  while (runs.next()) {
    const std::int64_t id = runs.integer(0);
    const auto row = rows.find(id);
    if (row == rows.end()) continue;  // not the experiment's, or in `bad` already
    TrialRecord t;
    t.problem = row->second.problem;
    t.config = row->second.config;
    const bool solved = solved_at < static_cast<std::ptrdiff_t>(fields.size()) &&
                        runs.type(static_cast<int>(1 + solved_at)) == SQLITE_INTEGER &&
                        runs.integer(static_cast<int>(1 + solved_at)) == 1;
    const auto wrong = [&] {
      for (std::size_t i = 0; i < fields.size(); ++i)
        if (const auto problem = stored_value_problem(runs, static_cast<int>(1 + i), *fields[i], solved)) {
          bad.push_back({i < in_runs ? "runs" : "run_texts", id, fields[i]->stored_as, *problem});
          return true;
        }
      return false;
    };
    if (wrong()) continue;
    for (std::size_t i = 0; i < fields.size(); ++i)
      fields[i]->set(t, from_column(runs, static_cast<int>(1 + i), *fields[i]));
    progress.run(id);
    bool measured = true, readable = true;
    while (readable && progress.next()) {
      // best_cost: NULL until an ant arrived; time: seconds; walks: NULL in rows of format 3 or earlier.
      for (const auto& [column, name, may_be_null] :
           {std::tuple{0, "best_cost", true}, std::tuple{1, "time", false}, std::tuple{2, "walks", true}}) {
        const int type = progress.type(column);
        const bool number = type == SQLITE_INTEGER || (type == SQLITE_FLOAT && column != 2);
        if ((type == SQLITE_NULL && may_be_null) ||
            (number && std::isfinite(progress.real(column)) && progress.real(column) >= 0))
          continue;
        bad.push_back(
            {"progress", id, name,
             progress.shown(column) + ", not " + (column == 2 ? "a whole number of walks" : "a finite number >= 0")});
        readable = false;
        break;
      }
      if (!readable) break;
      t.best_so_far.push_back(progress.null(0) ? std::numeric_limits<double>::infinity() : progress.real(0));
      t.elapsed_s.push_back(progress.real(1));
      t.walks.push_back(sqlite::from_sql(progress.integer(2)));
      measured = measured && !progress.null(2);
    }
    if (!readable) continue;
    if (!measured) {
      t.elapsed_s.clear();
      t.walks.clear();
    }
    properties.run(id);
    while (properties.next()) t.properties[properties.text(0)] = properties.value(1);
    all.push_back(std::move(t));
  }
  if (!bad.empty() && !left_out)
    d.refuse(bad, "correct or delete it (acobench report leaves such runs out and counts them)");
  if (left_out) {
    std::sort(bad.begin(), bad.end(),
              [](const BadRow& a, const BadRow& b) { return std::tie(a.id, a.table) < std::tie(b.id, b.table); });
    left_out->insert(left_out->end(), bad.begin(), bad.end());
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
