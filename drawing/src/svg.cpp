#include "aco/drawing/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <sstream>

#include "aco/error.hpp"
#include "aco/process/output_file.hpp"
#include "aco/terrain.hpp"

namespace aco {
namespace {

constexpr double kMapPixels = 560.0;
constexpr double kPlotWidth = 420.0;
constexpr double kPlotHeight = 300.0;
constexpr double kMargin = 40.0;
constexpr double kConvergenceAir = 0.05;  // of the values' range, above and below them

void polyline(std::ostream& out, const std::vector<std::pair<double, double>>& points, const char* style) {
  if (points.size() < 2) return;
  out << "<polyline fill=\"none\" " << style << " points=\"";
  for (const auto& [x, y] : points) out << x << ',' << y << ' ';
  out << "\"/>\n";
}

// Hypsometric tints, low to high: lowland green, tan, brown, snow.
struct ColourStop {
  double at;
  int r, g, b;
};
constexpr ColourStop kHeightRamp[] = {
    {0.0, 0x3a, 0x8a, 0x3f}, {0.35, 0xd8, 0xc8, 0x7a}, {0.7, 0x8b, 0x5a, 0x2b}, {1.0, 0xf7, 0xf7, 0xf4}};
// Shading bands: cells of one band share a colour, so rows merge into few rectangles.
constexpr int kHeightBands = 32;

std::string hex_colour(int r, int g, int b) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", r, g, b);
  return text;
}

// Colour of a relative height t in [0, 1].
std::string ramp_colour(double t) {
  std::size_t i = 1;
  while (i + 1 < std::size(kHeightRamp) && t > kHeightRamp[i].at) ++i;
  const ColourStop& a = kHeightRamp[i - 1];
  const ColourStop& b = kHeightRamp[i];
  const double u = std::clamp((t - a.at) / (b.at - a.at), 0.0, 1.0);
  auto mix = [u](int x, int y) { return static_cast<int>(std::lround(x + (y - x) * u)); };
  return hex_colour(mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b));
}

struct HeightRange {
  double low = 0;
  double high = 0;
};

// The heights of the cells with data, or nothing if the map is not a terrain or is flat.
std::optional<HeightRange> height_range(const TerrainMap* terrain) {
  if (!terrain) return std::nullopt;
  std::optional<HeightRange> range;
  for (int y = 0; y < terrain->height(); ++y)
    for (int x = 0; x < terrain->width(); ++x) {
      if (!terrain->has_data({x, y})) continue;
      const double z = terrain->elevation({x, y});
      if (!range) range = HeightRange{z, z};
      range->low = std::min(range->low, z);
      range->high = std::max(range->high, z);
    }
  if (!range || range->high <= range->low) return std::nullopt;
  return range;
}

// Each cell with data filled with its height band's colour, runs of one colour merged.
void draw_height_shading(std::ostream& out, const TerrainMap& terrain, HeightRange range) {
  auto band = [&](int x, int y) -> int {
    if (!terrain.has_data({x, y})) return -1;
    const double t = (terrain.elevation({x, y}) - range.low) / (range.high - range.low);
    return std::min(kHeightBands - 1, static_cast<int>(t * kHeightBands));
  };
  out << "<g id=\"terrain\" shape-rendering=\"crispEdges\">\n";
  for (int y = 0; y < terrain.height(); ++y)
    for (int x = 0; x < terrain.width();) {
      const int b = band(x, y);
      int end = x + 1;
      while (end < terrain.width() && band(end, y) == b) ++end;
      if (b >= 0)
        out << "<rect x=\"" << x - 0.5 << "\" y=\"" << y - 0.5 << "\" width=\"" << end - x << "\" height=\"1\" fill=\""
            << ramp_colour((b + 0.5) / kHeightBands) << "\"/>\n";
      x = end;
    }
  out << "</g>\n";
}

// A round contour interval giving about eight levels: 1, 2 or 5 times a power of ten.
double contour_interval(HeightRange range) {
  const double rough = (range.high - range.low) / 8;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  for (double factor : {1.0, 2.0, 5.0})
    if (factor * power >= rough) return factor * power;
  return 10 * power;
}

