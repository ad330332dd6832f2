#pragma once
// The 3D page of a voxel world: one self-contained HTML file (three.js inside it, no network) that
// shows the world's surface voxels, the path, start and goal, and the pheromone, turned and zoomed
// with the mouse. acoplan writes it with --html.
#include <cstddef>
#include <filesystem>
#include <string>

#include "aco/drawing/voxel_view.hpp"

namespace aco {

struct VoxelHtmlOptions {
  // Surface cubes drawn at most; a larger surface is drawn coarsened (VoxelSurface), which the
  // page says. 200,000 cubes turn smoothly on a laptop's GPU.
  std::size_t max_cubes = 200'000;
  // Pheromone voxels drawn at most: the strongest.
  std::size_t max_pheromone = 20'000;
};

// The page's text. Deterministic: the same view gives the same bytes.
std::string render_voxel_html(const VoxelWorldView& view, const VoxelHtmlOptions& options = {});
// Written whole through aco::write_output_file() (errors name the file).
void write_voxel_html(const std::filesystem::path& file, const VoxelWorldView& view,
                      const VoxelHtmlOptions& options = {});

}  // namespace aco
