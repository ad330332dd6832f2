// acobench's statistics and plots, against values worked out by hand (written down next to each
// check), SciPy's documented results, and brute-force enumeration of the Mann-Whitney null
// distribution.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numeric>

#include "aco/error.hpp"
#include "aco/studies/plots.hpp"
#include "aco/studies/statistics.hpp"
#include "support.hpp"

namespace {

using Catch::Matchers::Contains;

// Two-sided exact p of Mann-Whitney by enumerating every way to give n1 of the ranks 1..n1+n2 to
// the first sample (no ties): 2 P(U >= max(U1, U2)), at most 1.
double enumerated_exact_p(std::size_t n1, std::size_t n2, double u1) {
  const std::size_t n = n1 + n2;
  const double larger = std::max(u1, double(n1 * n2) - u1);
  std::vector<bool> chosen(n, false);
  std::fill(chosen.begin(), chosen.begin() + std::ptrdiff_t(n1), true);
  double total = 0, at_least = 0;
  do {  // prev_permutation walks every arrangement of n1 trues among n places once
    double rank_sum = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (chosen[i]) rank_sum += double(i + 1);
    total += 1;
    at_least += rank_sum - double(n1 * (n1 + 1)) / 2 >= larger;
  } while (std::prev_permutation(chosen.begin(), chosen.end()));
  return std::min(1.0, 2 * at_least / total);
}

std::size_t count(const std::string& text, const std::string& word) {
  std::size_t found = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + word.size())) ++found;
  return found;
}

// Every opened element is closed in order, and the document is one <svg> root with no stray '<'
// or '>' in text: enough to catch a forgotten "/>" or an unescaped name.
bool well_formed(const std::string& svg) {
  if (svg.rfind("<svg", 0) != 0) return false;
  std::vector<std::string> open;
  std::size_t roots = 0, at = 0;
  while (at < svg.size()) {
    const std::size_t begin = svg.find('<', at);
    if (svg.substr(at, begin - at).find('>') != std::string::npos) return false;
    if (begin == std::string::npos) break;
    const std::size_t end = svg.find('>', begin);
    if (end == std::string::npos) return false;
    const std::string tag = svg.substr(begin + 1, end - begin - 1);
    if (tag.find('<') != std::string::npos) return false;
    const bool closing = tag.front() == '/', empty = tag.back() == '/';
    const std::string name = tag.substr(closing, tag.find_first_of(" /", 1) - closing);
    if (closing) {
      if (open.empty() || open.back() != name) return false;
      open.pop_back();
    } else {
      roots += open.empty();
      if (!empty) open.push_back(name);
    }
    at = end + 1;
  }
  return open.empty() && roots == 1;
}

bool has_undefined_number(const std::string& svg) {
  return svg.find("nan") != std::string::npos || svg.find("inf") != std::string::npos;
}

}  // namespace

TEST_CASE("summarize gives the textbook statistics of a small sample", "[statistics]") {
  // Sorted: 2 4 4 4 5 5 7 9. Mean 40/8 = 5; squared deviations 9+1+1+1+0+0+4+16 = 32, sd = sqrt(32/7).
  // Type 7: q1 at h = 7/4 = 1.75 -> 4 + 0.75 (4 - 4) = 4; median at 3.5 -> 4.5; q3 at 5.25 -> 5 + 0.25 (7 - 5) = 5.5.
  // CI half-width t(0.975, 7) sd / sqrt(8) = 2.3646242516 * 2.1380899353 / 2.8284271247 = 1.7874879182.
  const std::vector<double> sample{5, 2, 9, 4, 4, 7, 4, 5};
  const auto s = aco::studies::summarize(sample);
  CHECK(s.n == 8);
  CHECK(s.mean == Approx(5));
  CHECK(s.stddev == Approx(std::sqrt(32.0 / 7)));
  CHECK(s.median == Approx(4.5));
  CHECK(s.q1 == Approx(4));
  CHECK(s.q3 == Approx(5.5));
  CHECK(s.iqr == Approx(1.5));
  CHECK(s.ci_low == Approx(5 - 1.7874879182).epsilon(1e-9));
  CHECK(s.ci_high == Approx(5 + 1.7874879182).epsilon(1e-9));
  CHECK(s.min == 2);
  CHECK(s.max == 9);
}