// Contour lines by marching squares over the lattice of cell centres; squares with a NODATA
// corner are skipped. A saddle square is split by its centre value (the mean of its corners).
void draw_contours(std::ostream& out, const TerrainMap& terrain, HeightRange range, double stroke) {
  const double interval = contour_interval(range);
  out << "<g id=\"contours\" fill=\"none\" stroke=\"#4e342e\" stroke-opacity=\"0.55\" stroke-width=\"" << stroke
      << "\">\n";
  for (double level = std::floor(range.low / interval + 1) * interval; level < range.high; level += interval) {
    out << "<path class=\"contour\" data-height=\"" << level << "\" d=\"";
    for (int y = 0; y + 1 < terrain.height(); ++y)
      for (int x = 0; x + 1 < terrain.width(); ++x) {
        const Cell corner[4] = {{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}};  // clockwise from top left
        double z[4];
        bool complete = true;
        for (int i = 0; i < 4; ++i) {
          complete = complete && terrain.has_data(corner[i]);
          z[i] = terrain.elevation(corner[i]);
        }
        if (!complete) continue;
        // Crossing points on the square's sides i = corner i -> corner i+1.
        std::vector<std::pair<double, double>> crossings;
        for (int i = 0; i < 4; ++i) {
          const int j = (i + 1) % 4;
          if ((z[i] >= level) == (z[j] >= level)) continue;
          const double t = (level - z[i]) / (z[j] - z[i]);
          crossings.emplace_back(corner[i].x + t * (corner[j].x - corner[i].x),
                                 corner[i].y + t * (corner[j].y - corner[i].y));
        }
        if (crossings.size() == 4) {
          // Join sides 0-1 and 2-3 when corner 1 is cut off from the centre, else sides 3-0 and 1-2.
          const bool centre_high = (z[0] + z[1] + z[2] + z[3]) / 4 >= level;
          if ((z[1] >= level) == centre_high) crossings = {crossings[3], crossings[0], crossings[1], crossings[2]};
        }
        for (std::size_t k = 0; k + 1 < crossings.size(); k += 2)
          out << 'M' << crossings[k].first << ' ' << crossings[k].second << 'L' << crossings[k + 1].first << ' '
              << crossings[k + 1].second;
      }
    out << "\"/>\n";
  }
  out << "</g>\n";
}

constexpr double kBarWidth = 200;
constexpr const char* kBlockedTerrainLabel = "blocked (NODATA or too steep)";
// The height legend's width and its height below its top (its title is above the top).
double height_legend_width() { return kBarWidth + 32 + text_width(kBlockedTerrainLabel); }
constexpr double kHeightLegendHeight = 32;

// A colour bar from the lowest to the highest height, with both values.
void draw_height_legend(std::ostream& out, HeightRange range, double left, double top) {
  out << "<defs><linearGradient id=\"height-ramp\">";
  for (const auto& stop : kHeightRamp)
    out << "<stop offset=\"" << stop.at << "\" stop-color=\"" << hex_colour(stop.r, stop.g, stop.b) << "\"/>";
  out << "</linearGradient></defs>\n";
  out << "<g id=\"height-legend\" transform=\"translate(" << left << ',' << top
      << ")\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<text x=\"0\" y=\"-6\">height (contour interval " << contour_interval(range) << ")</text>\n";
  out << "<rect width=\"" << kBarWidth << "\" height=\"12\" fill=\"url(#height-ramp)\" stroke=\"#888\"/>\n";
  out << "<text x=\"0\" y=\"28\">" << range.low << "</text>\n";
  out << "<text x=\"" << kBarWidth << "\" y=\"28\" text-anchor=\"end\">" << range.high << "</text>\n";
  out << "<rect x=\"" << kBarWidth + 16 << "\" width=\"12\" height=\"12\" fill=\"#333\"/><text x=\"" << kBarWidth + 32
      << "\" y=\"11\">" << kBlockedTerrainLabel << "</text>\n";
  out << "</g>\n";
}

