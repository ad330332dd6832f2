#pragma once
// Terrain maps (paper 000): a grid of heights, where a step costs its 3D length and a slope
// limit can forbid steps and cells.
//
// Planning frame: x = column * cell size, y = row from the top * cell size, z = height, all in
// the units of the file (metres for most DEMs). y grows southwards, like the rows of the file
// and of every other map here. The georeference (ESRI xllcorner/yllcorner) is recorded but not
// used for planning: paths are reported in this local frame.
#include <Eigen/Core>
#include <boost/config.hpp>
#include <string>
#include <vector>

#include "aco/map.hpp"

namespace aco {

struct TerrainOptions {
  double max_slope_deg = 90;  // steepest slope a step or a cell may have; 90 = no limit
  double height_scale = 1;  // PGM height images: height = grey value * height_scale
  double cell_size = 1;  // PGM height images: horizontal size of a cell (.asc files carry their own)
};

// The largest height (in magnitude) and cell size a terrain map takes: a step's 3D length, the sum
// of a path's and every plugin's arithmetic on them stay finite far beyond any real terrain's.
inline constexpr double kMaxTerrainMagnitude = 1e12;

class BOOST_SYMBOL_VISIBLE TerrainMap final : public Map {
 public:
  // `heights` row-major, row 0 at the top, NaN where there is no data. Throws an Error naming
  // `name` for a size mismatch, a cell size not in (0, kMaxTerrainMagnitude], a height beyond
  // +-kMaxTerrainMagnitude (the cell named) or a slope limit outside [0, 90].
  TerrainMap(int width, int height, double cell_size, std::vector<double> heights, double max_slope_deg,
             std::string name);

  int width() const override { return width_; }
  int height() const override { return height_; }
  // Inside the map, with data, and no steeper than the limit.
  bool passable(Cell c) const override { return contains(c) && reason_[index(c)] == Blocked::no; }
  // (x * cell size, y * cell size, height); z is NaN on a NODATA cell (never passable).
  Eigen::Vector3d position(Cell c) const override;
  // Both cells have data and the step's slope atan(|dz| / horizontal distance) is within the
  // limit. Symmetric, so every edge of the graph stays reversible.
  bool step_allowed(Cell from, Cell to) const override;
  // "", "outside the map", "NODATA" or "too steep: slope 41.2 deg > max 30 deg".
  std::string blocked_reason(Cell c) const override;
  std::string name() const override { return name_; }

  bool has_data(Cell c) const;  // inside the map and not NODATA
  double elevation(Cell c) const;  // NaN where there is no data
  double cell_size() const { return cell_size_; }
  double max_slope_deg() const { return max_slope_deg_; }
  // The cell's own slope in degrees (NaN without data): atan of the gradient's magnitude, the
  // gradient by central differences, one-sided at the map's edge or next to NODATA, zero along
  // an axis with no neighbour data at all.
  double slope_deg(Cell c) const;

  // World position of the lower-left corner of the lower-left cell (ESRI xllcorner, yllcorner).
  const Eigen::Vector2d& lower_left() const { return lower_left_; }
  void set_lower_left(const Eigen::Vector2d& corner) { lower_left_ = corner; }

 private:
  enum class Blocked : unsigned char { no, no_data, too_steep };
  std::size_t index(Cell c) const { return static_cast<std::size_t>(c.y) * width_ + c.x; }
  double gradient(Cell c, int dx, int dy) const;  // dz per unit length along (dx, dy), an axis

  int width_;
  int height_;
  double cell_size_;
  double max_slope_deg_;
  std::string name_;
  std::vector<double> heights_;
  std::vector<double> slopes_;
  std::vector<Blocked> reason_;
  Eigen::Vector2d lower_left_{0, 0};
};

}  // namespace aco
