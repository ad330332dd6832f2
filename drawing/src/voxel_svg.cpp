#include "aco/drawing/voxel_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>
#include <tuple>

#include "aco/error.hpp"
#include "aco/process/output_file.hpp"
#include "aco/drawing/svg.hpp"
#include "voxel_colours.hpp"

namespace aco {
namespace {

namespace colours = voxel_colours;

constexpr double kMargin = 20;
constexpr double kTitleHeight = 34;  // the title's line, above the views
constexpr double kGap = 24;  // between the parts
constexpr double kLegendRow = 18;
constexpr double kSliceLabel = 18;  // a slice's "z = N" above it
constexpr int kHeightBands = 16;  // cubes of one band share their faces' colours
// Shading of the faces seen from above the far corner: the top lit, the others darker.
constexpr double kTopLight = 1.0, kRightLight = 0.78, kLeftLight = 0.6;

// Coordinates with at most two decimals, trailing zeros dropped: 12.5, 3, -0.25.
std::string num(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", std::abs(v) < 0.005 ? 0.0 : v);
  std::string s = text;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s;
}

struct Rgb {
  double r, g, b;
};
Rgb parse(const char* hex) {
  unsigned r = 0, g = 0, b = 0;
  std::sscanf(hex, "#%02x%02x%02x", &r, &g, &b);
  return {double(r), double(g), double(b)};
}
std::string hex(Rgb c, double light = 1.0) {
  char text[8];
  auto channel = [light](double v) { return static_cast<int>(std::lround(std::clamp(v * light, 0.0, 255.0))); };
  std::snprintf(text, sizeof text, "#%02x%02x%02x", channel(c.r), channel(c.g), channel(c.b));
  return text;
}
Rgb band_colour(int band) {
  const Rgb low = parse(colours::kVoxelLow), high = parse(colours::kVoxelHigh);
  const double t = kHeightBands > 1 ? double(band) / (kHeightBands - 1) : 0.0;
  return {low.r + (high.r - low.r) * t, low.g + (high.g - low.g) * t, low.b + (high.b - low.b) * t};
}

// The isometric projection, in pixels: x runs down to the right, y down to the left, z up.
struct Isometric {
  double scale = 1;
  double left = 0, top = 0;  // where the projection's origin is in the picture
  std::pair<double, double> operator()(double x, double y, double z) const {
    static const double kCos30 = std::sqrt(3.0) / 2;
    return {left + (x - y) * kCos30 * scale, top + ((x + y) * 0.5 - z) * scale};
  }
};

// The extent of the world's box projected at scale 1: min x, max x, min y, max y.
std::array<double, 4> projected_extent(const Map& map) {
  const Isometric unit;
  std::array<double, 4> e{1e300, -1e300, 1e300, -1e300};
  for (double x : {-0.5, map.width() - 0.5})
    for (double y : {-0.5, map.height() - 0.5})
      for (double z : {-0.5, map.depth() - 0.5}) {
        const auto [px, py] = unit(x, y, z);
        e = {std::min(e[0], px), std::max(e[1], px), std::min(e[2], py), std::max(e[3], py)};
      }
  return e;
}

void polyline(std::ostream& out, const std::vector<std::pair<double, double>>& points, const std::string& attributes) {
  if (points.size() < 2) return;
  out << "<polyline fill=\"none\" " << attributes << " points=\"";
  for (std::size_t i = 0; i < points.size(); ++i)
    out << (i ? " " : "") << num(points[i].first) << ',' << num(points[i].second);
  out << "\"/>\n";
}

void end_mark(std::ostream& out, const char* id, std::pair<double, double> at, double radius, const char* colour) {
  out << "<circle id=\"" << id << "\" cx=\"" << num(at.first) << "\" cy=\"" << num(at.second) << "\" r=\""
      << num(radius) << "\" fill=\"" << colour << "\" stroke=\"#fff\" stroke-width=\"1\"/>\n";
}

// The faces draw_isometric() draws: a cube's top, +x and +y faces not covered by a neighbour.
std::size_t visible_faces(const VoxelSurface& surface) {
  std::size_t faces = 0;
  for (const Cell& c : surface.cubes())
    faces += !surface.blocked({c.x, c.y, c.z + 1}) + !surface.blocked({c.x + 1, c.y, c.z}) +
             !surface.blocked({c.x, c.y + 1, c.z});
  return faces;
}

// The isometric view at (left, top), `width` wide; returns its height.
double draw_isometric(std::ostream& out, const VoxelWorldView& view, const VoxelSurface& surface, double left,
                      double top, double width) {
  const Map& map = view.map;
  const auto extent = projected_extent(map);
  Isometric iso;
  iso.scale = width / (extent[1] - extent[0]);
  iso.left = left - extent[0] * iso.scale;
  iso.top = top - extent[2] * iso.scale;
  const double height = (extent[3] - extent[2]) * iso.scale;
  out << "<g id=\"isometric\">\n";
  // The floor's outline, under everything.
  {
    std::vector<std::pair<double, double>> floor;
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{-0.5, -0.5},
                                                                     {map.width() - 0.5, -0.5},
                                                                     {map.width() - 0.5, map.height() - 0.5},
                                                                     {-0.5, map.height() - 0.5},
                                                                     {-0.5, -0.5}})
      floor.push_back(iso(x, y, -0.5));
    polyline(out, floor, std::string("id=\"floor\" stroke=\"") + colours::kFrame + "\" stroke-dasharray=\"4,3\"");
  }
  // Cubes back to front: along the view, a cube can hide only cubes of a smaller x + y + z.
  std::vector<Cell> cubes = surface.cubes();
  std::stable_sort(cubes.begin(), cubes.end(),
                   [](const Cell& a, const Cell& b) { return a.x + a.y + a.z < b.x + b.y + b.z; });
  const int k = surface.cell();
  out << "<g id=\"voxels\" stroke-width=\"0.4\" stroke-linejoin=\"round\">\n";
  for (const Cell& c : cubes) {
    const double x0 = c.x * k - 0.5, x1 = std::min((c.x + 1) * k, map.width()) - 0.5;
    const double y0 = c.y * k - 0.5, y1 = std::min((c.y + 1) * k, map.height()) - 0.5;
    const double z0 = c.z * k - 0.5, z1 = std::min((c.z + 1) * k, map.depth()) - 0.5;
    const double middle = (z0 + z1) / 2;  // the cube's central layer
    const int band =
        map.depth() > 1
            ? std::clamp(static_cast<int>(middle / (map.depth() - 1) * (kHeightBands - 1) + 0.5), 0, kHeightBands - 1)
            : 0;
    auto face = [&](const char* kind, std::array<std::array<double, 3>, 4> corners) {
      out << "<path class=\"" << kind << band << "\" d=\"M";
      for (std::size_t i = 0; i < 4; ++i) {
        const auto [px, py] = iso(corners[i][0], corners[i][1], corners[i][2]);
        out << (i ? "L" : "") << num(px) << ' ' << num(py);
      }
      out << "Z\"/>\n";
    };
    if (!surface.blocked({c.x, c.y, c.z + 1})) face("t", {{{x0, y0, z1}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z1}}});
    if (!surface.blocked({c.x + 1, c.y, c.z})) face("r", {{{x1, y0, z0}, {x1, y1, z0}, {x1, y1, z1}, {x1, y0, z1}}});
    if (!surface.blocked({c.x, c.y + 1, c.z})) face("l", {{{x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1}}});
  }
  out << "</g>\n";
  // The paths on top of the voxels.
  const double line = std::clamp(iso.scale * 0.35, 1.5, 4.0);
  std::vector<std::pair<double, double>> points;
  for (const Cell& c : view.grid_path) points.push_back(iso(c.x, c.y, c.z));
  polyline(out, points,
           std::string("id=\"grid-path\" stroke=\"") + colours::kGridPath + "\" stroke-width=\"" + num(line / 2) +
               "\" stroke-linejoin=\"round\"");
  points.clear();
  for (const auto& p : view.path) points.push_back(iso(p.x(), p.y(), p.z()));
  polyline(out, points,
           std::string("id=\"path\" stroke=\"") + colours::kPath + "\" stroke-width=\"" + num(line) +
               "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"");
  const double radius = std::max(4.0, line * 1.6);
  if (view.start) end_mark(out, "start", iso(view.start->x, view.start->y, view.start->z), radius, colours::kStart);
  if (view.goal) end_mark(out, "goal", iso(view.goal->x, view.goal->y, view.goal->z), radius, colours::kGoal);
  out << "</g>\n";
  return height;
}

