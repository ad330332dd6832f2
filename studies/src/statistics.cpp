#include "aco/studies/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

#include "aco/error.hpp"

namespace aco::studies {
namespace {

std::string text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

// NaN would break sorting and infinity every mean: both are the caller's bug, not data.
void require_finite(std::span<const double> values, const std::string& what) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw aco::Error(what + ": value " + std::to_string(i + 1) + " of " + std::to_string(values.size()) + " is " +
                       text(values[i]) + "; statistics need finite values (leave unsolved runs out)");
}

void require_samples(std::span<const double> first, std::span<const double> second, const std::string& what) {
  if (first.empty() || second.empty())
    throw aco::Error(what + " needs two non-empty samples, got sizes " + std::to_string(first.size()) + " and " +
                     std::to_string(second.size()));
  require_finite(first, what + " (first sample)");
  require_finite(second, what + " (second sample)");
}

// U of the first sample from the mid-ranks of both samples pooled: U1 = R1 - n1 (n1 + 1) / 2.
double u_statistic(std::span<const double> pooled_ranks, std::size_t n1) {
  const double rank_sum = std::accumulate(pooled_ranks.begin(), pooled_ranks.begin() + std::ptrdiff_t(n1), 0.0);
  return rank_sum - double(n1) * double(n1 + 1) / 2.0;
}

// How many arrangements of the pooled sample give each U = 0..m n when there are no ties: the
// coefficients of the Gaussian binomial [m + n choose m]_q = prod_{i=1..m} (1 - q^(n+i)) / (1 - q^i).
// After step i the polynomial is [n + i choose i]_q, so every coefficient stays non-negative.
std::vector<double> u_frequencies(std::size_t m, std::size_t n) {
  if (m > n) std::swap(m, n);  // the distribution is symmetric in the sizes; fewer factors
  std::vector<double> poly(m * n + m + 1, 0.0);
  poly[0] = 1.0;
  for (std::size_t i = 1; i <= m; ++i) {
    const std::size_t top = i * n + i;  // degree after multiplying [n + i - 1 choose i - 1]_q by 1 - q^(n+i)
    for (std::size_t k = top; k >= n + i; --k) poly[k] -= poly[k - n - i];
    for (std::size_t k = i; k <= top; ++k) poly[k] += poly[k - i];
  }
  poly.resize(m * n + 1);
  return poly;
}

// P(U >= u) under the null hypothesis, from the exact distribution. Summed as P(U <= n1 n2 - u)
// by symmetry: the low coefficients never went through a subtraction, so even tiny tails are
// accurate.
double exact_upper_tail(double u, std::size_t n1, std::size_t n2) {
  const std::vector<double> frequencies = u_frequencies(n1, n2);
  const double total = std::accumulate(frequencies.begin(), frequencies.end(), 0.0);
  const auto end = frequencies.begin() + std::ptrdiff_t(n1 * n2 - std::size_t(std::llround(u))) + 1;
  return std::accumulate(frequencies.begin(), end, 0.0) / total;
}

double standard_normal_upper_tail(double z) { return 0.5 * std::erfc(z / std::sqrt(2.0)); }

}  // namespace

double quantile(std::span<const double> sorted, double p) {
  if (sorted.empty()) throw aco::Error("quantile of an empty sample");
  if (!(p >= 0.0 && p <= 1.0)) throw aco::Error("quantile: probability " + text(p) + " is outside [0, 1]");
  const double h = double(sorted.size() - 1) * p;
  const auto below = std::size_t(std::floor(h));
  if (below + 1 >= sorted.size()) return sorted.back();
  return sorted[below] + (h - double(below)) * (sorted[below + 1] - sorted[below]);
}

double student_t_quantile(double p, double degrees_of_freedom) {
  if (!(p > 0.0 && p < 1.0)) throw aco::Error("Student t quantile: probability " + text(p) + " is outside (0, 1)");
  if (!(degrees_of_freedom > 0.0) || !std::isfinite(degrees_of_freedom))
    throw aco::Error("Student t quantile: degrees of freedom " + text(degrees_of_freedom) +
                     " must be positive and finite");
  return boost::math::quantile(boost::math::students_t(degrees_of_freedom), p);
}