constexpr const char* kStartColour = "#43a047";
constexpr const char* kGoalColour = "#e53935";
constexpr double kMapLegendRow = 18.0;

// What the map shows, in two columns: the start and goal marks, both paths, and, when drawn, the
// blocked cells (a terrain's height legend names its own) and the pheromone field. Returns its height.
double draw_map_legend(std::ostream& out, const RunPicture& pic, bool terrain_shading, double left, double top) {
  struct Entry {
    std::string mark;  // an element's name and attributes, drawn about (10, 0) of its row
    const char* label;
  };
  // A continuous planner's path (ompl) has no grid path under it and saw no smoother.
  const bool continuous = pic.grid_path.empty() && !pic.path.empty();
  std::vector<Entry> entries = {
      {std::string("circle cx=\"10\" cy=\"0\" r=\"4\" fill=\"") + kStartColour + "\"", "start"},
      {std::string("circle cx=\"10\" cy=\"0\" r=\"4\" fill=\"") + kGoalColour + "\"", "goal"}};
  if (!continuous)
    entries.push_back({"line x1=\"0\" x2=\"20\" y1=\"0\" y2=\"0\" stroke=\"#1565c0\" stroke-width=\"2\"",
                       "grid path (cell to cell)"});
  entries.push_back(
      {"line x1=\"0\" x2=\"20\" y1=\"0\" y2=\"0\" stroke=\"#d32f2f\" stroke-width=\"2\" stroke-dasharray=\"6,3\"",
       continuous ? "path (continuous, in the plane)" : "path after the smoother"});
  if (!terrain_shading)
    entries.push_back({"rect x=\"4\" y=\"-6\" width=\"12\" height=\"12\" fill=\"#333\"", "blocked cell"});
  if (!pic.pheromone.empty())
    entries.push_back({"rect x=\"4\" y=\"-6\" width=\"12\" height=\"12\" fill=\"#2e7d32\" fill-opacity=\"0.6\"",
                       "pheromone (darker: more)"});
  // One flat group (no nested ones), each entry placed by its own transform and coordinates.
  out << "<g id=\"map-legend\" transform=\"translate(" << left << ',' << top
      << ")\" font-family=\"sans-serif\" font-size=\"12\">\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double x = double(i % 2) * kPlotWidth / 2, y = double(i / 2) * kMapLegendRow;
    out << '<' << entries[i].mark << " transform=\"translate(" << x << ',' << y << ")\"/><text x=\"" << x + 26
        << "\" y=\"" << y + 4 << "\">" << entries[i].label << "</text>\n";
  }
  out << "</g>\n";
  return double((entries.size() + 1) / 2) * kMapLegendRow;
}

