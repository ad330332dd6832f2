#pragma once
// acobench's plots: self-contained SVG strings (no scripts, no external fonts or images) to
// paste inline into the HTML report. The root <svg> element carries class="boxplot" or the line
// chart's css_class ("convergence" unless set). The same input always gives the same bytes: numbers are written with
// std::to_chars, never through a locale.
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace aco {
class Map;
}

namespace aco::studies {

struct NamedSample {
  std::string name;
  std::vector<double> values;  // finite; an empty sample is labelled "no data"
};

// Vertical Tukey box plots: the box spans the quartiles (type 7, see Summary), the whiskers reach
// the most extreme values within 1.5 IQR of the box, the values beyond are drawn as dots.
struct BoxPlot {
  std::string title;
  std::string value_label;  // the y axis, e.g. "path length"
  std::vector<NamedSample> samples;
  std::optional<double> reference;  // a dashed horizontal line, e.g. the optimal length
  std::string reference_label = "optimum";
};

std::string box_plot_svg(const BoxPlot& plot);

// How the k-th series is drawn: ten colours, and with each further ten the next dash pattern
// (solid, dashed, dotted, dash-dot), so that 40 series stay distinguishable; after that the styles
// repeat. Drawings that match the plots (the report's path pictures) use it too.
struct SeriesStyle {
  const char* colour;
  const char* dash;  // an SVG stroke-dasharray; "" for a solid line
};
inline constexpr std::size_t kDistinctStyles = 40;
SeriesStyle series_style(std::size_t k);
// stroke="..." (and stroke-dasharray="..." unless solid): the SVG attributes of series_style(k).
std::string stroke_attributes(std::size_t k);

// One curve of a line chart: value[i] is drawn at x[i], or at x = i + 1 (the iteration) when x is
// empty. A non-finite value (or on a log axis, an x <= 0) leaves a gap; the band is shaded
// between band_low and band_high where both are finite.
struct Series {
  std::string name;
  std::vector<double> value;
  std::vector<double> band_low;  // empty, or as long as value
  std::vector<double> band_high;  // empty, or as long as value
  std::vector<double> x;  // empty, or as long as value and non-decreasing
  // Its series_style(); by default its position in the chart. A report gives each configuration
  // its own, the same in every chart, whichever series a chart leaves out.
  std::optional<std::size_t> style = {};
};

// One run's best-so-far curve as a step function: value[i] holds from x[i] (its effort by the end
// of iteration i + 1: the iteration, seconds or walks) until x[i + 1], and after the last x.
struct StepCurve {
  std::vector<double> x;
  std::vector<double> value;
};

// The mean of several runs' step curves at each point of `at` (ascending), with its 95 %
// confidence interval as the band; the series' x is `at`. A run counts at a point where it has a
// finite value by then (a path found), and past its end with its last value, as a best-so-far
// curve goes on; where fewer than two count, there is no band. With `same_runs`, a point has a
// value only once every run with any finite value has one by then (runs without are left out):
// the mean of one set of runs throughout, which never rises for best-so-far curves, instead of a
// mean that jumps up whenever a run finds its first, poor, path.
Series mean_series(std::string name, const std::vector<StepCurve>& runs, std::vector<double> at,
                   bool same_runs = false);

// The same per iteration: run[i] is the value of iteration i + 1 (x empty: the chart's iteration).
Series convergence_series(std::string name, const std::vector<std::vector<double>>& runs);

// `count` points from low to high, evenly spaced on a log scale (low and high > 0 included).
std::vector<double> log_spaced(double low, double high, std::size_t count);

// The fixed-target ECDF of some runs as a step series from `low` to `high`: the share of the
// runs (infinity: never reached) whose hitting time is <= x, at low, every hit and high.
Series ecdf_series(std::string name, const std::vector<double>& hitting_times, double low, double high);

struct LineChart {
  std::string title;
  std::string x_label = "iterations run";  // a count: 1 after the first iteration
  std::string y_label;
  std::vector<Series> series;
  std::optional<double> reference;
  std::string reference_label = "optimum";
  std::string css_class = "convergence";
  bool log_x = false;  // decades, with 2 and 5 between them on a short range
  bool steps = false;  // each value holds until the next x (a step function) instead of a line to it
  std::optional<std::pair<double, double>> y_range;  // fixed instead of the values' (e.g. 0 to 1 for shares)
};

std::string line_chart_svg(const LineChart& chart);

// A path on a map: the report's picture of each configuration's best path on a problem.
struct MapPath {
  std::string label;  // its legend entry
  std::size_t style;  // its series_style()
  std::vector<std::array<double, 2>> points;  // where the path went: x and y of the map's positions
  std::vector<double> layers;  // in a voxel world, each point's z
};

// The map (blocked cells dark) with the paths on it and a legend beside it. A voxel world is drawn
// as an isometric view with the shortest of the paths (a view of the world holds one), named in
// its title.
std::string map_paths_svg(const aco::Map& map, const std::vector<MapPath>& paths);

}  // namespace aco::studies