TEST_CASE("quantiles interpolate linearly like numpy's default", "[statistics]") {
  const std::vector<double> sorted{1, 2, 3, 4};
  CHECK(aco::studies::quantile(sorted, 0.25) == Approx(1.75));  // numpy.percentile([1,2,3,4], 25)
  CHECK(aco::studies::quantile(sorted, 0.5) == Approx(2.5));
  CHECK(aco::studies::quantile(sorted, 0.9) == Approx(3.7));
  CHECK(aco::studies::quantile(sorted, 0) == 1);
  CHECK(aco::studies::quantile(sorted, 1) == 4);
  CHECK_THROWS_WITH(aco::studies::quantile(sorted, 1.5), Contains("1.5") && Contains("[0, 1]"));
  CHECK_THROWS_AS(aco::studies::quantile(std::vector<double>{}, 0.5), aco::Error);
}

TEST_CASE("empty and single-value samples give NaN where a statistic is undefined", "[statistics]") {
  const auto empty = aco::studies::summarize(std::vector<double>{});
  CHECK(empty.n == 0);
  CHECK(std::isnan(empty.mean));
  CHECK(std::isnan(empty.median));
  CHECK(std::isnan(empty.min));
  const auto one = aco::studies::summarize(std::vector<double>{3.5});
  CHECK(one.n == 1);
  CHECK(one.mean == 3.5);
  CHECK(one.median == 3.5);
  CHECK(one.q1 == 3.5);
  CHECK(one.iqr == 0);
  CHECK(one.min == 3.5);
  CHECK(one.max == 3.5);
  CHECK(std::isnan(one.stddev));
  CHECK(std::isnan(one.ci_low));
  CHECK(std::isnan(one.ci_high));
  const auto constant = aco::studies::summarize(std::vector<double>{2, 2, 2});
  CHECK(constant.stddev == 0);
  CHECK(constant.ci_low == 2);
  CHECK(constant.ci_high == 2);
}

TEST_CASE("statistics refuse non-finite values with a message naming the value", "[statistics]") {
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(aco::studies::summarize(std::vector<double>{1, inf, 3}),
                    Contains("summarize") && Contains("value 2 of 3 is inf"));
  CHECK_THROWS_WITH(aco::studies::mann_whitney_u(std::vector<double>{1}, std::vector<double>{std::nan("")}),
                    Contains("second sample") && Contains("nan"));
  CHECK_THROWS_WITH(aco::studies::mann_whitney_u(std::vector<double>{}, std::vector<double>{1, 2}),
                    Contains("non-empty") && Contains("sizes 0 and 2"));
  CHECK_THROWS_WITH(aco::studies::vargha_delaney_a12(std::vector<double>{1}, std::vector<double>{}),
                    Contains("non-empty"));
}

TEST_CASE("Student t quantiles match the tables", "[statistics]") {
  CHECK(aco::studies::student_t_quantile(0.975, 9) == Approx(2.262157).epsilon(1e-6));
  CHECK(aco::studies::student_t_quantile(0.975, 1) == Approx(12.706205).epsilon(1e-6));
  CHECK(aco::studies::student_t_quantile(0.975, 29) == Approx(2.045230).epsilon(1e-6));
  CHECK(aco::studies::student_t_quantile(0.95, 5) == Approx(2.015048).epsilon(1e-6));
  CHECK(aco::studies::student_t_quantile(0.025, 9) == Approx(-2.262157).epsilon(1e-6));
  CHECK_THROWS_WITH(aco::studies::student_t_quantile(1.0, 9), Contains("probability 1"));
  CHECK_THROWS_WITH(aco::studies::student_t_quantile(0.5, 0), Contains("degrees of freedom 0"));
}

TEST_CASE("Mann-Whitney reproduces SciPy's documented example exactly and asymptotically", "[statistics]") {
  // scipy.stats.mannwhitneyu docs: males vs females, U1 = 17, exact p = 0.1111111111111111
  // (2 * 7 / 126: 7 of the C(9, 4) = 126 arrangements have U <= 3).
  const std::vector<double> males{19, 22, 16, 29, 24};
  const std::vector<double> females{20, 11, 17, 12};
  const auto exact = aco::studies::mann_whitney_u(males, females);
  CHECK(exact.exact);
  CHECK(exact.u == 17);
  CHECK(exact.p == Approx(2.0 * 7 / 126).epsilon(1e-12));
  CHECK(exact.p == Approx(enumerated_exact_p(5, 4, 17)).epsilon(1e-12));
  // The other way round: U1 = 20 - 17 = 3, the same p.
  const auto swapped = aco::studies::mann_whitney_u(females, males);
  CHECK(swapped.u == 3);
  CHECK(swapped.p == Approx(exact.p).epsilon(1e-12));
}