// Cells are drawn centred on their positions, in map units scaled by `scale`.
// `terrain` is the map if it is one; `heights` its height range if it is not flat. `ends`: the
// start and goal marks (a map drawn alone has neither).
void draw_map(std::ostream& out, const Graph& graph, const RunPicture& pic, double scale, const TerrainMap* terrain,
              const std::optional<HeightRange>& heights, bool ends = true) {
  const int w = graph.width, h = graph.height;
  // Positions are in map units; the picture is in cells.
  const double unit = terrain ? terrain->cell_size() : 1.0;
  out << "<g id=\"map\" transform=\"translate(" << kMargin << ',' << kMargin << ") scale(" << scale
      << ") translate(0.5,0.5)\">\n";
  out << "<rect x=\"-0.5\" y=\"-0.5\" width=\"" << w << "\" height=\"" << h
      << "\" fill=\"#ffffff\" stroke=\"#888\" stroke-width=\"" << 1.0 / scale << "\"/>\n";
  if (heights) {
    draw_height_shading(out, *terrain, *heights);
    draw_contours(out, *terrain, *heights, 1.0 / scale);
  }
  if (!pic.pheromone.empty()) {
    // Pheromone of a cell = sum over the edges into it, shown as the green's opacity in steps of
    // kOpacityStep, so that neighbouring cells of one step merge into one rectangle (a 512 x 512
    // map's field shrinks from some 200,000 rectangles to a few tens of thousands).
    constexpr double kOpacityStep = 0.02, kMostOpaque = 0.8;
    std::vector<double> cell(graph.num_nodes(), 0.0);
    for (EdgeId e = 0; e < graph.num_edges(); ++e) cell[graph.targets[e]] += pic.pheromone[e];
    const double top = *std::max_element(cell.begin(), cell.end());
    const auto level = [&](int x, int y) -> int {  // steps of opacity; 0: not drawn
      const NodeId node = graph.node({x, y});
      if (top <= 0 || cell[node] <= 0) return 0;
      return static_cast<int>(std::lround(std::sqrt(cell[node] / top) * kMostOpaque / kOpacityStep));
    };
    out << "<g id=\"pheromone\" fill=\"#2e7d32\" shape-rendering=\"crispEdges\">\n";
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w;) {
        const int l = level(x, y);
        int end = x + 1;
        while (end < w && level(end, y) == l) ++end;
        if (l > 0)
          out << "<rect x=\"" << x - 0.5 << "\" y=\"" << y - 0.5 << "\" width=\"" << end - x
              << "\" height=\"1\" fill-opacity=\"" << l * kOpacityStep << "\"/>\n";
        x = end;
      }
    out << "</g>\n";
  }
  // Blocked cells, merged into horizontal runs to keep large maps small, with crisp edges:
  // anti-aliased edges of neighbouring rows would leave light seams between them.
  out << "<g id=\"obstacles\" fill=\"#333\" shape-rendering=\"crispEdges\">\n";
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w;) {
      if (graph.map->passable({x, y})) {
        ++x;
        continue;
      }
      int end = x;
      while (end < w && !graph.map->passable({end, y})) ++end;
      out << "<rect x=\"" << x - 0.5 << "\" y=\"" << y - 0.5 << "\" width=\"" << end - x << "\" height=\"1\"/>\n";
      x = end;
    }
  }
  out << "</g>\n";
  const double line = std::max(0.08, 2.0 / scale);
  std::vector<std::pair<double, double>> points;
  for (NodeId n : pic.grid_path) points.emplace_back(graph.position(n).x() / unit, graph.position(n).y() / unit);
  std::ostringstream style;
  style << "id=\"grid-path\" stroke=\"#1565c0\" stroke-width=\"" << line << "\" stroke-linejoin=\"round\"";
  polyline(out, points, style.str().c_str());
  points.clear();
  for (const auto& p : pic.path) points.emplace_back(p.x() / unit, p.y() / unit);
  style.str("");
  style << "id=\"path\" stroke=\"#d32f2f\" stroke-width=\"" << line << "\" stroke-dasharray=\"" << 3 * line << ','
        << 1.5 * line << "\"";
  polyline(out, points, style.str().c_str());
  for (const auto& [node, colour] : {std::pair{pic.start, kStartColour}, std::pair{pic.goal, kGoalColour}}) {
    if (!ends) break;
    const auto& p = graph.position(node);
    out << "<circle cx=\"" << p.x() / unit << "\" cy=\"" << p.y() / unit << "\" r=\"" << std::max(0.35, 4.0 / scale)
        << "\" fill=\"" << colour << "\"/>\n";
  }
  out << "</g>\n";
}

