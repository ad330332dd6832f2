#pragma once
// Maps are grids of cells; x = column, y = row from the top, both 0-based (Moving AI convention).
// A voxel world (aco/voxel.hpp) adds z, the layer from the ground up; on every other map z is 0.
#include <Eigen/Core>
#include <boost/config.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace aco {

struct Cell {
  int x = 0;
  int y = 0;
  int z = 0;
  friend bool operator==(const Cell&, const Cell&) = default;
};

std::string to_string(Cell c);  // "(x,y)", or "(x,y,z)" where z is not 0

// A grid the planner can move on. The occupancy grid is the 2D case; a terrain map
// (heights, slope limits; aco/terrain.hpp) overrides position() and step_allowed().
class BOOST_SYMBOL_VISIBLE Map {
 public:
  virtual ~Map();
  virtual int width() const = 0;
  virtual int height() const = 0;
  // Layers: 1 for a grid or a terrain, more for a voxel world.
  virtual int depth() const { return 1; }
  // A voxel world: moves go up and down too (6-, 18- and 26-neighbourhoods), and cells are named
  // x,y,z. False for grids and terrains, whose cells all have z = 0.
  virtual bool volumetric() const { return false; }
  virtual bool passable(Cell c) const = 0;
  // Position of a cell's centre in planning units; z is the cell's layer (0 on flat maps).
  virtual Eigen::Vector3d position(Cell c) const;
  // Extra per-step rule beyond passable cells (for example a slope limit).
  virtual bool step_allowed(Cell from, Cell to) const;
  // Human-readable origin of the map, e.g. the file it came from.
  virtual std::string name() const = 0;
  // Why a cell is not passable, for messages ("start (3,4) is blocked: NODATA"); "" if it is.
  // The default says "outside the map" or "an obstacle".
  virtual std::string blocked_reason(Cell c) const;

  bool contains(Cell c) const {
    return c.x >= 0 && c.y >= 0 && c.z >= 0 && c.x < width() && c.y < height() && c.z < depth();
  }
  // to_string(c), with z on a volumetric map even where it is 0.
  std::string describe(Cell c) const;
};

// World placement of a grid, as given by ROS map_server YAML; identity for other formats.
struct GridGeometry {
  double resolution = 1.0;  // metres per cell
  Eigen::Vector3d origin{0, 0, 0};  // world pose of the lower-left cell: x, y, yaw
};

class BOOST_SYMBOL_VISIBLE OccupancyGrid final : public Map {
 public:
  OccupancyGrid(int width, int height, std::string name);
  int width() const override { return width_; }
  int height() const override { return height_; }
  bool passable(Cell c) const override { return contains(c) && !blocked_[index(c)]; }
  std::string name() const override { return name_; }

  void set_blocked(Cell c, bool blocked) { blocked_[index(c)] = blocked ? 1 : 0; }
  bool blocked(Cell c) const { return blocked_[index(c)] != 0; }
  const GridGeometry& geometry() const { return geometry_; }
  void set_geometry(const GridGeometry& g) { geometry_ = g; }

 private:
  std::size_t index(Cell c) const { return static_cast<std::size_t>(c.y) * width_ + c.x; }
  int width_;
  int height_;
  std::string name_;
  std::vector<std::uint8_t> blocked_;
  GridGeometry geometry_;
};

// Calls f(map) with the OccupancyGrid itself where the map is one, else with the Map: a loop over
// every cell of a large map then makes no virtual call per cell on a plain grid (final, so its
// passable() inlines), which keeps Map's position() and step rule.
template <class F>
void with_concrete_map(const Map& map, F&& f) {
  if (const auto* grid = dynamic_cast<const OccupancyGrid*>(&map))
    f(*grid);
  else
    f(map);
}

}  // namespace aco
