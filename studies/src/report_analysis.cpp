#include "report_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <variant>
#include <nlohmann/json.hpp>

#include "aco/error.hpp"

namespace aco::studies {
namespace {

// Problems from one scenario file share a set name: "arena#40" belongs to "arena".
std::string problem_set(const std::string& problem) { return problem.substr(0, problem.find('#')); }

}  // namespace

double gap_percent(const TrialRecord& t, double optimal) { return gap_percent(t.grid_length, optimal); }

bool unmeasured(const TrialRecord& t) { return !t.simulation && t.iterations > 0 && t.elapsed_s.empty(); }

// A property's value as a number, if it is one (a count, a real or a flag).
std::optional<double> numeric(const aco::ParamValue& value) {
  return std::visit(
      [](const auto& v) -> std::optional<double> {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>)
          return std::nullopt;
        else
          return static_cast<double>(v);
      },
      value);
}

double mean_of(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  double s = 0;
  for (double x : v) s += x;
  return s / v.size();
}

double largest(const std::vector<double>& v) { return v.empty() ? NAN : *std::max_element(v.begin(), v.end()); }

Analysis analyse(const ResultsDb& db) {
  Analysis a;
  a.name = db.meta("experiment_name");
  a.problems = db.problems();
  a.configs = db.configs();
  a.trials = db.trials(&a.left_out);
  a.appended = db.appended_runs();
  a.experiment_dir = std::filesystem::path(db.meta("experiment_file")).parent_path();
  a.host_version = db.find_meta("host_version").value_or("");
  a.host_build = db.find_meta("host_build").value_or("");
  std::map<int, int> index;  // config id -> position
  for (std::size_t c = 0; c < a.configs.size(); ++c) index[a.configs[c].first] = static_cast<int>(c);
  a.results.assign(a.problems.size(), std::vector<Result>(a.configs.size()));
  for (const auto& problem : a.problems) {
    const auto setup = nlohmann::json::parse(problem.setup_json);
    a.buckets.push_back(setup.value("bucket", -1));
  }
  for (std::size_t p = 0; p < a.problems.size(); ++p)
    for (std::size_t c = 0; c < a.configs.size(); ++c) a.results[p][c].config = static_cast<int>(c);
  for (const auto& t : a.trials) a.results[t.problem][index.at(t.config)].runs.push_back(&t);
  a.unmeasured = static_cast<std::size_t>(std::count_if(a.trials.begin(), a.trials.end(), unmeasured));

  std::vector<double> raw_p;
  std::vector<Result*> compared;
  for (std::size_t p = 0; p < a.problems.size(); ++p) {
    const double optimal = a.problems[p].optimal_length, any_angle = a.problems[p].anyangle_length;
    for (auto& r : a.results[p]) {
      std::vector<double> turns, best_iterations, times, over_any_angle, in_corridor;
      for (const auto* t : r.runs) {
        times.push_back(t->time_s * 1000.0);
        if (!t->solved) continue;
        r.lengths.push_back(t->length);
        turns.push_back(t->turns);
        best_iterations.push_back(t->best_iteration);
        // A continuous planner's trial (ompl) has no grid path: its grid_length is NULL in the
        // database, read back as 0, and it has no gap.
        if (optimal > 0 && t->grid_length > 0) r.gaps.push_back(gap_percent(*t, optimal));
        if (any_angle > 0) over_any_angle.push_back(gap_percent(t->length, any_angle));
        if (t->optimal_corridor) in_corridor.push_back(*t->optimal_corridor ? 1.0 : 0.0);
        const auto walked = t->properties.find("optimal_corridor_walked");
        if (walked != t->properties.end()) {
          if (r.corridor_left < 0) r.corridor_never_walked = r.corridor_left = 0;
          if (t->optimal_corridor == false)
            ++(numeric(walked->second) > 0.0 ? r.corridor_left : r.corridor_never_walked);
        }
        if (!r.best || t->length < r.best->length) r.best = t;
      }
      r.length = summarize(r.lengths);
      r.success = r.runs.empty() ? NAN : double(r.lengths.size()) / r.runs.size();
      r.gap = mean_of(r.gaps);
      r.over_any_angle = mean_of(over_any_angle);
      r.optimal_corridor = mean_of(in_corridor);
      r.turns = mean_of(turns);
      r.best_iteration = mean_of(best_iterations);
      r.time_ms = mean_of(times);
    }
    const Result& baseline = a.results[p][0];
    for (std::size_t c = 1; c < a.configs.size(); ++c) {
      Result& r = a.results[p][c];
      if (r.lengths.empty() || baseline.lengths.empty()) continue;
      r.p = mann_whitney_u(r.lengths, baseline.lengths).p;
      r.a12 = vargha_delaney_a12(r.lengths, baseline.lengths);
      raw_p.push_back(r.p);
      compared.push_back(&r);
    }
  }
  const auto adjusted = holm_adjust(raw_p);
  for (std::size_t i = 0; i < compared.size(); ++i) compared[i]->p_holm = adjusted[i];

  // Ranking by mean length; a configuration that never solved a problem ranks last on it.
  std::vector<std::vector<double>> scores(a.configs.size(), std::vector<double>(a.problems.size()));
  for (std::size_t p = 0; p < a.problems.size(); ++p)
    for (std::size_t c = 0; c < a.configs.size(); ++c) {
      const double m = a.results[p][c].length.mean;
      scores[c][p] = std::isfinite(m) ? m : std::numeric_limits<double>::max();
    }
  if (!a.problems.empty() && !a.configs.empty()) a.average_rank = average_ranks(scores);
  try {
    a.ablation_path = nlohmann::json::parse(db.meta("ablation_path")).get<std::vector<std::string>>();
  } catch (const aco::Error&) {
    // No ablation in this experiment.
  }
  return a;
}

