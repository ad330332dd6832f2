#pragma once
// What the pictures of a voxel world show (aco/drawing/voxel_html.hpp: the 3D page, aco/drawing/voxel_svg.hpp:
// the isometric and sliced SVG), and the blocked voxels they draw.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "aco/map.hpp"

namespace aco {

// A voxel world and a run on it. Coordinates are voxels: voxel (x,y,z)'s centre is at x, y, z
// (aco::Map::position()), x = column, y = row (as in the 2D pictures), z = layer from the ground.
struct VoxelWorldView {
  explicit VoxelWorldView(const Map& world) : map(world) {}
  const Map& map;  // volumetric or not: a 2D map is one layer
  std::vector<Eigen::Vector3d> path;  // the final waypoints; empty: no path
  std::vector<Cell> grid_path;  // optional: voxel to voxel, before the smoother
  std::optional<Cell> start;
  std::optional<Cell> goal;
  // Optional: voxels and their pheromone (any positive scale; drawn relative to the largest),
  // typically the strongest few thousand.
  std::vector<std::pair<Cell, double>> pheromone;
  std::string title;  // "" : the map's name
};

// The blocked voxels worth drawing: those on the surface, a blocked voxel with a free 6-neighbour
// or on the world's boundary (the rest cannot be seen). When there are more than `max_cubes`, the
// world is coarsened: cubes of `cell` x `cell` x `cell` voxels, a cube blocked where any of its
// voxels is, `cell` the smallest that leaves at most `max_cubes` surface cubes.
class VoxelSurface {
 public:
  VoxelSurface(const Map& map, std::size_t max_cubes);

  int cell() const { return cell_; }  // voxels per side of a cube; 1: the world's own voxels
  int width() const { return width_; }  // the grid of cubes
  int height() const { return height_; }
  int depth() const { return depth_; }
  // Cube c of the grid of cubes is blocked (false outside the grid).
  bool blocked(Cell c) const;
  // The surface cubes, x fastest, then y, then z.
  const std::vector<Cell>& cubes() const { return cubes_; }
  std::int64_t blocked_voxels() const { return blocked_voxels_; }  // in the world
  std::int64_t surface_voxels() const { return surface_voxels_; }  // of them on the surface (cell 1)

 private:
  void coarsen(const std::vector<std::uint8_t>& voxels, int world_width, int world_height, int world_depth, int cell);
  std::vector<Cell> surface() const;
  int cell_ = 1;
  int width_ = 0;
  int height_ = 0;
  int depth_ = 0;
  std::vector<std::uint8_t> blocked_;  // per cube, x fastest
  std::vector<Cell> cubes_;
  std::int64_t blocked_voxels_ = 0;
  std::int64_t surface_voxels_ = 0;
};

// The view's title: its own, or the map's name.
std::string view_title(const VoxelWorldView& view);

}  // namespace aco