TEST_CASE("Mann-Whitney exact p values agree with enumerating every rank assignment", "[statistics]") {
  // No ties; the smaller sample has at most 8 values, so the exact distribution is used even when
  // the other sample is large (SciPy's method="auto").
  const std::vector<double> a{3.1, 7.4, 0.2, 9.9, 5.5, 6.1};
  const std::vector<double> b{4.4, 8.8, 1.3, 2.7, 10.5, 11.2, 12.9};
  const auto r = aco::studies::mann_whitney_u(a, b);
  CHECK(r.exact);
  CHECK(r.p == Approx(enumerated_exact_p(a.size(), b.size(), r.u)).epsilon(1e-12));

  const std::vector<double> few{0.5, 13.5, 21.5};
  std::vector<double> many;
  for (int i = 0; i < 20; ++i) many.push_back(i + (i % 3) * 0.01);
  const auto lopsided = aco::studies::mann_whitney_u(few, many);
  CHECK(lopsided.exact);
  CHECK(lopsided.u == Approx(1 + 14 + 20));  // values of `many` below each of `few`
  CHECK(lopsided.p == Approx(enumerated_exact_p(few.size(), many.size(), lopsided.u)).epsilon(1e-12));

  // Completely separated samples of 4 and 4: p = 2 / C(8, 4) = 2 / 70.
  const auto separated = aco::studies::mann_whitney_u(std::vector<double>{1, 2, 3, 4}, std::vector<double>{5, 6, 7, 8});
  CHECK(separated.u == 0);
  CHECK(separated.p == Approx(2.0 / 70).epsilon(1e-12));
  // The far tail stays accurate: 8 values all below 30 others, p = 2 / C(38, 8) = 2 / 48903492.
  std::vector<double> below(8), above(30);
  std::iota(below.begin(), below.end(), 0.0);
  std::iota(above.begin(), above.end(), 100.0);
  CHECK(aco::studies::mann_whitney_u(below, above).p == Approx(2.0 / 48903492).epsilon(1e-12));
}

TEST_CASE("Mann-Whitney with ties uses the tie-corrected normal approximation", "[statistics]") {
  // Pooled, sorted: 1 | 2 2 2 | 3 3 3 | 4 4 | 5 -> mid-ranks 1, 3, 6, 8.5, 10.
  // R1 = 1 + 3 + 3 + 6 + 6 = 19, U1 = 19 - 15 = 4, U2 = 21. Ties: (27-3) + (27-3) + (8-2) = 54.
  // sigma = sqrt(25/12 (11 - 54/90)) = 4.6547466813; z = (21 - 12.5 - 0.5) / sigma = 1.7186756977;
  // p = erfc(z / sqrt 2) = 0.0856734396.
  const auto r = aco::studies::mann_whitney_u(std::vector<double>{1, 2, 2, 3, 3}, std::vector<double>{2, 3, 4, 4, 5});
  CHECK_FALSE(r.exact);
  CHECK(r.u == 4);
  CHECK(r.p == Approx(0.08567343955231692).epsilon(1e-9));

  // Every value tied: sigma = 0 and no evidence of a difference (SciPy: z = -inf, p clipped to 1).
  const auto all_tied = aco::studies::mann_whitney_u(std::vector<double>{7, 7, 7}, std::vector<double>{7, 7});
  CHECK_FALSE(all_tied.exact);
  CHECK(all_tied.u == 3);
  CHECK(all_tied.p == 1);
}

