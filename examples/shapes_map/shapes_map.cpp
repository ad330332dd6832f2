// map/shapes: a map given as obstacles in metres, rectangles and circles, rasterised at
// map.resolution metres per cell: a cell is blocked when its centre lies in an obstacle.
//
//   # a room of 10 x 8 metres (x to the right, y down from the top-left corner)
//   size 10 8
//   rect 2 0 1 5        # x y width height
//   circle 7 5 1.5      # centre x, centre y, radius
//
// '#' starts a comment; blank lines are skipped; every other line is one of the three.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double resolution = 0.5;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("resolution", &Parameters::resolution, "[0.01:10]", "metres per cell (--map.resolution)"),
});

struct Shape {
  bool circle = false;
  double x = 0, y = 0, width = 0, height = 0, radius = 0;
  bool contains(double px, double py) const {
    if (circle) return std::hypot(px - x, py - y) <= radius;
    return px >= x && px <= x + width && py >= y && py <= y + height;
  }
};

class ShapesReader final : public aco::MapReader {
 public:
  explicit ShapesReader(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  std::vector<std::string> extensions() const override { return {".shapes"}; }

  std::string sample() const override { return "size 4 3\nrect 1 0 1 2\ncircle 3 2.5 0.4\n"; }

  std::unique_ptr<aco::Map> read(const std::filesystem::path& file, const aco::TerrainOptions&) const override {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw aco::Error(file.string() + ": no such shapes file");
    std::ifstream in(file);
    if (!in) throw aco::Error(file.string() + ": cannot open the shapes file");
    double width = 0, height = 0;
    std::vector<Shape> shapes;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      const auto fail = [&](const std::string& what) -> aco::Error {
        return aco::Error(file.string() + ":" + std::to_string(number) + ": " + what);
      };
      std::istringstream words(line.substr(0, line.find('#')));
      std::string kind;
      if (!(words >> kind)) continue;
      std::vector<double> numbers;
      for (double v; words >> v;) numbers.push_back(v);
      if (!words.eof()) throw fail("'" + line + "' holds a word that is not a number");
      const auto expect = [&](std::size_t count, const char* form) {
        if (numbers.size() != count) throw fail("'" + kind + "' takes " + form);
        for (double v : numbers)
          if (!std::isfinite(v) || v < 0) throw fail("'" + kind + "': every number must be finite and >= 0");
      };
      if (kind == "size") {
        expect(2, "WIDTH HEIGHT in metres");
        width = numbers[0], height = numbers[1];
        if (width <= 0 || height <= 0) throw fail("the size must be positive");
      } else if (kind == "rect") {
        expect(4, "X Y WIDTH HEIGHT in metres");
        shapes.push_back({false, numbers[0], numbers[1], numbers[2], numbers[3], 0});
      } else if (kind == "circle") {
        expect(3, "X Y RADIUS in metres");
        shapes.push_back({true, numbers[0], numbers[1], 0, 0, numbers[2]});
      } else {
        throw fail("unknown shape '" + kind + "' (expected size, rect or circle)");
      }
    }
    if (width <= 0) throw aco::Error(file.string() + ": no 'size WIDTH HEIGHT' line");
    const int columns = static_cast<int>(std::ceil(width / p_.resolution - 1e-9));
    const int rows = static_cast<int>(std::ceil(height / p_.resolution - 1e-9));
    // Before allocating: a fine resolution over a large area may need more than the host allows.
    aco::check_planning_memory(columns, rows, aco::Neighbourhood::four, file.string());
    auto grid = std::make_unique<aco::OccupancyGrid>(columns, rows, file.string());
    grid->set_geometry({p_.resolution, {0, 0, 0}});
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < columns; ++x) {
        const double cx = (x + 0.5) * p_.resolution, cy = (y + 0.5) * p_.resolution;
        for (const Shape& s : shapes)
          if (s.contains(cx, cy)) grid->set_blocked({x, y}, true);
      }
    return grid;
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(map, shapes, ShapesReader, "0.1",
           "obstacles as rectangles and circles in metres, rasterised at map.resolution", kParams)
