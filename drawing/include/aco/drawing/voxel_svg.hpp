#pragma once
// A voxel world as SVG, for reports: an isometric view (the surface voxels as shaded cubes drawn
// back to front, the path on top) and/or horizontal slices (one panel per chosen layer, with the
// path's points in that layer).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "aco/drawing/voxel_view.hpp"

namespace aco {

struct VoxelSvgStyle {
  bool isometric = true;  // the isometric view, seen from above the world's far (x, y) corner
  std::vector<int> slices;  // layers z drawn as panels, in this order; outside the world: refused
  double isometric_width = 640;  // pixels the isometric view is scaled to fit
  double slice_width = 200;  // pixels per slice panel (its longer side)
  // Cube faces drawn at most in the isometric view (the top and the two sides facing the viewer
  // where no cube covers them; some 70 bytes each); more: the world is drawn in coarser cubes
  // (VoxelSurface), which the legend says. 20,000 faces keep the file under 1.5 MB.
  std::size_t max_faces = 20'000;
};

// Deterministic. Throws aco::Error for a slice outside the world or a style drawing nothing.
std::string render_voxel_svg(const VoxelWorldView& view, const VoxelSvgStyle& style = {});
void write_voxel_svg(const std::filesystem::path& file, const VoxelWorldView& view, const VoxelSvgStyle& style = {});

// Layers for VoxelSvgStyle::slices: `count` of them spread evenly over a world `depth` layers deep,
// the lowest and the highest included, ascending (all of them when the world has no more).
std::vector<int> spread_layers(int depth, int count);

}  // namespace aco