// The part of segment a-b with z in [layer - 0.5, layer + 0.5), if any.
std::optional<std::pair<Eigen::Vector3d, Eigen::Vector3d>> clip_to_layer(const Eigen::Vector3d& a,
                                                                         const Eigen::Vector3d& b, int layer) {
  const double low = layer - 0.5, high = layer + 0.5;
  double t0 = 0, t1 = 1;
  const double dz = b.z() - a.z();
  if (std::abs(dz) < 1e-12) {
    if (a.z() < low || a.z() >= high) return std::nullopt;
  } else {
    double ta = (low - a.z()) / dz, tb = (high - a.z()) / dz;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return std::nullopt;
  }
  return std::pair{a + t0 * (b - a), a + t1 * (b - a)};
}

// The pieces of a polyline in a layer, each a polyline of its own (joined where they meet).
std::vector<std::vector<Eigen::Vector3d>> pieces_in_layer(const std::vector<Eigen::Vector3d>& line, int layer) {
  std::vector<std::vector<Eigen::Vector3d>> pieces;
  if (line.size() == 1 && clip_to_layer(line[0], line[0], layer)) pieces.push_back({line[0]});
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const auto part = clip_to_layer(line[i], line[i + 1], layer);
    if (!part) continue;
    if (!pieces.empty() && (pieces.back().back() - part->first).norm() < 1e-9)
      pieces.back().push_back(part->second);
    else
      pieces.push_back({part->first, part->second});
  }
  return pieces;
}