TEST_CASE("Mann-Whitney switches to the approximation when both samples exceed 8 values", "[statistics]") {
  std::vector<double> low, high;
  for (int i = 0; i < 9; ++i) low.push_back(i), high.push_back(i + 4.5);
  // U1 = pairs with low > high: low i beats high j when i > j + 4.5, i.e. j <= i - 5: sum_{i=5..8} (i - 4) = 10.
  // sigma = sqrt(81 * 19 / 12) = 11.3247516529; z = 30 / sigma = 2.6490647141; p = erfc(z / sqrt 2) = 0.0080714874.
  const auto r = aco::studies::mann_whitney_u(low, high);
  CHECK_FALSE(r.exact);
  CHECK(r.u == 10);
  const double z = 30.0 / std::sqrt(81.0 * 19 / 12);
  CHECK(r.p == Approx(std::erfc(z / std::sqrt(2.0))).epsilon(1e-12));
  CHECK(r.p == Approx(0.008071487425268021).epsilon(1e-9));
}

TEST_CASE("Holm adjustment is step-down, monotone, in input order and capped at 1", "[statistics]") {
  // Sorted 0.005 0.01 0.03 0.04 -> x4, x3, x2, x1 = 0.02 0.03 0.06 0.04 -> running max 0.02 0.03 0.06 0.06.
  const auto adjusted = aco::studies::holm_adjust(std::vector<double>{0.01, 0.04, 0.03, 0.005});
  REQUIRE(adjusted.size() == 4);
  CHECK(adjusted[0] == Approx(0.03));
  CHECK(adjusted[1] == Approx(0.06));
  CHECK(adjusted[2] == Approx(0.06));
  CHECK(adjusted[3] == Approx(0.02));
  const auto capped = aco::studies::holm_adjust(std::vector<double>{0.5, 0.4, 0.9});
  CHECK(capped == std::vector<double>{1, 1, 1});
  CHECK(aco::studies::holm_adjust(std::vector<double>{}).empty());
  CHECK_THROWS_WITH(aco::studies::holm_adjust(std::vector<double>{0.1, 1.2}), Contains("p value 2") && Contains("1.2"));
}

TEST_CASE("Vargha-Delaney A12 counts wins and half ties, and is labelled symmetrically", "[statistics]") {
  // first {1,2,3} vs second {2,2,4}: 1 wins none; 2 ties twice (1); 3 beats both 2s (2): 3 of 9.
  const std::vector<double> first{1, 2, 3}, second{2, 2, 4};
  const double a12 = aco::studies::vargha_delaney_a12(first, second);
  CHECK(a12 == Approx(1.0 / 3));
  CHECK(aco::studies::vargha_delaney_a12(second, first) == Approx(2.0 / 3));
  CHECK(a12 == Approx(aco::studies::mann_whitney_u(first, second).u / 9));
  CHECK(aco::studies::effect_size(a12) == aco::studies::EffectSize::medium);
  CHECK(aco::studies::effect_size(0.5) == aco::studies::EffectSize::negligible);
  CHECK(aco::studies::effect_size(0.55) == aco::studies::EffectSize::negligible);
  CHECK(aco::studies::effect_size(0.6) == aco::studies::EffectSize::small);
  CHECK(aco::studies::effect_size(0.4) == aco::studies::EffectSize::small);
  CHECK(aco::studies::effect_size(0.7) == aco::studies::EffectSize::medium);
  CHECK(aco::studies::effect_size(0.75) == aco::studies::EffectSize::large);
  CHECK(aco::studies::effect_size(0.0) == aco::studies::EffectSize::large);
  CHECK(aco::studies::to_string(aco::studies::EffectSize::small) == "small");
  CHECK_THROWS_WITH(aco::studies::effect_size(1.5), Contains("1.5"));
}

TEST_CASE("average ranks across problems share tied ranks", "[statistics]") {
  // Problem 0: 1 2 2 -> 1 2.5 2.5; problem 1: 5 5 4 -> 2.5 2.5 1; problem 2: 3 1 2 -> 3 1 2.
  const std::vector<std::vector<double>> scores{{1, 5, 3}, {2, 5, 1}, {2, 4, 2}};
  const auto average = aco::studies::average_ranks(scores);
  REQUIRE(average.size() == 3);
  CHECK(average[0] == Approx(6.5 / 3));
  CHECK(average[1] == Approx(2.0));
  CHECK(average[2] == Approx(5.5 / 3));
  CHECK(aco::studies::ranks(std::vector<double>{10, 30, 20, 30}) == std::vector<double>{1, 3.5, 2, 3.5});
  CHECK_THROWS_WITH(aco::studies::average_ranks({{1, 2}, {1}}), Contains("configuration 2 has 1 scores"));
  CHECK_THROWS_AS(aco::studies::average_ranks({}), aco::Error);
}

