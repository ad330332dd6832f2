#pragma once
// Self-contained SVG picture of a run: the map, the grid and final paths, optionally the final
// pheromone field, and the convergence curve.
#include <filesystem>
#include <span>
#include <string>
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
  std::vector<double> pheromone;       // per edge, optional
  std::vector<double> best_so_far;     // per iteration, optional
  std::vector<double> iteration_best;  // per iteration, optional
  double optimal_length = 0.0;         // drawn as a reference line when > 0
};

std::string render_svg(const Graph& graph, const RunPicture& picture);
void write_svg(const std::filesystem::path& file, const Graph& graph, const RunPicture& picture);

// Text made safe for SVG, HTML and XML: & < > " as entities.
std::string xml_escape(const std::string& text);

}  // namespace aco