// The curves span every value: the highest and lowest of both curves and the optimum, with air
// above and below so that no value, an early poor iteration's best in particular, lies on the
// frame where it could not be told from it. An iteration in which no ant arrived leaves a gap.
void draw_convergence(std::ostream& out, const RunPicture& pic, double left, double top) {
  std::vector<double> finite;
  for (const auto* curve : {&pic.best_so_far, &pic.iteration_best})
    for (double v : *curve)
      if (std::isfinite(v)) finite.push_back(v);
  if (pic.optimal_length > 0) finite.push_back(pic.optimal_length);
  out << "<g id=\"convergence\" transform=\"translate(" << left << ',' << top
      << ")\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<rect width=\"" << kPlotWidth << "\" height=\"" << kPlotHeight << "\" fill=\"none\" stroke=\"#888\"/>\n";
  out << "<text x=\"" << kPlotWidth / 2 << "\" y=\"-8\" text-anchor=\"middle\">path length per iteration</text>\n";
  if (finite.empty() || pic.best_so_far.empty()) {
    out << "<text x=\"" << kPlotWidth / 2 << "\" y=\"" << kPlotHeight / 2
        << "\" text-anchor=\"middle\">no path found</text>\n</g>\n";
    return;
  }
  const double low = *std::min_element(finite.begin(), finite.end());
  const double high = *std::max_element(finite.begin(), finite.end());
  const double air = high - low < 1e-9 ? 1.0 : (high - low) * kConvergenceAir;
  const double axis_low = low - air, axis_high = high + air;
  const std::size_t n = std::max(pic.best_so_far.size(), pic.iteration_best.size());
  auto px = [&](std::size_t i) { return n <= 1 ? 0.0 : kPlotWidth * double(i) / double(n - 1); };
  auto py = [&](double v) { return kPlotHeight * (1.0 - (v - axis_low) / (axis_high - axis_low)); };
  auto curve = [&](const std::vector<double>& values, const char* style) {
    std::vector<std::pair<double, double>> points;
    for (std::size_t i = 0; i <= values.size(); ++i) {
      if (i < values.size() && std::isfinite(values[i])) {
        points.emplace_back(px(i), py(values[i]));
        continue;
      }
      if (points.size() == 1)  // one iteration between gaps: a dot, as a line needs two
        out << "<circle cx=\"" << points[0].first << "\" cy=\"" << points[0].second << "\" r=\"1.5\" " << style
            << "/>\n";
      polyline(out, points, style);
      points.clear();
    }
  };
  curve(pic.iteration_best, "stroke=\"#90a4ae\" stroke-width=\"1\" class=\"iteration-best\"");
  curve(pic.best_so_far, "stroke=\"#1565c0\" stroke-width=\"2\" class=\"best-so-far\"");
  if (pic.optimal_length > 0)
    out << "<line x1=\"0\" x2=\"" << kPlotWidth << "\" y1=\"" << py(pic.optimal_length) << "\" y2=\""
        << py(pic.optimal_length) << "\" stroke=\"#43a047\" stroke-dasharray=\"4,3\" class=\"optimum\"/>\n";
  // The highest and the lowest value, each at its height with a tick.
  for (const double v : {high, low})
    out << "<line x1=\"-4\" x2=\"0\" y1=\"" << py(v) << "\" y2=\"" << py(v) << "\" stroke=\"#888\"/><text x=\"-6\" y=\""
        << py(v) + 4 << "\" text-anchor=\"end\">" << v << "</text>\n";
  out << "<text x=\"0\" y=\"" << kPlotHeight + 16 << "\">1</text>\n";
  out << "<text x=\"" << kPlotWidth << "\" y=\"" << kPlotHeight + 16 << "\" text-anchor=\"end\">" << n << "</text>\n";
  out << "<text x=\"" << kPlotWidth / 2 << "\" y=\"" << kPlotHeight + 16
      << "\" text-anchor=\"middle\">iterations run</text>\n";
  const double ly = kPlotHeight + 36;
  out << "<line x1=\"0\" x2=\"20\" y1=\"" << ly << "\" y2=\"" << ly
      << "\" stroke=\"#1565c0\" stroke-width=\"2\"/><text x=\"24\" y=\"" << ly + 4 << "\">best so far</text>\n";
  out << "<line x1=\"120\" x2=\"140\" y1=\"" << ly << "\" y2=\"" << ly << "\" stroke=\"#90a4ae\"/><text x=\"144\" y=\""
      << ly + 4 << "\">iteration best</text>\n";
  if (pic.optimal_length > 0)
    out << "<line x1=\"260\" x2=\"280\" y1=\"" << ly << "\" y2=\"" << ly
        << "\" stroke=\"#43a047\" stroke-dasharray=\"4,3\"/><text x=\"284\" y=\"" << ly + 4
        << "\">optimum (A*)</text>\n";
  out << "</g>\n";
}