TEST_CASE("box plots draw one box per sample, Tukey outliers and the reference line", "[statistics][plots]") {
  aco::studies::BoxPlot plot;
  plot.title = "lengths on <map1> & co";
  plot.value_label = "path length";
  // 1..9 and 30: q1 3.25, q3 7.75, IQR 4.5, upper fence 14.5, so 30 is the only outlier.
  plot.samples = {{"ant_system", {1, 2, 3, 4, 5, 6, 7, 8, 9, 30}}, {"max_min", {4, 5, 6}}, {"acs", {5, 5, 5}}};
  plot.reference = 3.25;
  const std::string svg = aco::studies::box_plot_svg(plot);
  REQUIRE_FALSE(well_formed("<svg><g></svg>"));  // the checker itself can fail
  REQUIRE_FALSE(well_formed("<svg><text>a < b</text></svg>"));
  REQUIRE(well_formed("<svg><g/><text>a</text></svg>\n"));
  CHECK(well_formed(svg));
  CHECK(count(svg, "class=\"boxplot\"") == 1);
  CHECK(count(svg, "class=\"box\"") == 3);
  CHECK(count(svg, "class=\"median\"") == 3);
  CHECK(count(svg, "class=\"outlier\"") == 1);
  CHECK(count(svg, "class=\"reference\"") == 1);
  CHECK_THAT(svg, Contains("optimum 3.25") && Contains("lengths on &lt;map1&gt; &amp; co") && Contains(">max_min<"));
  CHECK_FALSE(has_undefined_number(svg));
  CHECK(svg == aco::studies::box_plot_svg(plot));
  // The reference's label is a key above the frame, clear of every box (it lay across the last one).
  const auto number_after = [&](std::size_t from, const std::string& attribute) {
    const std::size_t at = svg.find(attribute + "=\"", from);
    REQUIRE(at != std::string::npos);
    return std::stod(svg.substr(at + attribute.size() + 2));
  };
  const std::size_t key = svg.find("class=\"reference-key\"");
  REQUIRE(key != std::string::npos);
  const double key_baseline = number_after(svg.find("<text", key), "y");
  const double frame_top = number_after(svg.find("<rect", svg.find("class=\"y-axis\"")), "y");
  CHECK(key_baseline < frame_top);
  for (std::size_t box = svg.find("class=\"box\""); box != std::string::npos; box = svg.find("class=\"box\"", box + 1))
    CHECK(key_baseline < number_after(box, "y"));
}

TEST_CASE("box plots of constant, empty or no samples stay free of NaN", "[statistics][plots]") {
  aco::studies::BoxPlot plot;
  plot.samples = {{"flat", {34.3848, 34.3848}}, {"unsolved", {}}};
  const std::string svg = aco::studies::box_plot_svg(plot);
  CHECK(well_formed(svg));
  CHECK(count(svg, "class=\"box\"") == 1);
  CHECK_THAT(svg, Contains("unsolved (no data)"));
  CHECK_FALSE(has_undefined_number(svg));
  const std::string nothing = aco::studies::box_plot_svg({});
  CHECK(well_formed(nothing));
  CHECK_THAT(nothing, Contains("no data"));
  CHECK_FALSE(has_undefined_number(nothing));
  plot.reference = std::nan("");
  CHECK_THROWS_WITH(aco::studies::box_plot_svg(plot), Contains("reference line") && Contains("not finite"));
  plot.reference.reset();
  plot.samples.push_back({"broken", {1, std::numeric_limits<double>::infinity()}});
  CHECK_THROWS_WITH(aco::studies::box_plot_svg(plot), Contains("sample \"broken\"") && Contains("inf"));
}

TEST_CASE("box plots slant long sample names and cut the longest", "[statistics][plots]") {
  aco::studies::BoxPlot plot;
  plot.samples = {
      {"max_min rho=0.02 p_best=0.05 & smoother=prune local=dwa", {1, 2}}, {"acs", {2, 3}}, {"ant_system", {1}}};
  const std::string svg = aco::studies::box_plot_svg(plot);
  CHECK(well_formed(svg));
  CHECK(count(svg, "rotate(-45") == 3);
  CHECK_THAT(svg, Contains(">max_min rho=0.02 p_best=0.05 &amp; smoother\u2026<") && Contains(">acs<"));
  CHECK_THAT(svg, Contains("<title>max_min rho=0.02 p_best=0.05 &amp; smoother=prune local=dwa: n 2"));
  CHECK(test::texts_outside_view_box(svg).empty());
}

