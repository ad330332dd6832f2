#pragma once
// The colours of the voxel world's pictures, one set for the 3D page and the SVG. Start and goal
// are the 2D picture's (svg.cpp); the path is orange there being a red goal beside it.
namespace aco::voxel_colours {

constexpr const char* kStart = "#43a047";
constexpr const char* kGoal = "#e53935";
constexpr const char* kPath = "#f57c00";
constexpr const char* kGridPath = "#1565c0";
constexpr const char* kVoxelLow = "#546e7a";  // blocked voxels, shaded by height: the lowest layer
constexpr const char* kVoxelHigh = "#90a4ae";  // ... the highest
constexpr const char* kPheromoneWeak = "#ce93d8";
constexpr const char* kPheromoneStrong = "#6a1b9a";
constexpr const char* kFrame = "#9e9e9e";  // the world's bounding box

}  // namespace aco::voxel_colours
