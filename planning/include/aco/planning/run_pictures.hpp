#pragma once
// What the pictures of a planned run show, for every front end that draws one (acoplan's --svg
// and --html, Python's Result): the map, the grid path and the final path, start and goal, the
// convergence curve against the optimum, and on request the final pheromone field.
#include <span>
#include <vector>

#include "aco/graph.hpp"
#include "aco/drawing/svg.hpp"
#include "aco/drawing/voxel_view.hpp"
#include "aco/planning/yardsticks.hpp"

namespace aco {

// A run on a 2D map (aco::render_svg()).
RunPicture run_picture(const Graph& graph, const PlanRun& run, bool pheromone);

// Per node: the strongest of `per_edge` (a value per edge of `graph`) on an edge into it, 0 for
// none. What a voxel world's view and the ROS node's pheromone grid show per cell.
std::vector<double> strongest_into(const Graph& graph, std::span<const double> per_edge);

// A run in a voxel world (aco::render_voxel_svg(), aco::render_voxel_html()). The pheromone: per
// voxel the strongest edge into it, for the voxels above the median (most voxels keep the initial
// value, and a world has millions), the strongest few thousand of them.
VoxelWorldView run_view(const Graph& graph, const PlanRun& run, bool pheromone);

}  // namespace aco