TEST_CASE("convergence series average the runs with a 95 % band", "[statistics][plots]") {
  const double none = std::numeric_limits<double>::infinity();  // no path yet
  // Iteration 1: only the second run has a path; 2: 10 and 10; 3: the first run stopped at 10, 8.
  const auto s = aco::studies::convergence_series("acs", {{none, 10}, {12, 10, 8}});
  REQUIRE(s.value.size() == 3);
  CHECK(s.value[0] == 12);
  CHECK(std::isnan(s.band_low[0]));
  CHECK(s.value[1] == 10);
  CHECK(s.band_low[1] == 10);
  CHECK(s.value[2] == 9);
  // sd of {10, 8} = sqrt 2, half-width t(0.975, 1) sqrt 2 / sqrt 2 = 12.7062047362.
  CHECK(s.band_high[2] == Approx(9 + 12.7062047362).epsilon(1e-9));
}

TEST_CASE("convergence charts draw a line and a band per series, a legend and axes", "[statistics][plots]") {
  aco::studies::LineChart chart;
  chart.title = "classic map1";
  chart.y_label = "best length so far";
  chart.series = {
      aco::studies::convergence_series("ant_system", {{40, 38, 36, 35}, {41, 37, 37, 34.5}, {39, 39, 35, 35}}),
      aco::studies::convergence_series("max_min", {{42, 36, 34.4, 34.4}, {40, 35, 34.4, 34.4}})};
  chart.reference = 34.3848;
  const std::string svg = aco::studies::line_chart_svg(chart);
  CHECK(well_formed(svg));
  CHECK(count(svg, "class=\"convergence\"") == 1);
  CHECK(count(svg, "class=\"series\"") == 2);
  CHECK(count(svg, "class=\"band\"") == 2);
  CHECK(count(svg, "class=\"reference\"") == 1);
  CHECK_THAT(svg, Contains(">ant_system<") && Contains(">max_min<") && Contains(">iterations run<") &&
                      Contains(">best length so far<"));
  CHECK_FALSE(has_undefined_number(svg));
  CHECK(svg == aco::studies::line_chart_svg(chart));

  aco::studies::LineChart flat;
  flat.series = {{"one run", {5, 5, 5}, {}, {}, {}}, {"one point", {7}, {}, {}, {}}};
  const std::string flat_svg = aco::studies::line_chart_svg(flat);
  CHECK(well_formed(flat_svg));
  CHECK(count(flat_svg, "class=\"band\"") == 0);
  CHECK_FALSE(has_undefined_number(flat_svg));
  CHECK_FALSE(has_undefined_number(aco::studies::line_chart_svg({})));

  flat.series.push_back({"bad band", {1, 2}, {1}, {2, 3}, {}});
  CHECK_THROWS_WITH(aco::studies::line_chart_svg(flat), Contains("\"bad band\"") && Contains("band has 1 low"));
  flat.series.back() = {"bad x", {1, 2}, {}, {}, {0.5}};
  CHECK_THROWS_WITH(aco::studies::line_chart_svg(flat), Contains("\"bad x\"") && Contains("1 x values for 2 values"));
}