Summary summarize(std::span<const double> sample) {
  require_finite(sample, "summarize");
  Summary s;
  s.n = sample.size();
  if (s.n == 0) return s;
  std::vector<double> sorted(sample.begin(), sample.end());
  std::sort(sorted.begin(), sorted.end());
  const double n = double(s.n);
  s.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / n;
  s.median = quantile(sorted, 0.5);
  s.q1 = quantile(sorted, 0.25);
  s.q3 = quantile(sorted, 0.75);
  s.iqr = s.q3 - s.q1;
  s.min = sorted.front();
  s.max = sorted.back();
  if (s.n < 2) return s;
  // Two passes: summing squared deviations from the mean loses less precision than sum x^2 - n mean^2.
  double squares = 0.0;
  for (double x : sorted) squares += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(squares / (n - 1.0));
  const double half_width = student_t_quantile(0.975, n - 1.0) * s.stddev / std::sqrt(n);
  s.ci_low = s.mean - half_width;
  s.ci_high = s.mean + half_width;
  return s;
}

std::vector<double> ranks(std::span<const double> values) {
  require_finite(values, "ranks");
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> result(values.size());
  for (std::size_t begin = 0; begin < order.size();) {
    std::size_t end = begin + 1;
    while (end < order.size() && values[order[end]] == values[order[begin]]) ++end;
    const double shared = double(begin + 1 + end) / 2.0;  // mean of the ranks begin+1 .. end
    for (std::size_t k = begin; k < end; ++k) result[order[k]] = shared;
    begin = end;
  }
  return result;
}

MannWhitney mann_whitney_u(std::span<const double> first, std::span<const double> second) {
  require_samples(first, second, "Mann-Whitney U test");
  std::vector<double> pooled(first.begin(), first.end());
  pooled.insert(pooled.end(), second.begin(), second.end());
  const std::vector<double> pooled_ranks = ranks(pooled);
  const double n1 = double(first.size()), n2 = double(second.size()), n = n1 + n2;

  std::sort(pooled.begin(), pooled.end());
  double tie_term = 0.0;  // sum over groups of tied values of t^3 - t
  for (auto begin = pooled.begin(); begin != pooled.end();) {
    const auto end = std::upper_bound(begin, pooled.end(), *begin);
    const double t = double(end - begin);
    tie_term += t * t * t - t;
    begin = end;
  }

  MannWhitney result;
  result.u = u_statistic(pooled_ranks, first.size());
  const double larger_u = std::max(result.u, n1 * n2 - result.u);
  result.exact = tie_term == 0.0 && std::min(first.size(), second.size()) <= 8;
  if (result.exact) {
    result.p = 2.0 * exact_upper_tail(larger_u, first.size(), second.size());
  } else {
    const double sigma = std::sqrt(n1 * n2 / 12.0 * ((n + 1.0) - tie_term / (n * (n - 1.0))));
    // Every value tied: no evidence of any difference (SciPy's z = -inf gives the same p = 1).
    result.p = sigma > 0.0 ? 2.0 * standard_normal_upper_tail((larger_u - n1 * n2 / 2.0 - 0.5) / sigma) : 1.0;
  }
  result.p = std::min(result.p, 1.0);
  return result;
}

std::vector<double> holm_adjust(std::span<const double> p_values) {
  for (std::size_t i = 0; i < p_values.size(); ++i)
    if (!(p_values[i] >= 0.0 && p_values[i] <= 1.0))
      throw aco::Error("Holm adjustment: p value " + std::to_string(i + 1) + " is " + text(p_values[i]) +
                       ", outside [0, 1]");
  std::vector<std::size_t> order(p_values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p_values[a] < p_values[b]; });
  std::vector<double> adjusted(p_values.size());
  double running_max = 0.0;  // step-down: an adjusted p never falls below the one before it
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    const double factor = double(order.size() - rank);
    running_max = std::max(running_max, std::min(1.0, factor * p_values[order[rank]]));
    adjusted[order[rank]] = running_max;
  }
  return adjusted;
}