std::vector<std::pair<std::string, std::vector<std::size_t>>> problem_sets(const Analysis& a) {
  std::vector<std::pair<std::string, std::vector<std::size_t>>> sets;
  for (std::size_t p = 0; p < a.problems.size(); ++p) {
    const std::string set = problem_set(a.problems[p].name);
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const auto& s) { return s.first == set; });
    (it == sets.end() ? sets.emplace_back(set, std::vector<std::size_t>{}) : *it).second.push_back(p);
  }
  return sets;
}

std::vector<double> gap_curve(const TrialRecord& t, double optimal) {
  std::vector<double> gaps;
  for (const double b : t.best_so_far) gaps.push_back(std::isfinite(b) ? gap_percent(b, optimal) : b);
  return gaps;
}

std::vector<double> as_reals(const std::vector<std::uint64_t>& counts) { return {counts.begin(), counts.end()}; }

std::vector<std::vector<Reach>> reaches(const Analysis& a) {
  std::vector<std::vector<Reach>> all(a.configs.size());
  for (std::size_t p = 0; p < a.problems.size(); ++p) {
    const double optimal = a.problems[p].optimal_length;
    if (!(optimal > 0)) continue;
    for (const Result& r : a.results[p])
      for (const TrialRecord* t : r.runs) {
        if (t->simulation || unmeasured(*t)) continue;
        const std::vector<double> gaps = gap_curve(*t, optimal), walks = as_reals(t->walks);
        Reach reach;
        for (std::size_t k = 0; k < kTargets.size(); ++k) {
          reach.seconds[k] = hitting_time(t->elapsed_s, gaps, kTargets[k]);
          reach.walks[k] = hitting_time(walks, gaps, kTargets[k]);
        }
        reach.seconds_spent = t->elapsed_s.empty() ? t->time_s : t->elapsed_s.back();
        all[static_cast<std::size_t>(r.config)].push_back(reach);
      }
  }
  return all;
}

std::vector<double> ablation_gaps(const Analysis& a) {
  std::vector<double> means;
  for (const std::string& step : a.ablation_path) {
    std::vector<double> gaps;
    for (std::size_t p = 0; p < a.problems.size(); ++p)
      for (const auto& r : a.results[p])
        if (a.configs[r.config].second.name == step && std::isfinite(r.gap)) gaps.push_back(r.gap);
    means.push_back(mean_of(gaps));
  }
  return means;
}

}  // namespace aco::studies
