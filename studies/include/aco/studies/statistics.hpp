#pragma once
// acobench's statistics: summaries of repeated runs, the Mann-Whitney U test between two
// configurations, Holm's correction for many such tests, the Vargha-Delaney A12 effect size and
// average ranks across problems (Demšar 2006). Every function takes finite values only and throws
// aco::Error otherwise: an unsolved run's length (infinity) must be left out, or counted apart,
// by the caller.
#include <cstddef>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace aco::studies {

// Descriptive statistics of one sample. Quantiles use linear interpolation between order
// statistics (Hyndman & Fan type 7, the default of R and numpy): the p-quantile of the sorted
// x[0..n-1] is x[h] interpolated at h = (n - 1) p.
// Undefined values are NaN: everything for n = 0; the standard deviation and the confidence
// interval for n = 1 (the other fields are then the single value, iqr 0).
struct Summary {
  static constexpr double undefined = std::numeric_limits<double>::quiet_NaN();
  std::size_t n = 0;
  double mean = undefined;
  double stddev = undefined;  // sample standard deviation (divisor n - 1)
  double median = undefined;
  double q1 = undefined;
  double q3 = undefined;
  double iqr = undefined;  // q3 - q1
  double ci_low = undefined;  // 95 % confidence interval of the mean: mean -+ t(0.975, n - 1) stddev / sqrt(n)
  double ci_high = undefined;
  double min = undefined;
  double max = undefined;
};

Summary summarize(std::span<const double> sample);

// The type 7 quantile (see Summary) of an ascending, non-empty sample; 0 <= p <= 1.
double quantile(std::span<const double> sorted, double p);

// The p-quantile of Student's t distribution with `degrees_of_freedom` > 0; 0 < p < 1.
double student_t_quantile(double p, double degrees_of_freedom);

// Ranks 1..n of the values, ties getting the average of the ranks they span (mid-ranks).
std::vector<double> ranks(std::span<const double> values);

// Two-sided Mann-Whitney U test, chosen as SciPy's mannwhitneyu(method="auto",
// use_continuity=True): the exact null distribution of U when there are no ties and the smaller
// sample has at most 8 values, else the normal approximation with tie-corrected variance and a
// continuity correction of 1/2. Both samples must be non-empty.
struct MannWhitney {
  double u = 0.0;  // U of the first sample: pairs (x, y) with x > y, ties counting 1/2; U2 = n1 n2 - u
  double p = 1.0;  // two-sided p value, at most 1
  bool exact = false;  // whether p comes from the exact distribution
};

MannWhitney mann_whitney_u(std::span<const double> first, std::span<const double> second);

// Holm-Bonferroni step-down adjusted p values, in the input order: the i-th smallest p (from 1)
// becomes max over j <= i of min(1, (m - j + 1) p_(j)). Each p must lie in [0, 1].
std::vector<double> holm_adjust(std::span<const double> p_values);

// Vargha-Delaney A12: the probability that a value drawn from `first` is larger than one drawn
// from `second`, ties counting half (= U / (n1 n2)). 0.5 means no difference. For path lengths
// smaller is better, so A12 < 0.5 means the first configuration tends to find shorter paths.
double vargha_delaney_a12(std::span<const double> first, std::span<const double> second);

// Vargha & Delaney's (2000) labels, symmetric about 0.5: max(A, 1 - A) below 0.56 is
// negligible, below 0.64 small, below 0.71 medium, else large.
enum class EffectSize { negligible, small, medium, large };
EffectSize effect_size(double a12);
std::string_view to_string(EffectSize size);

// Average rank of each configuration across problems, as in the Friedman test (Demšar 2006).
// scores[c][p] is configuration c's score on problem p, lower is better; on each problem the best
// configuration gets rank 1 and ties share their average rank. Every row must have as many
// problems as the first, at least one.
std::vector<double> average_ranks(const std::vector<std::vector<double>>& scores);

// Fixed-target anytime measures, as IOHanalyzer and COCO define them. A run's curve gives, per
// iteration, the effort spent by its end (seconds or walks, non-decreasing) and the best value so
// far (infinity before the first solution). A run that never reaches a target has an infinite
// hitting time.

// The effort at the end of the first iteration whose value is <= target; infinity if none.
double hitting_time(std::span<const double> effort, std::span<const double> value, double target);

// The empirical cumulative distribution of hitting times: for each t of `at`, the share of ALL
// the runs (those that never hit included) whose hitting time is <= t. No runs: 0.
std::vector<double> ecdf(std::span<const double> hitting_times, std::span<const double> at);

// Expected running time: the effort of every run until it hit the target or ended (`run_efforts`,
// one per run), divided by the runs that hit; infinity if none did.
double expected_running_time(std::span<const double> hitting_times, std::span<const double> run_efforts);

}  // namespace aco::studies
