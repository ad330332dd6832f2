#pragma once
// What the node's two halves share: plain data, and no header of either. The ROS half
// (ros_planner.cpp) is C++17, as ROS 1's message headers are (they use allocator<void>::rebind,
// which C++20 removed); the planning half (planner_core.cpp) is C++20, as aco's headers are.
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace aco_ros {

// A nav_msgs/OccupancyGrid's content: occupancy 0-100 or -1 (unknown), rows from the origin up.
struct GridMap {
  std::string frame;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  double resolution = 0.0;  // metres per cell
  double origin_x = 0.0;  // the lower-left corner of cell (0, 0), in the frame
  double origin_y = 0.0;
  std::vector<std::int8_t> occupancy;
};

// The node's parameters at one request (README.md).
struct Settings {
  int occupied_threshold = 65;  // map_server's occupied_thresh of 0.65
  bool allow_unknown = false;
  bool publish_pheromone = false;
  int threads = 0;  // 0: all cores
  std::string preset;
  std::string config;
  std::map<std::string, std::string> keys;  // run keys, as acoplan's (without its dashes)
};

struct Point {
  double x = 0.0;
  double y = 0.0;
};

struct Plan {
  std::vector<Point> points;  // in the map's frame, from the start cell's centre to the goal cell's
  double length = 0.0;  // metres
  double time_ms = 0.0;  // the planner's
  std::vector<std::int8_t> pheromone;  // with Settings::publish_pheromone: per cell 0-100, as GridMap
};

// Plans on a map; an impossible request throws std::runtime_error naming the reason, its keys
// named as ROS parameters ("~update/rho").
class Planner {
 public:
  Planner();
  ~Planner();
  Plan plan(const GridMap& map, Point start, Point goal, double tolerance, const Settings& settings);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A private parameter's name as a run key: "update/rho" -> "update.rho", "time_limit" ->
// "time-limit" (ROS names have neither dots nor dashes; a slot's parameters keep their
// underscores: "update/p_best" -> "update.p_best").
std::string run_key(const std::string& name);

}  // namespace aco_ros