// One layer at (left, top), `scale` pixels per voxel.
void draw_slice(std::ostream& out, const VoxelWorldView& view, int layer, double left, double top, double scale) {
  const Map& map = view.map;
  const int w = map.width(), h = map.height();
  out << "<g class=\"slice\" data-z=\"" << layer << "\">\n";
  out << "<text x=\"" << num(left) << "\" y=\"" << num(top - 5) << "\">z = " << layer << "</text>\n";
  out << "<g transform=\"translate(" << num(left) << ',' << num(top) << ") scale(" << num(scale) << ")\"><rect width=\""
      << w << "\" height=\"" << h << "\" fill=\"#fff\" stroke=\"#888\" stroke-width=\"" << num(1 / scale) << "\"/>\n";
  out << "<g fill=\"" << colours::kVoxelLow << "\" shape-rendering=\"crispEdges\">";
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w;) {
      if (map.passable({x, y, layer})) {
        ++x;
        continue;
      }
      int end = x;
      while (end < w && !map.passable({end, y, layer})) ++end;
      out << "<rect x=\"" << x << "\" y=\"" << y << "\" width=\"" << end - x << "\" height=\"1\"/>";
      x = end;
    }
  out << "</g></g>\n";
  // Lines and marks in pixels, so that their widths do not grow with the scale.
  auto pixel = [&](const Eigen::Vector3d& p) {
    return std::pair{left + (p.x() + 0.5) * scale, top + (p.y() + 0.5) * scale};
  };
  const double line = std::clamp(scale * 0.3, 1.0, 3.0);
  auto draw_pieces = [&](const std::vector<Eigen::Vector3d>& polyline_points, const std::string& attributes,
                         double dot) {
    for (const auto& piece : pieces_in_layer(polyline_points, layer)) {
      std::vector<std::pair<double, double>> points;
      for (const auto& p : piece) points.push_back(pixel(p));
      if (points.size() >= 2 && (piece.front() - piece.back()).norm() > 1e-9)
        polyline(out, points, attributes);
      else  // a vertical step through the layer: a dot
        out << "<circle class=\"dot\" cx=\"" << num(points[0].first) << "\" cy=\"" << num(points[0].second) << "\" r=\""
            << num(dot) << "\" " << attributes << "/>\n";
    }
  };
  std::vector<Eigen::Vector3d> grid;
  for (const Cell& c : view.grid_path) grid.emplace_back(c.x, c.y, c.z);
  draw_pieces(
      grid,
      std::string("class=\"grid-path\" stroke=\"") + colours::kGridPath + "\" stroke-width=\"" + num(line / 2) + "\"",
      line);
  draw_pieces(view.path,
              std::string("class=\"path\" stroke=\"") + colours::kPath + "\" stroke-width=\"" + num(line) +
                  "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"",
              line * 1.2);
  const double radius = std::max(3.0, line * 1.5);
  for (const auto& [end, colour, id] :
       {std::tuple{view.start, colours::kStart, "start"}, std::tuple{view.goal, colours::kGoal, "goal"}})
    if (end && end->z == layer) {
      const auto at = pixel(Eigen::Vector3d(end->x, end->y, end->z));
      out << "<circle class=\"" << id << "\" cx=\"" << num(at.first) << "\" cy=\"" << num(at.second) << "\" r=\""
          << num(radius) << "\" fill=\"" << colour << "\"/>\n";
    }
  out << "</g>\n";
}

