#pragma once
// Map and scenario loaders. Every malformed input is an Error naming the file, the line and
// what was expected; nothing is guessed.
#include <filesystem>
#include <istream>
#include <memory>
#include <string>
#include <vector>

#include "aco/map.hpp"

namespace aco {

// Moving AI .map: "type octile", "height H", "width W", "map", then H rows of W characters.
OccupancyGrid read_movingai_map(std::istream& in, const std::string& name);
// 0/1 matrix, one row per line, whitespace separated, row 0 at the top (classic20 maps).
OccupancyGrid read_matrix_map(std::istream& in, const std::string& name);
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

// By extension: .map (Moving AI), .yaml/.yml (ROS), anything else the 0/1 matrix.
std::unique_ptr<Map> load_map(const std::filesystem::path& file);

struct Scenario {
  int bucket = 0;
  std::string map_path;  // as written in the file
  int width = 0;
  int height = 0;
  Cell start;
  Cell goal;
  double optimal_length = 0.0;  // octile, no corner cutting
};

// Moving AI .scen: "version 1" then tab-separated lines of nine fields.
std::vector<Scenario> read_scenarios(std::istream& in, const std::string& name);
std::vector<Scenario> load_scenarios(const std::filesystem::path& file);
// The map a scenario file belongs to: "<dir>/arena.map" for "<dir>/arena.map.scen".
std::filesystem::path scenario_map_file(const std::filesystem::path& scen_file);

}  // namespace aco
