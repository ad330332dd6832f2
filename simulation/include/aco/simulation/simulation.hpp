#pragma once
// acosim: a robot follows the colony's global path with a local planner (paper 003, section 4)
// in a world that also holds obstacles the map does not show, some of them moving. The global
// path is planned on the known map with the run's whole configuration (aco::RunSpec: any
// planner, pipeline or preset); its turning points are the local planner's intermediate goals.
// When the robot stops making progress, it adds the unknown cells it has sensed to its map and
// replans from where it stands.
#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "aco/path.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/robot.hpp"
#include "aco/planning/run_spec.hpp"

namespace aco::simulation {

// The robot's limits as a scenario writes them: turn limits in degrees.
struct RobotSettings {
  double radius = 0.3;
  double max_speed = 1.5;
  double max_yaw_rate = 20.0;  // degrees/s
  double max_accel = 0.2;
  double max_yaw_accel = 50.0;  // degrees/s^2
  double min_speed = 0.0;  // below 0: may back up

  aco::RobotLimits limits() const {
    return {radius, max_speed, max_yaw_rate * aco::kDegree, max_accel, max_yaw_accel * aco::kDegree, min_speed};
  }
};

struct SimulationSettings {
  double period = 0.1;  // control period, s
  double sensor_range = 7.0;  // cells (and moving discs) within this distance are seen
  double time_limit = 300.0;  // s
  double goal_tolerance = 0.3;  // reached when the robot's centre is this close to the goal
  double waypoint_tolerance = 0.6;  // an intermediate goal this close is passed
  double stall_time = 8.0;  // no progress for this long: replan
  double stall_distance = 0.3;  // progress = the distance to the intermediate goal shrinking by this much
  int max_replans = 10;
};

// A moving obstacle: a disc driving round a closed route at a constant speed, or, with one
// point, from there with a constant velocity.
struct MovingObstacle {
  std::vector<Eigen::Vector2d> route;
  double speed = 0.0;
  Eigen::Vector2d velocity{0.0, 0.0};
  double radius = 0.3;

  Eigen::Vector2d position(double t) const;
  Eigen::Vector2d velocity_at(double t) const;
};

struct Scenario {
  std::filesystem::path file;
  aco::KeyedValues keys;  // the run keys as written (the map's path made absolute), with their origins
  aco::RunSpec run;  // map, start, goal, graph, planner, pipeline (its local slot drives)
  // run.problem loaded once: the known map (shared by copies: batch variations) and the cells.
  std::shared_ptr<const aco::OccupancyGrid> map;
  aco::Cell start;
  aco::Cell goal;
  RobotSettings robot;
  SimulationSettings simulation;
  std::vector<aco::Cell> unknown;  // blocked in the world, free on the map
  std::vector<MovingObstacle> moving;
};

// Reads a scenario file (YAML, see README.md). Errors name the file, the line and the key.
Scenario load_scenario(const std::filesystem::path& file, aco::PluginRegistry& registry);

// The scenario driven with other run keys: `changes` over the file's (aco::overlay: another
// plugin in a slot drops the file's parameters of that slot). The problem keys (map, start,
// goal) stay the scenario's. Errors name the key and where it was written, a changed key as
// `spelling` writes it (Python's keywords), the file's as YAML does.
Scenario with_run_keys(const Scenario& scenario, const aco::KeyedValues& changes, aco::PluginRegistry& registry,
                       const aco::KeySpelling& spelling = {});

struct Frame {
  double t = 0.0;
  aco::RobotState robot;
  int goal_index = 0;  // into the current plan's intermediate goals
  int plan = 0;  // which plan the robot follows
  std::vector<Eigen::Vector2d> moving;
};

// Every outcome a simulation can have, and its text, in the enum's order (the results database
// keeps it as an index into kOutcomes).
enum class Outcome { reached, collision, timeout, stuck, no_path };
inline constexpr const char* kOutcomes[] = {"reached", "collision", "timeout", "stuck", "no path"};
static_assert(std::size(kOutcomes) == static_cast<std::size_t>(Outcome::no_path) + 1);

constexpr const char* to_string(Outcome outcome) { return kOutcomes[static_cast<int>(outcome)]; }

struct SimulationResult {
  bool reached = false;
  // One of kOutcomes. In a batch of worker processes (batch.hpp), a variation whose worker
  // crashed or ran out of memory has that failure's text (aco/process/failure_kind.hpp) instead.
  std::string outcome;
  std::string reason;
  double time = 0.0;
  double distance = 0.0;
  double min_clearance = std::numeric_limits<double>::infinity();
  int collisions = 0;
  int replans = 0;
  int steps = 0;
  std::vector<Frame> frames;  // the start, then one per control step
  std::vector<std::vector<Eigen::Vector2d>> plans;  // each global plan's intermediate goals, start first
  std::vector<aco::Cell> sensed;  // unknown cells the robot has seen
};

// Runs the scenario to the goal, a collision, the time limit, or a plan that cannot be made.
// Deterministic: the same scenario gives the same result.
SimulationResult simulate(const Scenario& scenario, aco::PluginRegistry& registry);

// Outputs.
// The summary as JSON, with the plugins' provenance (aco::plugins_json).
std::string summary_json(const Scenario& scenario, const SimulationResult& result, const aco::PluginRegistry& registry);
std::string trajectory_csv(const SimulationResult& result);
std::string render_svg(const Scenario& scenario, const SimulationResult& result);
// A self-contained page that plays the run (play/pause, time slider); #final shows the last frame.
std::string render_html(const Scenario& scenario, const SimulationResult& result);

}  // namespace aco::simulation