double vargha_delaney_a12(std::span<const double> first, std::span<const double> second) {
  require_samples(first, second, "Vargha-Delaney A12");
  std::vector<double> pooled(first.begin(), first.end());
  pooled.insert(pooled.end(), second.begin(), second.end());
  return u_statistic(ranks(pooled), first.size()) / (double(first.size()) * double(second.size()));
}

EffectSize effect_size(double a12) {
  if (!(a12 >= 0.0 && a12 <= 1.0)) throw aco::Error("effect size: A12 " + text(a12) + " is outside [0, 1]");
  const double distance = std::max(a12, 1.0 - a12);
  if (distance < 0.56) return EffectSize::negligible;
  if (distance < 0.64) return EffectSize::small;
  if (distance < 0.71) return EffectSize::medium;
  return EffectSize::large;
}

std::string_view to_string(EffectSize size) {
  switch (size) {
    case EffectSize::negligible:
      return "negligible";
    case EffectSize::small:
      return "small";
    case EffectSize::medium:
      return "medium";
    case EffectSize::large:
      return "large";
  }
  return "unknown";
}

std::vector<double> average_ranks(const std::vector<std::vector<double>>& scores) {
  if (scores.empty() || scores.front().empty())
    throw aco::Error("average ranks need at least one configuration and one problem");
  const std::size_t problems = scores.front().size();
  for (std::size_t c = 0; c < scores.size(); ++c) {
    if (scores[c].size() != problems)
      throw aco::Error("average ranks: configuration " + std::to_string(c + 1) + " has " +
                       std::to_string(scores[c].size()) + " scores, the first has " + std::to_string(problems));
    require_finite(scores[c], "average ranks, configuration " + std::to_string(c + 1));
  }
  std::vector<double> sums(scores.size(), 0.0);
  std::vector<double> column(scores.size());
  for (std::size_t p = 0; p < problems; ++p) {
    for (std::size_t c = 0; c < scores.size(); ++c) column[c] = scores[c][p];
    const std::vector<double> on_problem = ranks(column);
    for (std::size_t c = 0; c < scores.size(); ++c) sums[c] += on_problem[c];
  }
  for (double& sum : sums) sum /= double(problems);
  return sums;
}

double hitting_time(std::span<const double> effort, std::span<const double> value, double target) {
  if (effort.size() != value.size())
    throw aco::Error("hitting time: " + std::to_string(effort.size()) + " efforts for " + std::to_string(value.size()) +
                     " values");
  for (std::size_t i = 0; i < value.size(); ++i)
    if (value[i] <= target) return effort[i];
  return std::numeric_limits<double>::infinity();
}

std::vector<double> ecdf(std::span<const double> hitting_times, std::span<const double> at) {
  std::vector<double> sorted(hitting_times.begin(), hitting_times.end());
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> shares;
  for (const double t : at) {
    const auto reached = std::upper_bound(sorted.begin(), sorted.end(), t) - sorted.begin();
    shares.push_back(sorted.empty() ? 0.0 : double(reached) / double(sorted.size()));
  }
  return shares;
}

double expected_running_time(std::span<const double> hitting_times, std::span<const double> run_efforts) {
  if (hitting_times.size() != run_efforts.size())
    throw aco::Error("expected running time: " + std::to_string(hitting_times.size()) + " hitting times for " +
                     std::to_string(run_efforts.size()) + " runs");
  double spent = 0.0;
  std::size_t hits = 0;
  for (std::size_t i = 0; i < hitting_times.size(); ++i) {
    const bool hit = std::isfinite(hitting_times[i]);
    spent += hit ? hitting_times[i] : run_efforts[i];
    hits += hit ? 1 : 0;
  }
  return hits == 0 ? std::numeric_limits<double>::infinity() : spent / double(hits);
}

}  // namespace aco::studies
