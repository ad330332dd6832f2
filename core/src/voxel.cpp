#include "aco/voxel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "aco/error.hpp"

namespace aco {

VoxelMap::VoxelMap(int width, int height, int depth, std::string name)
    : width_(width), height_(height), depth_(depth), name_(std::move(name)) {
  const std::string size = std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(depth);
  if (width <= 0 || height <= 0 || depth <= 0) throw Error(name_ + ": voxel world size " + size + " is empty");
  const std::int64_t voxels = std::int64_t{width} * height * depth;
  if (voxels > std::numeric_limits<std::int32_t>::max())
    throw Error(name_ + ": a voxel world of " + size + " voxels exceeds the graph's 32-bit node ids");
  blocked_.assign(static_cast<std::size_t>(voxels), 0);
}

std::int64_t VoxelMap::blocked_count() const { return std::count(blocked_.begin(), blocked_.end(), 1); }

void VoxelMap::set_placement(double resolution, const Eigen::Vector3d& origin) {
  if (!(resolution > 0.0) || !std::isfinite(resolution) || !origin.allFinite())
    throw Error(name_ + ": a voxel world needs a positive, finite resolution and a finite origin");
  resolution_ = resolution;
  origin_ = origin;
}

}  // namespace aco