TEST_CASE("hitting times, the fixed-target ECDF and the expected running time on a hand-worked case",
          "[statistics][anytime]") {
  const double never = std::numeric_limits<double>::infinity();
  // A run's efforts (seconds) per iteration and its best gap by then.
  const std::vector<double> effort{0.1, 0.2, 0.4, 0.8}, gap{never, 7.0, 4.5, 1.0};
  CHECK(aco::studies::hitting_time(effort, gap, 5.0) == 0.4);
  CHECK(aco::studies::hitting_time(effort, gap, 7.0) == 0.2);  // reaching the target exactly counts
  CHECK(aco::studies::hitting_time(effort, gap, 1.0) == 0.8);
  CHECK(aco::studies::hitting_time(effort, gap, 0.5) == never);
  CHECK_THROWS_WITH(aco::studies::hitting_time(effort, std::vector<double>{1.0}, 5.0),
                    Contains("4 efforts for 1 values"));

  // Four runs reached the target at 0.5, 2 and 1 s, the third never: 1/4 by 0.5 s, 2/4 by 1 s,
  // 3/4 from 2 s on, never 4/4.
  const std::vector<double> hits{0.5, 2.0, never, 1.0};
  const std::vector<double> at{0.1, 0.5, 0.99, 1.0, 1.5, 2.0, 1000.0};
  CHECK(aco::studies::ecdf(hits, at) == std::vector<double>{0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75});
  CHECK(aco::studies::ecdf(std::vector<double>{}, at) == std::vector<double>(at.size(), 0.0));
  // ERT: the three hits' times plus the whole 4 s of the run that missed, over 3 hits.
  CHECK(aco::studies::expected_running_time(hits, std::vector<double>{3.0, 3.0, 4.0, 3.0}) ==
        Approx((0.5 + 2 + 4 + 1) / 3.0));
  CHECK(aco::studies::expected_running_time(std::vector<double>{never}, std::vector<double>{2.0}) == never);

  // The ECDF as a step series from 0.25 to 8 s: 0 at the start, a step at each hit, flat to the end.
  const auto series = aco::studies::ecdf_series("acs", hits, 0.25, 8.0);
  CHECK(series.x == std::vector<double>{0.25, 0.5, 1.0, 2.0, 8.0});
  CHECK(series.value == std::vector<double>{0.0, 0.25, 0.5, 0.75, 0.75});
}

TEST_CASE("anytime means: step curves on their own x, the same runs throughout if asked",
          "[statistics][plots][anytime]") {
  const double none = std::numeric_limits<double>::infinity();
  // Run 1 ends its iterations at 1, 2, 4 s with gaps inf, 10, 6; run 2 at 3 and 5 s with 20, 2.
  const std::vector<aco::studies::StepCurve> runs{{{1, 2, 4}, {none, 10, 6}}, {{3, 5}, {20, 2}}};
  const std::vector<double> at{1, 2, 3, 4, 5, 6};
  const auto any = aco::studies::mean_series("any", runs, at);
  CHECK(any.x == at);
  REQUIRE(any.value.size() == 6);
  CHECK(std::isnan(any.value[0]));  // no path yet
  CHECK(any.value[1] == 10);  // run 1 alone
  CHECK(any.value[2] == 15);  // (10 + 20) / 2
  CHECK(any.value[3] == 13);  // (6 + 20) / 2
  CHECK(any.value[4] == 4);  // (6 + 2) / 2
  CHECK(any.value[5] == 4);  // both ended: their last values
  const auto same = aco::studies::mean_series("same", runs, at, true);
  CHECK(std::isnan(same.value[1]));  // run 2 has no path before 3 s
  CHECK(same.value[2] == 15);
  CHECK(same.value[5] == 4);
  // A run that never finds a path does not hold the others' mean back.
  auto with_unsolved = runs;
  with_unsolved.push_back({{1, 2}, {none, none}});
  CHECK(aco::studies::mean_series("same", with_unsolved, at, true).value[2] == 15);

  const auto points = aco::studies::log_spaced(0.001, 10, 5);
  REQUIRE(points.size() == 5);
  CHECK(points.front() == 0.001);
  CHECK(points[1] == Approx(0.01));
  CHECK(points[3] == Approx(1));
  CHECK(points.back() == 10);
  CHECK(aco::studies::log_spaced(2, 2, 5) == std::vector<double>{2});
}

