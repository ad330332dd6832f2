#pragma once
// The report's analysis: what a results database's trials say per problem and configuration
// (summaries, tests against the baseline, ranks, the ablation path, the anytime view). report.cpp
// draws it as tables and figures; nothing here formats text.
#include <array>
#include <cmath>  // NAN
#include <cstdint>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "aco/engine/plugin_registry.hpp"
#include "aco/planning/yardsticks.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/statistics.hpp"

namespace aco::studies {

// One configuration on one problem.
struct Result {
  int config = 0;  // index into Analysis::configs
  std::vector<const TrialRecord*> runs;
  std::vector<double> lengths;  // solved runs only
  std::vector<double> gaps;  // solved runs only, when the optimum is known: gap_percent()
  Summary length;
  double success = 0.0;
  double gap = NAN;  // mean of gaps
  // Mean excess of the final path (after the smoother, or a continuous planner's) over the exact
  // any-angle optimum, %: NaN unless the problem has one.
  double over_any_angle = NAN;
  double optimal_corridor = NAN;  // share of the solved trials whose path is in the optimum's corridor
  // The solved trials in another corridor than the optimum's, by whether any walk of theirs took the
  // optimum's (property optimal_corridor_walked): never explored, or explored and then left.
  // -1: no trial says (another planner, or runs stored before the property).
  int corridor_never_walked = -1, corridor_left = -1;
  double turns = NAN, best_iteration = NAN, time_ms = NAN;
  double p = NAN, p_holm = NAN, a12 = NAN;  // against the baseline on this problem
  const TrialRecord* best = nullptr;
};

struct Analysis {
  std::string name;
  std::vector<ProblemRecord> problems;
  std::vector<std::pair<int, ConfigRecord>> configs;
  std::vector<TrialRecord> trials;
  std::vector<std::vector<Result>> results;  // [problem][config]
  std::vector<double> average_rank;  // per config
  std::vector<std::string> ablation_path;
  std::filesystem::path experiment_dir;  // the maps are relative to it
  aco::PluginRegistry* registry = nullptr;  // the map plugins
  std::vector<int> buckets;  // per problem: Moving AI bucket, or -1
  std::size_t unmeasured = 0;  // runs stored without anytime curves (by an older acobench)
  std::string host_version, host_build;  // of the acobench that ran the trials ("" if not recorded)
  std::vector<AppendedRun> appended;  // runs of OMPL logs appended to the database
  std::vector<BadRow> left_out;  // runs whose rows cannot be read, left out of every table
};

// The excess of a solved trial over the problem's optimum, %. The optimum is exact A* on the
// grid graph, so the trial's grid path (before any smoothing) is what is compared with it: a
// smoothed (any-angle) path may be shorter than the grid optimum, and its "gap" would be
// negative without being better than optimal. (A simulation trial's grid length is the distance
// driven.)
using aco::gap_percent;  // of a length (aco/planning/yardsticks.hpp)
double gap_percent(const TrialRecord& t, double optimal);

// A planning run whose rows lack the anytime curves: stored by an acobench of format 3 or earlier.
bool unmeasured(const TrialRecord& t);

double mean_of(const std::vector<double>& v);  // NaN if empty
// A run property's value as a number, if it is one (a count, a real or a flag).
std::optional<double> numeric(const aco::ParamValue& value);
double largest(const std::vector<double>& v);  // NaN if empty

// Everything the report shows, from the database (Analysis::registry is the caller's to set).
Analysis analyse(const ResultsDb& db);

// The problem sets (of the problems from one scenario file) in the order of their first problem,
// each with its problems' indices.
std::vector<std::pair<std::string, std::vector<std::size_t>>> problem_sets(const Analysis& a);

// The fixed targets of the anytime view, gap to the optimum in %.
inline constexpr std::array kTargets{1.0, 5.0};

// One run on a problem with a known optimum, for the anytime view: when it first came within each
// target, in seconds and in walks (infinity: never), and what it spent in all.
struct Reach {
  std::array<double, kTargets.size()> seconds{}, walks{};
  double seconds_spent = 0.0;
};

// The best-so-far gap per iteration, % (infinity before the first path).
std::vector<double> gap_curve(const TrialRecord& t, double optimal);

std::vector<double> as_reals(const std::vector<std::uint64_t>& counts);

// Per configuration: its runs on every problem with a known optimum. A run that failed or never
// started counts as one that never reached a target; a run without measured curves is left out.
std::vector<std::vector<Reach>> reaches(const Analysis& a);

// The mean gap over all problems of each step of the ablation path.
std::vector<double> ablation_gaps(const Analysis& a);

}  // namespace aco::studies