// The legend at (left, top); returns its height.
double draw_legend(std::ostream& out, const VoxelWorldView& view, const VoxelSurface* surface, double left, double top,
                   double* width) {
  struct Entry {
    std::string mark;
    std::string label;
  };
  std::vector<Entry> entries;
  const auto circle = [](const char* colour) {
    return std::string("<circle cx=\"10\" cy=\"0\" r=\"4\" fill=\"") + colour + "\"/>";
  };
  const auto line = [](const char* colour, double w) {
    return std::string("<line x1=\"0\" x2=\"20\" y1=\"0\" y2=\"0\" stroke=\"") + colour + "\" stroke-width=\"" +
           num(w) + "\"/>";
  };
  if (view.start) entries.push_back({circle(colours::kStart), "start " + view.map.describe(*view.start)});
  if (view.goal) entries.push_back({circle(colours::kGoal), "goal " + view.map.describe(*view.goal)});
  if (!view.path.empty()) entries.push_back({line(colours::kPath, 3), "path"});
  if (!view.grid_path.empty()) entries.push_back({line(colours::kGridPath, 1.5), "grid path (voxel to voxel)"});
  const Rgb low = parse(colours::kVoxelLow), high = parse(colours::kVoxelHigh);
  entries.push_back({"<rect x=\"0\" y=\"-6\" width=\"10\" height=\"12\" fill=\"" + hex(low) +
                         "\"/><rect x=\"10\" y=\"-6\" width=\"10\" height=\"12\" fill=\"" + hex(high) + "\"/>",
                     "blocked voxels, low to high"});
  if (surface && surface->cell() > 1) {
    const std::string k = std::to_string(surface->cell());
    entries.push_back(
        {"", "isometric view: each cube is " + k + " x " + k + " x " + k + " voxels, blocked where any of them is"});
  }
  out << "<g id=\"legend\" transform=\"translate(" << num(left) << ',' << num(top) << ")\">\n";
  *width = 0;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const double y = double(i) * kLegendRow;
    out << "<g transform=\"translate(0," << num(y) << ")\">" << entries[i].mark << "<text x=\"26\" y=\"4\">"
        << xml_escape(entries[i].label) << "</text></g>\n";
    *width = std::max(*width, 26 + text_width(entries[i].label));
  }
  out << "</g>\n";
  return double(entries.size()) * kLegendRow;
}

}  // namespace

std::vector<int> spread_layers(int depth, int count) {
  std::vector<int> layers;
  if (depth <= 0 || count <= 0) return layers;
  if (count >= depth || count == 1) {
    for (int z = 0; z < std::min(depth, count); ++z) layers.push_back(count == 1 ? 0 : z);
    return layers;
  }
  for (int i = 0; i < count; ++i) {
    const int z = static_cast<int>(std::floor(double(i) * (depth - 1) / (count - 1) + 1e-9));
    if (layers.empty() || layers.back() != z) layers.push_back(z);
  }
  return layers;
}