// The whole picture: its size, a light background, the title over the parts.
std::string picture_document(double width, double height, const std::string& title, const std::string& parts) {
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  out << "<text x=\"" << kMargin << "\" y=\"24\" font-family=\"sans-serif\" font-size=\"14\">" << xml_escape(title)
      << "</text>\n";
  out << parts << "</svg>\n";
  return out.str();
}

}  // namespace

std::string render_svg(const Graph& graph, const RunPicture& pic) {
  const auto* terrain = dynamic_cast<const TerrainMap*>(graph.map);
  const auto heights = height_range(terrain);
  const double scale = kMapPixels / std::max(graph.width, graph.height);
  const double map_w = graph.width * scale, map_h = graph.height * scale;
  const double plot_left = kMargin * 2 + map_w + 30;
  // Under the plot's own legend: the height legend on terrain, then the map's.
  const double height_legend_top = kMargin + 10 + kPlotHeight + 80;
  const double map_legend_top = height_legend_top + (heights ? 56 : 0);
  const double width = plot_left + kPlotWidth + kMargin;
  // The parts are drawn first and the picture sized after, to hold the tallest of them.
  std::ostringstream parts;
  draw_map(parts, graph, pic, scale, terrain, heights);
  draw_convergence(parts, pic, plot_left, kMargin + 10);
  if (heights) draw_height_legend(parts, *heights, plot_left, height_legend_top);
  const double legend_bottom =
      map_legend_top + draw_map_legend(parts, pic, heights.has_value(), plot_left, map_legend_top);
  const double height = std::max(map_h + kMargin * 2, legend_bottom + kMargin / 2);
  return picture_document(width, height, pic.title, parts.str());
}

std::string render_map_svg(const Graph& graph) {
  const auto* terrain = dynamic_cast<const TerrainMap*>(graph.map);
  const auto heights = height_range(terrain);
  const double scale = kMapPixels / std::max(graph.width, graph.height);
  std::ostringstream parts;
  draw_map(parts, graph, RunPicture{}, scale, terrain, heights, false);
  double width = graph.width * scale + kMargin * 2, height = graph.height * scale + kMargin * 2;
  if (heights) {  // the height legend under the map, its title clear of the map's edge
    const double top = graph.height * scale + kMargin + 30;
    draw_height_legend(parts, *heights, kMargin, top);
    width = std::max(width, kMargin * 2 + height_legend_width());
    height = top + kHeightLegendHeight + kMargin / 2;
  }
  return picture_document(width, height, graph.map->name(), parts.str());
}

std::string run_title(const std::string& map_name, bool solved, double length, std::uint64_t seed) {
  return map_name + ": " + (solved ? "length " + std::to_string(length) : "not solved") + ", seed " +
         std::to_string(seed);
}

void write_svg(const std::filesystem::path& file, const Graph& graph, const RunPicture& picture) {
  write_output_file(file, render_svg(graph, picture), "SVG");
}

double text_width(std::string_view text, double font_size) {
  double ems = 0.0;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte & 0xC0) == 0x80) continue;  // inside a UTF-8 character, counted at its first byte
    const std::string_view narrow = " ijl'.,:;|!", slim = "frt()[]{}/-\\\"";
    double em = 0.9;  // symbols (% + = & ...) and characters beyond ASCII (\u2026, \u25b2)
    if (narrow.find(c) != std::string_view::npos)
      em = 0.33;
    else if (slim.find(c) != std::string_view::npos)
      em = 0.43;
    else if (c == 'm' || c == 'w' || c == 'M' || c == 'W')
      em = 1.0;
    else if (c >= 'A' && c <= 'Z')
      em = 0.79;
    else if ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9'))
      em = 0.64;
    ems += em;
  }
  return ems * font_size;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace aco
