#pragma once
// Self-contained SVG picture of a run: the map, the grid and final paths, optionally the final
// pheromone field, and the convergence curve.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "aco/graph.hpp"
#include "aco/path.hpp"

namespace aco {

struct RunPicture {
  std::string title;
  NodeId start = 0;
  NodeId goal = 0;
  std::vector<NodeId> grid_path;
  Waypoints path;
  std::vector<double> pheromone;  // per edge, optional
  std::vector<double> best_so_far;  // per iteration, optional
  std::vector<double> iteration_best;  // per iteration, optional
  double optimal_length = 0.0;  // drawn as a reference line when > 0
};

std::string render_svg(const Graph& graph, const RunPicture& picture);
void write_svg(const std::filesystem::path& file, const Graph& graph, const RunPicture& picture);
// The map alone, drawn as render_svg() draws it (Python's Map._repr_svg_), titled with its name.
std::string render_map_svg(const Graph& graph);
// A run picture's title: "MAP: length L, seed S" or "MAP: not solved, seed S".
std::string run_title(const std::string& map_name, bool solved, double length, std::uint64_t seed);

// Text made safe for SVG, HTML and XML: & < > " as entities.
std::string xml_escape(const std::string& text);

// The width in pixels of `text` (UTF-8) set in a sans-serif font of `font_size` pixels, erring on
// the wide side: the widths are DejaVu Sans's (Linux's default sans-serif, wider than Arial or
// Helvetica) rounded up. Drawings reserve room for their labels and legends with it, so that no
// text is cut off at the picture's edge.
double text_width(std::string_view text, double font_size = 12.0);

}  // namespace aco
