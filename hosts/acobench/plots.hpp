#pragma once
// acobench's plots: self-contained SVG strings (no scripts, no external fonts or images) to
// paste inline into the HTML report. The root <svg> element carries class="boxplot" or
// class="convergence". The same input always gives the same bytes: numbers are written with
// std::to_chars, never through a locale.
#include <optional>
#include <string>
#include <vector>

namespace acobench {

struct NamedSample {
  std::string name;
  std::vector<double> values;  // finite; an empty sample is labelled "no data"
};

// Vertical Tukey box plots: the box spans the quartiles (type 7, see Summary), the whiskers reach
// the most extreme values within 1.5 IQR of the box, the values beyond are drawn as dots.
struct BoxPlot {
  std::string title;
  std::string value_label;          // the y axis, e.g. "path length"
  std::vector<NamedSample> samples;
  std::optional<double> reference;  // a dashed horizontal line, e.g. the optimal length
  std::string reference_label = "optimum";
};

std::string box_plot_svg(const BoxPlot& plot);

// The k-th colour of the plots' palette (it repeats after ten), for drawings that match them.
const char* colour(std::size_t k);

// One curve of a line chart: value[i] is drawn at x = i + 1 (the iteration). A non-finite value
// leaves a gap; the band is shaded between band_low and band_high where both are finite.
struct Series {
  std::string name;
  std::vector<double> value;
  std::vector<double> band_low;   // empty, or as long as value
  std::vector<double> band_high;  // empty, or as long as value
};

// The mean of several runs' per-iteration curves (e.g. best-so-far lengths) with its 95 %
// confidence interval as the band. A run shorter than the longest (stopped early) keeps its last
// value, as a best-so-far curve does. At each iteration only the runs with a finite value (a path
// found by then) count; where fewer than two do, there is no band.
Series convergence_series(std::string name, const std::vector<std::vector<double>>& runs);

struct LineChart {
  std::string title;
  std::string x_label = "iteration";
  std::string y_label;
  std::vector<Series> series;
  std::optional<double> reference;
  std::string reference_label = "optimum";
};

std::string line_chart_svg(const LineChart& chart);

}  // namespace acobench