TEST_CASE("line charts with their own x: a log axis, steps, fixed y range, and a legend never cut",
          "[statistics][plots][anytime]") {
  aco::studies::LineChart chart;
  chart.title = "within 1 %";
  chart.x_label = "seconds";
  chart.css_class = "ecdf";
  chart.log_x = chart.steps = true;
  chart.y_range = std::pair(0.0, 1.0);
  const double never = std::numeric_limits<double>::infinity();
  chart.series = {aco::studies::ecdf_series("acs", {0.00002, 0.0004, never}, 0.00001, 0.03),
                  aco::studies::ecdf_series("max_min", {0.001, 0.002}, 0.00001, 0.03)};
  const std::string svg = aco::studies::line_chart_svg(chart);
  CHECK(well_formed(svg));
  CHECK(count(svg, "class=\"ecdf\"") == 1);
  CHECK(count(svg, "class=\"series\"") == 2);
  CHECK(count(svg, "class=\"band\"") == 0);
  // Decades from 1e-5 to 0.1, small ones written with an exponent; shares from 0 to 1.
  CHECK_THAT(svg, Contains(">1e-5<") && Contains(">1e-4<") && Contains(">0.001<") && Contains(">0.1<") &&
                      Contains(">0.2<") && Contains(">1<"));
  CHECK_FALSE(svg.find(">1.2<") != std::string::npos);
  CHECK_THAT(svg, Contains("V"));  // steps: horizontal, then vertical
  CHECK_FALSE(has_undefined_number(svg));
  CHECK(svg == aco::studies::line_chart_svg(chart));
  CHECK_THAT(svg, Contains("width=\"640\""));

  // A longer name widens the legend beside the plot (the plotting area first, then the picture);
  // one too long for that puts the legend under the plot.
  chart.series[1].name = "003 obstacle-density init + wolf-pack";
  const std::string wider = aco::studies::line_chart_svg(chart);
  CHECK_THAT(wider,
             !Contains("width=\"640\"") && Contains("<g class=\"legend\">\n<line x1=\"386\" x2=\"406\" y1=\"50\""));
  chart.series[1].name = "003 obstacle-density init + wolf-pack update + Gaussian deposition";
  const std::string wide = aco::studies::line_chart_svg(chart);
  CHECK(well_formed(wide));
  CHECK_THAT(wide,
             Contains(">003 obstacle-density init + wolf-pack update + Gaussian deposition<") &&
                 Contains("<g class=\"legend\">\n<line x1=\"16\" x2=\"36\" y1=\"416\""));  // under the x axis title
  CHECK(test::texts_outside_view_box(wider).empty());
  CHECK(test::texts_outside_view_box(wide).empty());
}

namespace {

// Forty configurations with long names of digits and wide letters, as a study of many variants has.
std::vector<std::string> forty_long_names() {
  std::vector<std::string> names;
  for (int k = 1; k <= 40; ++k)
    names.push_back("configuration " + std::to_string(k) + " MMAS with alpha " + std::to_string(k * 0.25) +
                    " and a rather long name (wolf_pack, maximum)");
  return names;
}

}  // namespace

TEST_CASE("every plot's text lies inside its picture: forty long names, wide tick labels, long titles",
          "[statistics][plots][svg]") {
  const auto names = forty_long_names();
  aco::studies::BoxPlot box;
  box.title = "final path length of forty configurations on a map with a long name: Berlin_0_512.map";
  box.value_label = "path length";
  box.reference = 123456.789;
  for (std::size_t k = 0; k < names.size(); ++k)
    box.samples.push_back({names[k], {123000.0 + double(k), 124000.0 + double(k)}});
  const std::string boxes = aco::studies::box_plot_svg(box);
  CHECK(well_formed(boxes));
  for (const auto& text : test::texts_outside_view_box(boxes)) FAIL_CHECK("box plot: " << text);
  // A few short names stay level, side by side, in the 640-wide picture.
  box.samples.resize(3);
  for (std::size_t k = 0; k < 3; ++k) box.samples[k].name = "cfg " + std::to_string(k);
  const std::string level = aco::studies::box_plot_svg(box);
  CHECK(count(level, "rotate(-45") == 0);
  CHECK(test::texts_outside_view_box(level).empty());

  aco::studies::LineChart chart;
  chart.title = "best-so-far length (mean, 95 % CI) of forty configurations: Berlin_0_512.map";
  chart.y_label = "path length";
  chart.reference = 123456.789;
  for (std::size_t k = 0; k < names.size(); ++k)
    chart.series.push_back(aco::studies::convergence_series(names[k], {{130000.0 + double(k), 125000.0, 123500.0}}));
  for (const bool log_x : {false, true}) {
    chart.log_x = log_x;
    const std::string lines = aco::studies::line_chart_svg(chart);
    CHECK(well_formed(lines));
    for (const auto& text : test::texts_outside_view_box(lines)) FAIL_CHECK("line chart: " << text);
    CHECK_THAT(lines, Contains(">" + names.back() + "<"));  // the legend names every series in full
  }
}
