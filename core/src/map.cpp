#include "aco/map.hpp"

#include "aco/error.hpp"

namespace aco {

Error::~Error() = default;
OutOfMemoryError::~OutOfMemoryError() = default;
PluginFault::~PluginFault() = default;
Map::~Map() = default;

std::string to_string(Cell c) {
  std::string text = "(";
  text.append(std::to_string(c.x)).append(",").append(std::to_string(c.y));
  if (c.z != 0) text.append(",").append(std::to_string(c.z));
  return text.append(")");
}

std::string Map::describe(Cell c) const {
  std::string text = to_string(c);
  if (volumetric() && c.z == 0) text.insert(text.size() - 1, ",0");
  return text;
}

Eigen::Vector3d Map::position(Cell c) const { return {double(c.x), double(c.y), double(c.z)}; }

bool Map::step_allowed(Cell, Cell) const { return true; }

std::string Map::blocked_reason(Cell c) const {
  if (!contains(c)) return "outside the map";
  return passable(c) ? "" : "an obstacle";
}

OccupancyGrid::OccupancyGrid(int width, int height, std::string name)
    : width_(width), height_(height), name_(std::move(name)) {
  if (width <= 0 || height <= 0)
    throw Error(name_ + ": map size " + std::to_string(width) + "x" + std::to_string(height) + " is empty");
  blocked_.assign(static_cast<std::size_t>(width) * height, 0);
}

}  // namespace aco
