#include "aco/terrain.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "aco/error.hpp"

namespace aco {
namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

double slope_degrees(double rise, double run) { return std::atan2(std::abs(rise), run) * kDegreesPerRadian; }

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

TerrainMap::TerrainMap(int width, int height, double cell_size, std::vector<double> heights, double max_slope_deg,
                       std::string name)
    : width_(width),
      height_(height),
      cell_size_(cell_size),
      max_slope_deg_(max_slope_deg),
      name_(std::move(name)),
      heights_(std::move(heights)) {
  if (width <= 0 || height <= 0)
    throw Error(name_ + ": map size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
  const std::size_t cells = static_cast<std::size_t>(width) * height;
  if (heights_.size() != cells)
    throw Error(name_ + ": " + std::to_string(heights_.size()) + " heights for a " + std::to_string(width) + "x" +
                std::to_string(height) + " map (expected " + std::to_string(cells) + ")");
  if (!(cell_size > 0) || !(cell_size <= kMaxTerrainMagnitude))
    throw Error(name_ + ": cell size " + number(cell_size) + " is not a positive number up to " +
                number(kMaxTerrainMagnitude) + " (a larger one would overflow the path costs)");
  if (!(max_slope_deg >= 0 && max_slope_deg <= 90))
    throw Error(name_ + ": maximum slope " + number(max_slope_deg) + " deg is outside [0, 90]");
  for (std::size_t i = 0; i < heights_.size(); ++i)
    if (std::abs(heights_[i]) > kMaxTerrainMagnitude)
      throw Error(name_ + ": the height " + number(heights_[i]) + " of cell (" + std::to_string(i % width) + "," +
                  std::to_string(i / width) + ") is beyond +-" + number(kMaxTerrainMagnitude) +
                  " (larger heights would overflow the path costs)");
  slopes_.resize(cells);
  reason_.resize(cells);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const Cell c{x, y};
      if (!has_data(c)) {
        slopes_[index(c)] = std::numeric_limits<double>::quiet_NaN();
        reason_[index(c)] = Blocked::no_data;
        continue;
      }
      slopes_[index(c)] = std::atan(std::hypot(gradient(c, 1, 0), gradient(c, 0, 1))) * kDegreesPerRadian;
      reason_[index(c)] = slopes_[index(c)] > max_slope_deg ? Blocked::too_steep : Blocked::no;
    }
}

bool TerrainMap::has_data(Cell c) const { return contains(c) && !std::isnan(heights_[index(c)]); }

double TerrainMap::elevation(Cell c) const {
  return contains(c) ? heights_[index(c)] : std::numeric_limits<double>::quiet_NaN();
}

double TerrainMap::slope_deg(Cell c) const {
  return contains(c) ? slopes_[index(c)] : std::numeric_limits<double>::quiet_NaN();
}

double TerrainMap::gradient(Cell c, int dx, int dy) const {
  const Cell before{c.x - dx, c.y - dy};
  const Cell after{c.x + dx, c.y + dy};
  const bool has_before = has_data(before), has_after = has_data(after);
  if (has_before && has_after) return (elevation(after) - elevation(before)) / (2 * cell_size_);
  if (has_after) return (elevation(after) - elevation(c)) / cell_size_;
  if (has_before) return (elevation(c) - elevation(before)) / cell_size_;
  return 0.0;
}

Eigen::Vector3d TerrainMap::position(Cell c) const { return {c.x * cell_size_, c.y * cell_size_, elevation(c)}; }

bool TerrainMap::step_allowed(Cell from, Cell to) const {
  if (!has_data(from) || !has_data(to)) return false;
  const double run = cell_size_ * std::hypot(double(to.x - from.x), double(to.y - from.y));
  return slope_degrees(elevation(to) - elevation(from), run) <= max_slope_deg_;
}

std::string TerrainMap::blocked_reason(Cell c) const {
  if (!contains(c)) return "outside the map";
  switch (reason_[index(c)]) {
    case Blocked::no:
      return "";
    case Blocked::no_data:
      return "NODATA";
    case Blocked::too_steep:
      break;
  }
  char text[96];
  std::snprintf(text, sizeof text, "too steep: slope %.1f deg > max %g deg", slope_deg(c), max_slope_deg_);
  return text;
}

}  // namespace aco
