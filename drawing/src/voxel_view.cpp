#include "aco/drawing/voxel_view.hpp"

#include <algorithm>
#include <cmath>

namespace aco {

VoxelSurface::VoxelSurface(const Map& map, std::size_t max_cubes) {
  const int w = map.width(), h = map.height(), d = map.depth();
  std::vector<std::uint8_t> voxels(static_cast<std::size_t>(w) * h * d);
  std::size_t i = 0;
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x, ++i) {
        voxels[i] = map.passable({x, y, z}) ? 0 : 1;
        blocked_voxels_ += voxels[i];
      }
  coarsen(voxels, w, h, d, 1);
  cubes_ = surface();
  surface_voxels_ = static_cast<std::int64_t>(cubes_.size());
  max_cubes = std::max<std::size_t>(max_cubes, 1);
  if (cubes_.size() <= max_cubes) return;
  // A surface shrinks about with the square of the cube's side: start near the side that fits.
  int cell = std::max(2, static_cast<int>(std::sqrt(double(cubes_.size()) / double(max_cubes))));
  for (;; ++cell) {
    coarsen(voxels, w, h, d, cell);
    cubes_ = surface();
    if (cubes_.size() <= max_cubes || (width_ == 1 && height_ == 1 && depth_ == 1)) return;
  }
}

void VoxelSurface::coarsen(const std::vector<std::uint8_t>& voxels, int world_width, int world_height, int world_depth,
                           int cell) {
  cell_ = cell;
  width_ = (world_width + cell - 1) / cell;
  height_ = (world_height + cell - 1) / cell;
  depth_ = (world_depth + cell - 1) / cell;
  blocked_.assign(static_cast<std::size_t>(width_) * height_ * depth_, 0);
  std::size_t i = 0;
  for (int z = 0; z < world_depth; ++z)
    for (int y = 0; y < world_height; ++y)
      for (int x = 0; x < world_width; ++x, ++i)
        if (voxels[i]) blocked_[(static_cast<std::size_t>(z / cell) * height_ + y / cell) * width_ + x / cell] = 1;
}

bool VoxelSurface::blocked(Cell c) const {
  if (c.x < 0 || c.y < 0 || c.z < 0 || c.x >= width_ || c.y >= height_ || c.z >= depth_) return false;
  return blocked_[(static_cast<std::size_t>(c.z) * height_ + c.y) * width_ + c.x] != 0;
}

std::vector<Cell> VoxelSurface::surface() const {
  std::vector<Cell> cubes;
  for (int z = 0; z < depth_; ++z)
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) {
        if (!blocked({x, y, z})) continue;
        const bool boundary = x == 0 || y == 0 || z == 0 || x == width_ - 1 || y == height_ - 1 || z == depth_ - 1;
        if (boundary || !blocked({x - 1, y, z}) || !blocked({x + 1, y, z}) || !blocked({x, y - 1, z}) ||
            !blocked({x, y + 1, z}) || !blocked({x, y, z - 1}) || !blocked({x, y, z + 1}))
          cubes.push_back({x, y, z});
      }
  return cubes;
}

std::string view_title(const VoxelWorldView& view) { return view.title.empty() ? view.map.name() : view.title; }

}  // namespace aco
