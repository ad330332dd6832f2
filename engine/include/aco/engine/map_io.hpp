#pragma once
// Map and scenario loaders. Every malformed input is an Error naming the file, the line and
// what was expected; nothing is guessed.
#include <filesystem>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "aco/map.hpp"
#include "aco/terrain.hpp"
#include "aco/voxel.hpp"

namespace aco {

// Moving AI .map: "type octile", "height H", "width W", "map", then H rows of W characters.
OccupancyGrid read_movingai_map(std::istream& in, const std::string& name);
// 0/1 matrix, one row per line, whitespace separated, row 0 at the top (classic20 maps).
OccupancyGrid read_matrix_map(std::istream& in, const std::string& name);
// The two from a file (named in messages as given).
OccupancyGrid load_movingai_map(const std::filesystem::path& file);
OccupancyGrid load_matrix_map(const std::filesystem::path& file);
// ROS map_server: YAML (image, resolution, origin, negate, occupied_thresh, free_thresh, mode)
// plus its PGM image. Unknown cells count as blocked.
OccupancyGrid load_ros_map(const std::filesystem::path& yaml_file);
// PGM (P2 or P5, maxval up to 65535) as row-major grey values, row 0 at the top.
struct GreyImage {
  int width = 0;
  int height = 0;
  int maxval = 0;
  std::vector<int> pixels;
};
GreyImage load_pgm(const std::filesystem::path& file);
GreyImage read_pgm(std::istream& in, const std::string& name);

// ESRI ASCII grid (.asc): header lines "KEY VALUE" in any order, keys case-insensitive: ncols,
// nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize, optionally NODATA_value
// (default -9999); then nrows * ncols heights, whitespace separated, the first row the
// northernmost (our row 0). NODATA cells are blocked. The file's cellsize is the cell size;
// options.height_scale and options.cell_size do not apply, options.max_slope_deg does.
TerrainMap read_esri_ascii(std::istream& in, const std::string& name, const TerrainOptions& options);
TerrainMap load_esri_ascii(const std::filesystem::path& file, const TerrainOptions& options);
// A PGM image as a height map: height = grey value * options.height_scale, cell size
// options.cell_size. Every pixel has data.
TerrainMap load_height_pgm(const std::filesystem::path& file, const TerrainOptions& options);
TerrainMap read_height_pgm(std::istream& in, const std::string& name, const TerrainOptions& options);

// Moving AI voxel world (.3dmap, Brewer and Sturtevant 2018): "voxel W H D", then one blocked
// voxel "x y z" a line, 0-based, in any order; unlisted voxels are free. data/maps/voxel/README.md
// gives the format's sources. A size whose planning would exceed the memory limit is refused
// before anything is allocated.
VoxelMap read_movingai_voxels(std::istream& in, const std::string& name);
VoxelMap load_movingai_voxels(const std::filesystem::path& file);
// The same format; blocked voxels in the order HOG2's writer uses (x, then y, then z), so the
// same world always gives the same bytes.
void write_movingai_voxels(const VoxelMap& map, std::ostream& out);

// By extension: .map (Moving AI), .3dmap (Moving AI voxels), .yaml/.yml (ROS), .asc (ESRI ASCII
// terrain), .pgm (height image terrain), anything else the 0/1 matrix. `terrain` applies to the two terrain formats
// only. The built-in formats only; hosts read maps with aco/engine/map_formats.hpp's load_map(), which also asks the
// map plugins.
std::unique_ptr<Map> load_map(const std::filesystem::path& file, const TerrainOptions& terrain = {});

struct Scenario {
  int bucket = 0;  // 0 in a .3dscen, which has none
  std::string map_path;  // as written in the file
  int width = 0;  // the map's size as the .scen states it; 0 in a .3dscen, which does not
  int height = 0;
  Cell start;  // z = 0 in a .scen
  Cell goal;
  // 2D: octile (1, sqrt 2), 8-neighbourhood, no corner cutting. Voxels: 1, sqrt 2, sqrt 3 for
  // steps changing one, two or three coordinates, 26-neighbourhood, no corner cutting (every
  // voxel of the box a step spans free).
  double optimal_length = 0.0;
  // .3dscen only: optimal_length over the 3D octile distance of start and goal (> 1 in Moving
  // AI's files, which leave out problems a straight line solves); 0 in a .scen.
  double ratio = 0.0;
  bool volumetric = false;  // read from a .3dscen: start and goal are voxels of a .3dmap
};

// Moving AI .scen: "version 1" then tab-separated lines of nine fields.
std::vector<Scenario> read_scenarios(std::istream& in, const std::string& name);
// A file ending in .3dscen is read by load_voxel_scenarios(), any other by read_scenarios().
std::vector<Scenario> load_scenarios(const std::filesystem::path& file);
// Moving AI .3dscen: "version 1", the map's file name, then lines of "sx sy sz gx gy gz
// optimal_length ratio", whitespace separated (the ratio may be missing: older files).
std::vector<Scenario> read_voxel_scenarios(std::istream& in, const std::string& name);
std::vector<Scenario> load_voxel_scenarios(const std::filesystem::path& file);
// The map a scenario file belongs to: "<dir>/arena.map" for "<dir>/arena.map.scen",
// "<dir>/Simple.3dmap" for "<dir>/Simple.3dmap.3dscen".
std::filesystem::path scenario_map_file(const std::filesystem::path& scen_file);

}  // namespace aco
