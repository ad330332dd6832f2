#include "aco/svg.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "aco/error.hpp"

namespace aco {
namespace {

constexpr double kMapPixels = 560.0;
constexpr double kPlotWidth = 420.0;
constexpr double kPlotHeight = 300.0;
constexpr double kMargin = 40.0;

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

void polyline(std::ostream& out, const std::vector<std::pair<double, double>>& points, const char* style) {
  if (points.size() < 2) return;
  out << "<polyline fill=\"none\" " << style << " points=\"";
  for (const auto& [x, y] : points) out << x << ',' << y << ' ';
  out << "\"/>\n";
}

// Cells are drawn centred on their positions, in map units scaled by `scale`.
void draw_map(std::ostream& out, const Graph& graph, const RunPicture& pic, double scale) {
  const int w = graph.width, h = graph.height;
  out << "<g id=\"map\" transform=\"translate(" << kMargin << ',' << kMargin << ") scale(" << scale
      << ") translate(0.5,0.5)\">\n";
  out << "<rect x=\"-0.5\" y=\"-0.5\" width=\"" << w << "\" height=\"" << h << "\" fill=\"#ffffff\" stroke=\"#888\" stroke-width=\""
      << 1.0 / scale << "\"/>\n";
  if (!pic.pheromone.empty()) {
    // Pheromone of a cell = sum over the edges into it.
    std::vector<double> cell(graph.num_nodes(), 0.0);
    for (EdgeId e = 0; e < graph.num_edges(); ++e) cell[graph.targets[e]] += pic.pheromone[e];
    const double top = *std::max_element(cell.begin(), cell.end());
    out << "<g id=\"pheromone\" fill=\"#2e7d32\">\n";
    for (NodeId n = 0; n < graph.num_nodes(); ++n) {
      if (top <= 0 || cell[n] <= 0) continue;
      const double opacity = std::sqrt(cell[n] / top) * 0.8;
      if (opacity < 0.02) continue;
      const Cell c = graph.cell(n);
      out << "<rect x=\"" << c.x - 0.5 << "\" y=\"" << c.y - 0.5 << "\" width=\"1\" height=\"1\" fill-opacity=\"" << opacity
          << "\"/>\n";
    }
    out << "</g>\n";
  }
  // Blocked cells, merged into horizontal runs to keep large maps small.
  out << "<g id=\"obstacles\" fill=\"#333\">\n";
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
  for (NodeId n : pic.grid_path) points.emplace_back(graph.positions[n].x(), graph.positions[n].y());
  std::ostringstream style;
  style << "id=\"grid-path\" stroke=\"#1565c0\" stroke-width=\"" << line << "\" stroke-linejoin=\"round\"";
  polyline(out, points, style.str().c_str());
  points.clear();
  for (const auto& p : pic.path) points.emplace_back(p.x(), p.y());
  style.str("");
  style << "id=\"path\" stroke=\"#d32f2f\" stroke-width=\"" << line << "\" stroke-dasharray=\"" << 3 * line << ','
        << 1.5 * line << "\"";
  polyline(out, points, style.str().c_str());
  for (const auto& [node, colour] : {std::pair{pic.start, "#43a047"}, std::pair{pic.goal, "#e53935"}}) {
    const auto& p = graph.positions[node];
    out << "<circle cx=\"" << p.x() << "\" cy=\"" << p.y() << "\" r=\"" << std::max(0.35, 4.0 / scale) << "\" fill=\""
        << colour << "\"/>\n";
  }
  out << "</g>\n";
}

void draw_convergence(std::ostream& out, const RunPicture& pic, double left, double top) {
  std::vector<double> finite;
  for (const auto* curve : {&pic.best_so_far, &pic.iteration_best})
    for (double v : *curve)
      if (std::isfinite(v)) finite.push_back(v);
  if (pic.optimal_length > 0) finite.push_back(pic.optimal_length);
  out << "<g id=\"convergence\" transform=\"translate(" << left << ',' << top << ")\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<rect width=\"" << kPlotWidth << "\" height=\"" << kPlotHeight << "\" fill=\"none\" stroke=\"#888\"/>\n";
  out << "<text x=\"" << kPlotWidth / 2 << "\" y=\"-8\" text-anchor=\"middle\">path length per iteration</text>\n";
  if (finite.empty() || pic.best_so_far.empty()) {
    out << "<text x=\"" << kPlotWidth / 2 << "\" y=\"" << kPlotHeight / 2 << "\" text-anchor=\"middle\">no path found</text>\n</g>\n";
    return;
  }
  double low = *std::min_element(finite.begin(), finite.end());
  double high = *std::max_element(finite.begin(), finite.end());
  if (high - low < 1e-9) low -= 1, high += 1;
  const std::size_t n = pic.best_so_far.size();
  auto px = [&](std::size_t i) { return n <= 1 ? 0.0 : kPlotWidth * double(i) / double(n - 1); };
  auto py = [&](double v) { return kPlotHeight * (1.0 - (v - low) / (high - low)); };
  auto curve = [&](const std::vector<double>& values, const char* style) {
    std::vector<std::pair<double, double>> points;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (std::isfinite(values[i])) points.emplace_back(px(i), py(values[i]));
    polyline(out, points, style);
  };
  curve(pic.iteration_best, "stroke=\"#90a4ae\" stroke-width=\"1\" class=\"iteration-best\"");
  curve(pic.best_so_far, "stroke=\"#1565c0\" stroke-width=\"2\" class=\"best-so-far\"");
  if (pic.optimal_length > 0)
    out << "<line x1=\"0\" x2=\"" << kPlotWidth << "\" y1=\"" << py(pic.optimal_length) << "\" y2=\"" << py(pic.optimal_length)
        << "\" stroke=\"#43a047\" stroke-dasharray=\"4,3\" class=\"optimum\"/>\n";
  out << "<text x=\"-4\" y=\"" << py(high) + 4 << "\" text-anchor=\"end\">" << high << "</text>\n";
  out << "<text x=\"-4\" y=\"" << py(low) + 4 << "\" text-anchor=\"end\">" << low << "</text>\n";
  out << "<text x=\"0\" y=\"" << kPlotHeight + 16 << "\">1</text>\n";
  out << "<text x=\"" << kPlotWidth << "\" y=\"" << kPlotHeight + 16 << "\" text-anchor=\"end\">" << n << "</text>\n";
  out << "<text x=\"" << kPlotWidth / 2 << "\" y=\"" << kPlotHeight + 16 << "\" text-anchor=\"middle\">iteration</text>\n";
  const double ly = kPlotHeight + 36;
  out << "<line x1=\"0\" x2=\"20\" y1=\"" << ly << "\" y2=\"" << ly << "\" stroke=\"#1565c0\" stroke-width=\"2\"/><text x=\"24\" y=\""
      << ly + 4 << "\">best so far</text>\n";
  out << "<line x1=\"120\" x2=\"140\" y1=\"" << ly << "\" y2=\"" << ly << "\" stroke=\"#90a4ae\"/><text x=\"144\" y=\"" << ly + 4
      << "\">iteration best</text>\n";
  if (pic.optimal_length > 0)
    out << "<line x1=\"260\" x2=\"280\" y1=\"" << ly << "\" y2=\"" << ly << "\" stroke=\"#43a047\" stroke-dasharray=\"4,3\"/><text x=\"284\" y=\""
        << ly + 4 << "\">optimum (A*)</text>\n";
  out << "</g>\n";
}

}  // namespace

std::string render_svg(const Graph& graph, const RunPicture& pic) {
  const double scale = kMapPixels / std::max(graph.width, graph.height);
  const double map_w = graph.width * scale, map_h = graph.height * scale;
  const double plot_left = kMargin * 2 + map_w + 30;
  const double width = plot_left + kPlotWidth + kMargin;
  const double height = std::max(map_h, kPlotHeight + 60) + kMargin * 2;
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << ' ' << height << "\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  out << "<text x=\"" << kMargin << "\" y=\"24\" font-family=\"sans-serif\" font-size=\"14\">" << escape(pic.title) << "</text>\n";
  draw_map(out, graph, pic, scale);
  draw_convergence(out, pic, plot_left, kMargin + 10);
  out << "</svg>\n";
  return out.str();
}

void write_svg(const std::filesystem::path& file, const Graph& graph, const RunPicture& picture) {
  std::ofstream out(file);
  if (!out) throw Error(file.string() + ": cannot write SVG file");
  out << render_svg(graph, picture);
  if (!out) throw Error(file.string() + ": error while writing SVG file");
}

}  // namespace aco
