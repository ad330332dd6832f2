#include "aco/studies/plots.hpp"
#include "aco/drawing/voxel_svg.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "aco/error.hpp"
#include "aco/map.hpp"
#include "aco/path.hpp"
#include "aco/drawing/svg.hpp"
#include "aco/studies/statistics.hpp"

namespace aco::studies {
namespace {

constexpr double kWidth = 640.0;
constexpr double kHeight = 400.0;
constexpr double kLeft = 70.0;  // room for the y tick labels and the y axis label
constexpr double kTop = 40.0;  // room for the title
constexpr double kRight = 20.0;
constexpr double kLegendWidth = 170.0;
constexpr double kBottom = 50.0;  // x tick labels and the x axis label
constexpr double kRotatedBottom = 130.0;  // sample names written at a slant, at least
constexpr std::size_t kLongestSlantedName = 40;  // longer names are cut, in full in the tooltip
constexpr double kMinSlantedSlot = 18.0;  // a box's width of axis, so that slanted names do not overlap
constexpr double kSin45 = 0.7071067811865476;
constexpr double kFontSize = 12.0, kTitleFontSize = 15.0;
constexpr double kYTitleX = 18.0;  // the y axis title's centre line, written upwards
constexpr double kMinLineFrameWidth = 300.0;  // a line chart's plotting area, however wide its legend
constexpr std::size_t kMaxLegendRowsBeside = 15;  // more rows, or a wider legend, go under the plot
constexpr double kMaxLegendWidthBeside = 300.0;
constexpr double kLegendRow = 20.0;
constexpr std::array kPalette{"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                              "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
constexpr std::array kDashes{"", "7,3", "2,2", "8,3,2,3"};
static_assert(kPalette.size() * kDashes.size() == kDistinctStyles);

double text_width(const std::string& text) { return aco::text_width(text, kFontSize); }

// At most `decimals` decimals, trailing zeros dropped; std::to_chars ignores the locale.
std::string number(double value, int decimals = 1) {
  std::array<char, 400> buffer{};  // the widest finite double in fixed notation fits
  const auto end =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value + 0.0, std::chars_format::fixed, decimals).ptr;
  std::string text(buffer.data(), end);
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

// A value axis with ticks at 1, 2 or 5 times a power of ten, about five of them.
struct Axis {
  double low = 0.0;
  double high = 1.0;
  double step = 0.2;
  int decimals = 1;

  // Multiples of the step; an axis not rounded out to them also gets its low end (iteration 1).
  std::vector<double> ticks() const {
    std::vector<double> result;
    const double first = std::ceil(low / step - 1e-9), last = std::floor(high / step + 1e-9);
    if (first * step - low > step * 1e-9) result.push_back(low);
    for (double k = first; k <= last && result.size() < 50; ++k) result.push_back(k * step);
    return result;
  }
};

// `extend` rounds the ends out to whole ticks; `min_step` keeps iteration ticks whole numbers.
// A range of zero width (a constant sample) is widened so nothing divides by zero.
Axis nice_axis(double low, double high, bool extend, double min_step = 0.0) {
  if (!(high > low)) {
    const double pad = low != 0.0 ? std::abs(low) * 0.05 : 1.0;
    low -= pad;
    high += pad;
  }
  const double raw = (high - low) / 5.0;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double fraction = raw / magnitude;
  Axis axis;
  axis.step = std::max(min_step, (fraction <= 1.0   ? 1.0
                                  : fraction <= 2.0 ? 2.0
                                  : fraction <= 5.0 ? 5.0
                                                    : 10.0) *
                                     magnitude);
  axis.low = extend ? std::floor(low / axis.step) * axis.step : low;
  axis.high = extend ? std::ceil(high / axis.step) * axis.step : high;
  axis.decimals = std::max(0, -int(std::floor(std::log10(axis.step) + 1e-9)));
  return axis;
}

// The plotting area in pixels and its value axis.
struct Frame {
  double left = kLeft;
  double top = kTop;
  double width = 0.0;
  double height = 0.0;
  Axis y;

  double py(double value) const { return top + height * (1.0 - (value - y.low) / (y.high - y.low)); }
  double bottom() const { return top + height; }
  double right() const { return left + width; }
};

// The y range covering every value and the reference, with a little air so that no extreme
// value sits on the frame.
Axis value_axis(const std::vector<double>& values, const std::optional<double>& reference) {
  std::vector<double> all = values;
  if (reference && !std::isfinite(*reference))
    throw aco::Error("plot reference line: value " + number(*reference) + " is not finite");
  if (reference) all.push_back(*reference);
  if (all.empty()) return nice_axis(0.0, 1.0, true);
  const auto [low, high] = std::minmax_element(all.begin(), all.end());
  const double air = (*high - *low) * 0.03;
  // Values that cannot be negative (lengths, gaps) get no negative ticks.
  return nice_axis(*low >= 0.0 ? std::max(0.0, *low - air) : *low - air, *high + air, true);
}

void open_svg(std::ostream& out, const std::string& css_class, const std::string& title, double width = kWidth,
              double height = kHeight) {
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"" << aco::xml_escape(css_class) << "\" width=\""
      << number(width) << "\" height=\"" << number(height) << "\" viewBox=\"0 0 " << number(width) << ' '
      << number(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<rect width=\"" << number(width) << "\" height=\"" << number(height) << "\" fill=\"#fff\"/>\n";
  out << "<text class=\"title\" x=\"" << number(width / 2) << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">"
      << aco::xml_escape(title) << "</text>\n";
}

// Horizontal grid lines with their labels on the left, the axis label written upwards, the frame.
void draw_value_axis(std::ostream& out, const Frame& frame, const std::string& label) {
  out << "<g class=\"y-axis\">\n";
  for (double tick : frame.y.ticks()) {
    const std::string y = number(frame.py(tick));
    out << "<line x1=\"" << number(frame.left) << "\" x2=\"" << number(frame.right()) << "\" y1=\"" << y << "\" y2=\""
        << y << "\" stroke=\"#e0e0e0\"/>";
    out << "<text x=\"" << number(frame.left - 6) << "\" y=\"" << y << "\" dy=\"4\" text-anchor=\"end\">"
        << number(tick, frame.y.decimals) << "</text>\n";
  }
  const std::string middle = number(frame.top + frame.height / 2);
  out << "<text x=\"" << number(kYTitleX) << "\" y=\"" << middle << "\" text-anchor=\"middle\" transform=\"rotate(-90 "
      << number(kYTitleX) << ' ' << middle << ")\">" << aco::xml_escape(label) << "</text>\n";
  out << "<rect x=\"" << number(frame.left) << "\" y=\"" << number(frame.top) << "\" width=\"" << number(frame.width)
      << "\" height=\"" << number(frame.height) << "\" fill=\"none\" stroke=\"#555\"/>\n</g>\n";
}

constexpr const char* kReferenceStyle = "stroke=\"#2e7d32\" stroke-dasharray=\"6,4\"";

std::string reference_text(double value, const std::string& label) {
  return aco::xml_escape(label) + ' ' + number(value, 4);
}

// The dashed line across the frame. Unless a legend names it, a key above the frame's right
// corner does (kReferenceKeyRoom): a label on the line itself lay across the last box.
constexpr double kReferenceKeyRoom = 16.0;

void draw_reference(std::ostream& out, const Frame& frame, const std::optional<double>& value, const std::string& label,
                    bool labelled_here) {
  if (!value) return;
  const std::string y = number(frame.py(*value));
  out << "<line class=\"reference\" x1=\"" << number(frame.left) << "\" x2=\"" << number(frame.right()) << "\" y1=\""
      << y << "\" y2=\"" << y << "\" " << kReferenceStyle << "/>\n";
  if (!labelled_here) return;
  // Left-aligned at the estimated width's start, so that the dash sample stays beside the text
  // (the estimate errs wide) and the text never passes the frame's right edge.
  const double text_left = frame.right() - text_width(label + ' ' + number(*value, 4));
  const std::string dash_y = number(frame.top - 10);
  out << "<g class=\"reference-key\"><line x1=\"" << number(text_left - 26) << "\" x2=\"" << number(text_left - 6)
      << "\" y1=\"" << dash_y << "\" y2=\"" << dash_y << "\" " << kReferenceStyle << "/><text x=\"" << number(text_left)
      << "\" y=\"" << number(frame.top - 6) << "\" fill=\"#2e7d32\">" << reference_text(*value, label)
      << "</text></g>\n";
}

void no_data(std::ostream& out, const Frame& frame) {
  out << "<text x=\"" << number(frame.left + frame.width / 2) << "\" y=\"" << number(frame.top + frame.height / 2)
      << "\" text-anchor=\"middle\" fill=\"#777\">no data</text>\n";
}

Summary summarize_sample(const NamedSample& sample) {
  try {
    return summarize(sample.values);
  } catch (const aco::Error& e) {
    throw aco::Error("box plot sample \"" + sample.name + "\": " + e.what());
  }
}

void draw_box(std::ostream& out, const Frame& frame, const NamedSample& sample, const Summary& s, double centre,
              double box_width) {
  const double fence_low = s.q1 - 1.5 * s.iqr, fence_high = s.q3 + 1.5 * s.iqr;
  double whisker_low = s.q1, whisker_high = s.q3;
  for (double v : sample.values)
    if (v >= fence_low && v <= fence_high)
      whisker_low = std::min(whisker_low, v), whisker_high = std::max(whisker_high, v);
  const std::string x = number(centre), cap_left = number(centre - box_width / 4),
                    cap_right = number(centre + box_width / 4);
  const std::string left = number(centre - box_width / 2), right = number(centre + box_width / 2);
  out << "<g class=\"sample\"><title>" << aco::xml_escape(sample.name) << ": n " << std::to_string(s.n) << ", median "
      << number(s.median, 4) << ", quartiles " << number(s.q1, 4) << " to " << number(s.q3, 4) << "</title>\n";
  out << "<path class=\"whisker\" fill=\"none\" stroke=\"#333\" d=\"M" << x << ',' << number(frame.py(whisker_low))
      << "V" << number(frame.py(s.q1)) << "M" << x << ',' << number(frame.py(s.q3)) << "V"
      << number(frame.py(whisker_high)) << "M" << cap_left << ',' << number(frame.py(whisker_low)) << "H" << cap_right
      << "M" << cap_left << ',' << number(frame.py(whisker_high)) << "H" << cap_right << "\"/>\n";
  out << "<rect class=\"box\" x=\"" << left << "\" y=\"" << number(frame.py(s.q3)) << "\" width=\"" << number(box_width)
      << "\" height=\"" << number(frame.py(s.q1) - frame.py(s.q3)) << "\" fill=\"#bbdefb\" stroke=\"#1565c0\"/>\n";
  const std::string median = number(frame.py(s.median));
  out << "<line class=\"median\" x1=\"" << left << "\" x2=\"" << right << "\" y1=\"" << median << "\" y2=\"" << median
      << "\" stroke=\"#0d47a1\" stroke-width=\"2\"/>\n";
  for (double v : sample.values)
    if (v < fence_low || v > fence_high)
      out << "<circle class=\"outlier\" cx=\"" << x << "\" cy=\"" << number(frame.py(v))
          << "\" r=\"2.5\" fill=\"#d32f2f\"/>\n";
  out << "</g>\n";
}

// A sample's name as written under its box: slanted names longer than kLongestSlantedName are cut
// (the box's tooltip has them in full).
std::string shown_name(std::string name, bool slanted) {
  if (!slanted || name.size() <= kLongestSlantedName) return name;
  std::size_t cut = kLongestSlantedName - 1;
  while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return name.substr(0, cut) + "\u2026";
}

// How far a name slanted at 45 degrees, ending at its box, reaches left of and below its end:
// its length and its height, both at 45 degrees.
double slanted_reach(const std::string& name) { return kSin45 * (text_width(name) + kFontSize); }

// A sample's name under its box, level or slanted (names too long to sit side by side).
void draw_sample_name(std::ostream& out, const std::string& name, double centre, double baseline, bool slanted) {
  const std::string x = number(centre), y = number(baseline);
  if (!slanted) {
    out << "<text x=\"" << x << "\" y=\"" << y << "\" text-anchor=\"middle\">" << aco::xml_escape(name) << "</text>\n";
    return;
  }
  out << "<text x=\"" << x << "\" y=\"" << y << "\" text-anchor=\"end\" transform=\"rotate(-45 " << x << ' ' << y
      << ")\">" << aco::xml_escape(name) << "</text>\n";
}

// Half-open index ranges [begin, end) where `defined(i)` holds: the pieces of a curve with gaps.
using Stretches = std::vector<std::pair<std::size_t, std::size_t>>;

template <class Defined>
Stretches stretches(std::size_t count, Defined defined) {
  Stretches result;
  for (std::size_t begin = 0; begin < count;) {
    if (!defined(begin)) {
      ++begin;
      continue;
    }
    std::size_t end = begin;
    while (end < count && defined(end)) ++end;
    result.emplace_back(begin, end);
    begin = end;
  }
  return result;
}

void check_series(const Series& series) {
  const bool has_band = !series.band_low.empty() || !series.band_high.empty();
  if (has_band && (series.band_low.size() != series.value.size() || series.band_high.size() != series.value.size()))
    throw aco::Error("line chart series \"" + series.name + "\": the band has " +
                     std::to_string(series.band_low.size()) + " low and " + std::to_string(series.band_high.size()) +
                     " high values for " + std::to_string(series.value.size()) + " values");
  if (!series.x.empty() && series.x.size() != series.value.size())
    throw aco::Error("line chart series \"" + series.name + "\": " + std::to_string(series.x.size()) +
                     " x values for " + std::to_string(series.value.size()) + " values");
}

// The left margin that holds the y tick labels (right-aligned 6 px left of the frame) and, left
// of them, the y axis title.
double value_axis_room(const Axis& y) {
  double widest = 0.0;
  for (double tick : y.ticks()) widest = std::max(widest, text_width(number(tick, y.decimals)));
  return std::max(kLeft, kYTitleX + kFontSize + 6 + widest + 6);
}

// The picture's width is at least its title's.
double title_room(const std::string& title) { return aco::text_width(title, kTitleFontSize) + 20; }

// A line chart's x axis: linear with nice ticks, or logarithmic over whole decades.
struct XAxis {
  bool log = false;
  double low = 0.0;
  double high = 1.0;
  std::vector<std::pair<double, std::string>> ticks;  // value, label

  double fraction(double x) const {  // 0 at low, 1 at high
    return log ? (std::log10(x) - std::log10(low)) / (std::log10(high) - std::log10(low)) : (x - low) / (high - low);
  }
};

// `min_step` keeps iteration ticks whole numbers.
XAxis linear_x_axis(double low, double high, double min_step) {
  const Axis axis = nice_axis(low, high, false, min_step);
  XAxis x{false, axis.low, axis.high, {}};
  for (double tick : axis.ticks()) x.ticks.emplace_back(tick, number(tick, axis.decimals));
  return x;
}

// m x 10^e as a tick label: written out near 1, else as "2e-5" (the long form would crowd the axis).
std::string decade_label(double m, int e) {
  if (e < -3 || e > 5) return number(m, 0) + "e" + std::to_string(e);
  return number(m * std::pow(10.0, e), std::max(0, -e));
}

// Ticks at the powers of ten, and at 2 and 5 times them when the axis spans at most two decades.
XAxis log_x_axis(double low, double high) {
  const int first = static_cast<int>(std::floor(std::log10(low) + 1e-9));
  const int last = std::max(first + 1, static_cast<int>(std::ceil(std::log10(high) - 1e-9)));
  XAxis x{true, std::pow(10.0, first), std::pow(10.0, last), {}};
  const std::vector<double> multiples = last - first <= 2 ? std::vector<double>{1, 2, 5} : std::vector<double>{1};
  for (int e = first; e <= last; ++e)
    for (double m : multiples) {
      const double tick = m * std::pow(10.0, e);
      if (tick <= x.high * (1 + 1e-9)) x.ticks.emplace_back(tick, decade_label(m, e));
    }
  return x;
}

}  // namespace

SeriesStyle series_style(std::size_t k) {
  return {kPalette[k % kPalette.size()], kDashes[k / kPalette.size() % kDashes.size()]};
}

std::string stroke_attributes(std::size_t k) {
  const SeriesStyle style = series_style(k);
  std::string attributes = std::string("stroke=\"") + style.colour + "\"";
  if (*style.dash) attributes += std::string(" stroke-dasharray=\"") + style.dash + "\"";
  return attributes;
}

std::string box_plot_svg(const BoxPlot& plot) {
  std::vector<Summary> summaries;
  std::vector<double> extremes;
  for (const auto& sample : plot.samples) {
    summaries.push_back(summarize_sample(sample));
    if (summaries.back().n > 0) extremes.insert(extremes.end(), {summaries.back().min, summaries.back().max});
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < plot.samples.size(); ++i)
    names.push_back(plot.samples[i].name + (summaries[i].n == 0 ? " (no data)" : ""));
  // The layout makes room for every text by its estimated width (aco::text_width): the tick
  // labels left of the frame; names side by side if they fit their boxes' slots, else slanted,
  // with slots wide enough to keep them apart, the frame moved right until the first names' ends
  // stay in the picture, and the bottom as deep as the longest name reaches.
  Frame frame;
  if (plot.reference) frame.top += kReferenceKeyRoom;
  frame.y = value_axis(extremes, plot.reference);
  frame.left = value_axis_room(frame.y);
  const double count = double(std::max<std::size_t>(plot.samples.size(), 1));
  double slot = (kWidth - frame.left - kRight) / count;
  const bool slanted =
      std::any_of(names.begin(), names.end(), [&](const std::string& name) { return text_width(name) > slot - 4; });
  double bottom = kBottom;
  if (slanted) {
    slot = std::max(slot, kMinSlantedSlot);
    bottom = kRotatedBottom;
    for (std::size_t i = 0; i < names.size(); ++i) {
      names[i] = shown_name(names[i], true);
      frame.left = std::max(frame.left, 4 + slanted_reach(names[i]) - slot * (double(i) + 0.5));
      bottom = std::max(bottom, 16 + slanted_reach(names[i]) + 4);
    }
  }
  frame.width = slot * count;
  frame.height = std::max(kHeight - kTop - (slanted ? kRotatedBottom : kBottom), text_width(plot.value_label) + 10);
  const double width = std::max(frame.right() + kRight, title_room(plot.title));

  std::ostringstream out;
  open_svg(out, "boxplot", plot.title, width, frame.bottom() + bottom);
  draw_value_axis(out, frame, plot.value_label);
  if (extremes.empty()) no_data(out, frame);
  const double box_width = std::min(slot * 0.6, 60.0);
  for (std::size_t i = 0; i < plot.samples.size(); ++i) {
    const double centre = frame.left + slot * (double(i) + 0.5);
    if (summaries[i].n > 0) draw_box(out, frame, plot.samples[i], summaries[i], centre, box_width);
    draw_sample_name(out, names[i], centre, frame.bottom() + 16, slanted);
  }
  draw_reference(out, frame, plot.reference, plot.reference_label, true);
  out << "</svg>\n";
  return out.str();
}

Series mean_series(std::string name, const std::vector<StepCurve>& runs, std::vector<double> at, bool same_runs) {
  Series series{std::move(name), {}, {}, {}, {}, {}};
  const auto finite = [](double v) { return std::isfinite(v); };
  const auto counted = static_cast<std::size_t>(std::count_if(runs.begin(), runs.end(), [&](const StepCurve& run) {
    return std::any_of(run.value.begin(), run.value.end(), finite);
  }));
  std::vector<double> by_then;
  for (const double point : at) {
    by_then.clear();
    for (const auto& run : runs) {
      const auto ended =
          std::upper_bound(run.x.begin(), run.x.end(), point) - run.x.begin();  // iterations ended by then
      if (ended > 0 && finite(run.value[static_cast<std::size_t>(ended - 1)]))
        by_then.push_back(run.value[static_cast<std::size_t>(ended - 1)]);
    }
    if (same_runs && by_then.size() < counted) by_then.clear();
    const Summary s = summarize(by_then);
    series.value.push_back(s.mean);
    series.band_low.push_back(s.ci_low);
    series.band_high.push_back(s.ci_high);
  }
  series.x = std::move(at);
  return series;
}

Series convergence_series(std::string name, const std::vector<std::vector<double>>& runs) {
  std::vector<StepCurve> curves;
  std::size_t iterations = 0;
  for (const auto& run : runs) {
    StepCurve curve{std::vector<double>(run.size()), run};
    std::iota(curve.x.begin(), curve.x.end(), 1.0);
    curves.push_back(std::move(curve));
    iterations = std::max(iterations, run.size());
  }
  std::vector<double> at(iterations);
  std::iota(at.begin(), at.end(), 1.0);
  Series series = mean_series(std::move(name), curves, std::move(at));
  series.x.clear();  // the iterations: the chart's default
  return series;
}

std::vector<double> log_spaced(double low, double high, std::size_t count) {
  if (!(low > 0.0) || !(high > low) || count < 2) return {low};
  std::vector<double> points;
  for (std::size_t k = 0; k + 1 < count; ++k)
    points.push_back(low * std::pow(high / low, double(k) / double(count - 1)));
  points.push_back(high);
  return points;
}

Series ecdf_series(std::string name, const std::vector<double>& hitting_times, double low, double high) {
  std::vector<double> at{low};
  for (const double t : hitting_times)
    if (t > low && t < high) at.push_back(t);
  std::sort(at.begin(), at.end());
  at.push_back(high);
  return {std::move(name), ecdf(hitting_times, at), {}, {}, at, {}};
}

std::string line_chart_svg(const LineChart& chart) {
  std::vector<double> finite, xs;
  const auto x_of = [](const Series& s, std::size_t i) { return s.x.empty() ? double(i + 1) : s.x[i]; };
  const auto on_axis = [&](double x) { return std::isfinite(x) && (!chart.log_x || x > 0.0); };
  for (const auto& series : chart.series) {
    check_series(series);
    for (const auto* values : {&series.value, &series.band_low, &series.band_high})
      std::copy_if(values->begin(), values->end(), std::back_inserter(finite),
                   [](double v) { return std::isfinite(v); });
    for (std::size_t i = 0; i < series.value.size(); ++i)
      if (on_axis(x_of(series, i))) xs.push_back(x_of(series, i));
  }
  const auto [x_low, x_high] =
      xs.empty() ? std::pair(1.0, 1.0)
                 : std::pair(*std::min_element(xs.begin(), xs.end()), *std::max_element(xs.begin(), xs.end()));
  const bool by_iteration =
      std::all_of(chart.series.begin(), chart.series.end(), [](const Series& s) { return s.x.empty(); });
  const XAxis x_axis = chart.log_x    ? log_x_axis(x_low, x_high)
                       : by_iteration ? linear_x_axis(1.0, std::max(x_high, 1.0), 1.0)
                                      : linear_x_axis(x_low, x_high, 0.0);
  // The layout makes room for every text by its estimated width (aco::text_width): the y tick
  // labels left of the frame, the last x tick label (centred on the frame's right end) right of
  // it, the title above. The legend's entries are as wide as the longest; a short legend stands
  // in one column beside the plot (taking its width from the plotting area down to a minimum),
  // a long or wide one in rows under the plot, as many columns as fit, the picture growing
  // down (and wider if one column does not fit).
  std::vector<std::pair<std::string, std::string>> legend;  // line style, text (escaped)
  for (std::size_t k = 0; k < chart.series.size(); ++k)
    legend.emplace_back(stroke_attributes(chart.series[k].style.value_or(k)) + " stroke-width=\"2\"",
                        aco::xml_escape(chart.series[k].name));
  if (chart.reference) legend.emplace_back(kReferenceStyle, reference_text(*chart.reference, chart.reference_label));
  double longest = 0.0;
  for (const auto& series : chart.series) longest = std::max(longest, text_width(series.name));
  if (chart.reference)
    longest = std::max(longest, text_width(chart.reference_label + ' ' + number(*chart.reference, 4)));
  const double entry_width = 26 + longest + 8;  // line, gap, text, gap
  const double last_tick_half = x_axis.ticks.empty() ? 0.0 : text_width(x_axis.ticks.back().second) / 2 + 4;
  Frame frame;
  frame.y = chart.y_range ? nice_axis(chart.y_range->first, chart.y_range->second, false)
                          : value_axis(finite, chart.reference);
  frame.left = value_axis_room(frame.y);
  frame.height = std::max(kHeight - kTop - kBottom, text_width(chart.y_label) + 10);
  const bool beside = legend.size() <= kMaxLegendRowsBeside && 16 + entry_width <= kMaxLegendWidthBeside;
  double width = 0.0, height = 0.0, legend_x = 0.0, legend_y = 0.0;
  std::size_t columns = 1;
  if (beside) {
    const double legend_width = std::max(kLegendWidth, 16 + entry_width);
    frame.width = std::max(kMinLineFrameWidth, kWidth - frame.left - legend_width);
    legend_x = frame.right() + std::max(16.0, last_tick_half);
    legend_y = frame.top + 10;
    width = std::max(frame.right() + legend_width, legend_x + entry_width);
    height = std::max(frame.bottom() + kBottom, legend_y + kLegendRow * double(legend.size()));
  } else {
    frame.width = kWidth - frame.left - std::max(kRight, last_tick_half);
    legend_x = 16;
    legend_y = frame.bottom() + kBottom + 16;
    columns = std::max<std::size_t>(1, static_cast<std::size_t>((kWidth - legend_x - kRight) / entry_width));
    width = std::max(kWidth, legend_x + double(columns) * entry_width + kRight);
    const std::size_t rows = (legend.size() + columns - 1) / columns;
    height = legend_y + kLegendRow * double(rows);
  }
  width = std::max({width, frame.right() + last_tick_half, title_room(chart.title)});
  auto px = [&](double x) { return frame.left + frame.width * x_axis.fraction(x); };

  std::ostringstream out;
  open_svg(out, chart.css_class, chart.title, width, height);
  draw_value_axis(out, frame, chart.y_label);
  out << "<g class=\"x-axis\">\n";
  for (const auto& [tick, label] : x_axis.ticks)
    out << "<text x=\"" << number(px(tick)) << "\" y=\"" << number(frame.bottom() + 16) << "\" text-anchor=\"middle\">"
        << label << "</text>\n";
  out << "<text x=\"" << number(frame.left + frame.width / 2) << "\" y=\"" << number(frame.bottom() + 38)
      << "\" text-anchor=\"middle\">" << aco::xml_escape(chart.x_label) << "</text>\n</g>\n";
  if (finite.empty()) no_data(out, frame);

  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const Series& s = chart.series[k];
    const std::size_t style = s.style.value_or(k);
    const char* stroke = series_style(style).colour;
    auto banded = [&](std::size_t i) {
      return std::isfinite(s.band_low[i]) && std::isfinite(s.band_high[i]) && on_axis(x_of(s, i));
    };
    const Stretches band_pieces = s.band_low.empty() ? Stretches{} : stretches(s.value.size(), banded);
    if (!band_pieces.empty()) {
      out << "<path class=\"band\" fill=\"" << stroke << "\" fill-opacity=\"0.2\" stroke=\"none\" d=\"";
      for (const auto& [begin, end] : band_pieces) {
        for (std::size_t i = begin; i < end; ++i)
          out << (i == begin ? 'M' : 'L') << number(px(x_of(s, i))) << ',' << number(frame.py(s.band_high[i]));
        for (std::size_t i = end; i-- > begin;)
          out << 'L' << number(px(x_of(s, i))) << ',' << number(frame.py(s.band_low[i]));
        out << 'Z';
      }
      out << "\"/>\n";
    }
    out << "<path class=\"series\" fill=\"none\" " << stroke_attributes(style) << " stroke-width=\"2\" d=\"";
    for (const auto& [begin, end] :
         stretches(s.value.size(), [&](std::size_t i) { return std::isfinite(s.value[i]) && on_axis(x_of(s, i)); }))
      for (std::size_t i = begin; i < end; ++i) {
        if (i == begin)
          out << 'M' << number(px(x_of(s, i))) << ',' << number(frame.py(s.value[i]));
        else if (chart.steps)
          out << 'H' << number(px(x_of(s, i))) << 'V' << number(frame.py(s.value[i]));
        else
          out << 'L' << number(px(x_of(s, i))) << ',' << number(frame.py(s.value[i]));
      }
    out << "\"/>\n";
  }
  draw_reference(out, frame, chart.reference, chart.reference_label, false);

  out << "<g class=\"legend\">\n";
  for (std::size_t k = 0; k < legend.size(); ++k) {
    const double x = legend_x + entry_width * double(k % columns), y = legend_y + kLegendRow * double(k / columns);
    out << "<line x1=\"" << number(x) << "\" x2=\"" << number(x + 20) << "\" y1=\"" << number(y) << "\" y2=\""
        << number(y) << "\" " << legend[k].first << "/><text x=\"" << number(x + 26) << "\" y=\"" << number(y)
        << "\" dy=\"4\">" << legend[k].second << "</text>\n";
  }
  out << "</g>\n</svg>\n";
  return out.str();
}

namespace {

std::string voxel_paths_svg(const aco::Map& map, const std::vector<MapPath>& paths) {
  aco::VoxelWorldView view(map);
  view.title = map.name() + ": no path";
  double shortest = std::numeric_limits<double>::infinity();
  for (const MapPath& path : paths) {
    if (path.layers.size() != path.points.size()) continue;
    std::vector<Eigen::Vector3d> points;
    for (std::size_t i = 0; i < path.points.size(); ++i)
      points.emplace_back(path.points[i][0], path.points[i][1], path.layers[i]);
    const double length = aco::polyline_length(points);
    if (points.empty() || !(length < shortest)) continue;
    shortest = length;
    view.path = std::move(points);
    view.title = map.name() + ": the shortest path, " + path.label;
  }
  if (!view.path.empty()) {
    const auto voxel = [](const Eigen::Vector3d& p) {
      return aco::Cell{int(std::lround(p.x())), int(std::lround(p.y())), int(std::lround(p.z()))};
    };
    view.start = voxel(view.path.front());
    view.goal = voxel(view.path.back());
  }
  aco::VoxelSvgStyle style;
  style.isometric_width = 480;
  style.max_faces = 8000;  // a report holds one per problem
  return aco::render_voxel_svg(view, style);
}

}  // namespace

std::string map_paths_svg(const aco::Map& map, const std::vector<MapPath>& paths) {
  if (map.volumetric()) return voxel_paths_svg(map, paths);
  const int w = map.width(), h = map.height();
  const double scale = std::max(2.0, std::min(24.0, 480.0 / std::max(w, h)));
  const double cell = w > 1 ? map.position({1, 0}).x() - map.position({0, 0}).x() : 1.0;
  // The legend beside the map, one row per path: as wide as its longest entry and as tall as its
  // rows (by aco::text_width's estimate), so none is cut off.
  double longest = 0.0;
  for (const MapPath& path : paths) longest = std::max(longest, aco::text_width(path.label, 12));
  const double map_w = w * scale, map_h = h * scale, legend_x = map_w + 8;
  const double width = legend_x + 28 + longest + 8, height = std::max(map_h, 16.0 * double(paths.size()) + 4);
  std::ostringstream svg;
  svg << "<svg class=\"paths\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height
      << "\" font-family=\"sans-serif\" font-size=\"12\"><rect width=\"" << map_w << "\" height=\"" << map_h
      << "\" fill=\"#fff\" stroke=\"#999\"/><g fill=\"#333\" shape-rendering=\"crispEdges\">";
  // Blocked cells in horizontal runs, with crisp edges: no seams between rows.
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w;) {
      int end = x;
      while (end < w && !map.passable({end, y})) ++end;
      if (end > x)
        svg << "<rect x=\"" << x * scale << "\" y=\"" << y * scale << "\" width=\"" << (end - x) * scale
            << "\" height=\"" << scale << "\"/>";
      x = std::max(end, x + 1);
    }
  svg << "</g>";
  for (std::size_t row = 0; row < paths.size(); ++row) {
    const MapPath& path = paths[row];
    svg << "<polyline fill=\"none\" " << stroke_attributes(path.style) << " stroke-width=\"" << std::max(1.0, scale / 5)
        << "\" stroke-opacity=\"0.8\" points=\"";
    for (const auto& point : path.points)
      svg << (point[0] / cell + 0.5) * scale << "," << (point[1] / cell + 0.5) * scale << " ";
    const double y = 14 + 16 * double(row);
    svg << "\"/><line x1=\"" << legend_x << "\" x2=\"" << legend_x + 22 << "\" y1=\"" << y - 4 << "\" y2=\"" << y - 4
        << "\" " << stroke_attributes(path.style) << " stroke-width=\"2\"/><text x=\"" << legend_x + 28 << "\" y=\""
        << y << "\" fill=\"" << series_style(path.style).colour << "\">" << aco::xml_escape(path.label) << "</text>";
  }
  svg << "</svg>";
  return svg.str();
}

}  // namespace aco::studies
