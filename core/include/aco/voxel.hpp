#pragma once
// Voxel worlds: a width x height x depth block of unit cubes, each free or blocked, for planning in
// 3D (drones among buildings, trees, caves). x = column, y = row, z = layer from the ground up,
// all 0-based, as in Moving AI's .3dmap files. Moves between voxels go up and down as well as
// across (aco/graph.hpp: the 6-, 18- and 26-neighbourhoods).
#include <Eigen/Core>
#include <boost/config.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "aco/map.hpp"

namespace aco {

class BOOST_SYMBOL_VISIBLE VoxelMap final : public Map {
 public:
  // Every voxel free. Throws an Error naming `name` for an empty size or one whose voxel count
  // does not fit the graph's 32-bit node ids.
  VoxelMap(int width, int height, int depth, std::string name);

  int width() const override { return width_; }
  int height() const override { return height_; }
  int depth() const override { return depth_; }
  bool volumetric() const override { return true; }
  bool passable(Cell c) const override { return contains(c) && !blocked_[index(c)]; }
  std::string name() const override { return name_; }

  void set_blocked(Cell c, bool blocked) { blocked_[index(c)] = blocked ? 1 : 0; }
  bool blocked(Cell c) const { return blocked_[index(c)] != 0; }
  std::int64_t voxels() const { return static_cast<std::int64_t>(blocked_.size()); }
  std::int64_t blocked_count() const;

  // Metres per voxel and the world position of voxel (0,0,0)'s lower corner, as an OctoMap
  // file gives them; 1 and the origin for formats without units. Planning stays in voxels.
  double resolution() const { return resolution_; }
  const Eigen::Vector3d& origin() const { return origin_; }
  void set_placement(double resolution, const Eigen::Vector3d& origin);

 private:
  std::size_t index(Cell c) const {
    return (static_cast<std::size_t>(c.z) * height_ + static_cast<std::size_t>(c.y)) * width_ + c.x;
  }
  int width_;
  int height_;
  int depth_;
  std::string name_;
  std::vector<std::uint8_t> blocked_;  // per voxel, x fastest, then y, then z
  double resolution_ = 1.0;
  Eigen::Vector3d origin_{0, 0, 0};
};

// with_concrete_map() (aco/map.hpp), with a voxel world as itself too: a loop over its millions
// of voxels then makes no virtual call per voxel either.
template <class F>
void with_concrete_world(const Map& map, F&& f) {
  if (const auto* world = dynamic_cast<const VoxelMap*>(&map))
    f(*world);
  else
    with_concrete_map(map, f);
}

}  // namespace aco