std::string render_voxel_svg(const VoxelWorldView& view, const VoxelSvgStyle& style) {
  const Map& map = view.map;
  if (!style.isometric && style.slices.empty())
    throw Error("a voxel world's SVG needs the isometric view or at least one slice");
  for (int z : style.slices)
    if (z < 0 || z >= map.depth())
      throw Error("slice z = " + std::to_string(z) + " is outside " + map.name() + " (layers 0 to " +
                  std::to_string(map.depth() - 1) + ")");
  std::ostringstream parts;
  double y = kTitleHeight, width = 0;
  std::optional<VoxelSurface> surface;
  if (style.isometric) {
    // Coarser until the faces fit: each try allows fewer cubes than the last drew.
    std::size_t max_cubes = std::numeric_limits<std::size_t>::max();
    for (;;) {
      surface.emplace(map, max_cubes);
      const std::size_t faces = visible_faces(*surface), cubes = surface->cubes().size();
      if (faces <= style.max_faces || cubes <= 1) break;
      max_cubes =
          std::min(cubes - 1, static_cast<std::size_t>(double(cubes) * double(style.max_faces) / double(faces)));
    }
    y += draw_isometric(parts, view, *surface, kMargin, y, style.isometric_width) + kGap;
    width = style.isometric_width;
  }
  double legend_width = 0;
  y += draw_legend(parts, view, surface ? &*surface : nullptr, kMargin, y + 6, &legend_width) + kGap;
  width = std::max(width, legend_width);
  if (!style.slices.empty()) {
    const double scale = style.slice_width / std::max(map.width(), map.height());
    const double panel_w = map.width() * scale, panel_h = map.height() * scale;
    const int per_row =
        std::max(1, static_cast<int>((std::max(width, 3 * panel_w + 2 * kGap) + kGap) / (panel_w + kGap)));
    parts << "<g id=\"slices\">\n";
    for (std::size_t i = 0; i < style.slices.size(); ++i) {
      const int column = static_cast<int>(i) % per_row, row = static_cast<int>(i) / per_row;
      const double left = kMargin + column * (panel_w + kGap);
      draw_slice(parts, view, style.slices[i], left, y + kSliceLabel + row * (panel_h + kSliceLabel + kGap), scale);
      width = std::max(width, left + panel_w - kMargin);
    }
    parts << "</g>\n";
    const int rows = (static_cast<int>(style.slices.size()) + per_row - 1) / per_row;
    y += rows * (panel_h + kSliceLabel + kGap);
  }
  const std::string title = view_title(view);
  width = std::max(width, text_width(title, 14)) + 2 * kMargin;
  const double height = y + kMargin - kGap;
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(width) << "\" height=\"" << num(height)
      << "\" viewBox=\"0 0 " << num(width) << ' ' << num(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  // The faces' colours, per height band: t top, r the face towards +x, l the face towards +y.
  out << "<style>";
  for (int band = 0; band < kHeightBands; ++band) {
    const Rgb c = band_colour(band);
    out << ".t" << band << "{fill:" << hex(c, kTopLight) << ";stroke:" << hex(c, kTopLight * 0.8) << "}.r" << band
        << "{fill:" << hex(c, kRightLight) << ";stroke:" << hex(c, kRightLight * 0.8) << "}.l" << band
        << "{fill:" << hex(c, kLeftLight) << ";stroke:" << hex(c, kLeftLight * 0.8) << "}";
  }
  out << "</style>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  out << "<text x=\"" << num(kMargin) << "\" y=\"24\" font-size=\"14\">" << xml_escape(title) << "</text>\n";
  out << parts.str() << "</svg>\n";
  return out.str();
}

void write_voxel_svg(const std::filesystem::path& file, const VoxelWorldView& view, const VoxelSvgStyle& style) {
  write_output_file(file, render_voxel_svg(view, style), "SVG");
}

}  // namespace aco
