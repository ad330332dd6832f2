// Scenario files (YAML): the run's keys, the robot, the simulation settings, the obstacles the
// map does not show.
#include <yaml-cpp/yaml.h>

#include "aco/planning/presets.hpp"
#include "aco/error.hpp"
#include "aco/settings_table.hpp"
#include "aco/planning/yaml_keys.hpp"
#include "aco/simulation/simulation.hpp"

namespace aco::simulation {
namespace {

using aco::yaml::fail;
using aco::yaml::scalar;

const aco::SettingsTable<RobotSettings>& robot_table() {
  using R = RobotSettings;
  static const aco::SettingsTable<R> table({
      aco::field("radius", &R::radius, "(0:100]", "the robot is a disc of this radius (map units: cells)"),
      aco::field("max-speed", &R::max_speed, "(0:100]", "top speed v_max (paper 003: 1.5 m/s)"),
      aco::field("max-yaw-rate", &R::max_yaw_rate, "(0:3600]", "top turn rate in degrees/s (paper 003: 20)"),
      aco::field("max-accel", &R::max_accel, "(0:1000]", "acceleration and braking limit (paper 003: 0.2 m/s^2)"),
      aco::field("max-yaw-accel", &R::max_yaw_accel, "(0:36000]",
                 "turn-rate change limit in degrees/s^2 (paper 003: 50)"),
      aco::field("min-speed", &R::min_speed, "-100:0",
                 "slowest forward speed; below 0 the robot may back up (not in the paper, whose V_s starts at v_min)"),
  });
  return table;
}

const aco::SettingsTable<SimulationSettings>& simulation_table() {
  using S = SimulationSettings;
  static const aco::SettingsTable<S> table({
      aco::field("period", &S::period, "(0:10]", "control period in seconds: each command is held this long"),
      aco::field("sensor-range", &S::sensor_range, "(0:1000]", "obstacles within this distance of the robot are seen"),
      aco::field("time-limit", &S::time_limit, "(0:1e6]", "seconds before the run counts as a timeout"),
      aco::field("goal-tolerance", &S::goal_tolerance, "(0:100]", "the goal is reached within this distance"),
      aco::field("waypoint-tolerance", &S::waypoint_tolerance, "(0:100]",
                 "an intermediate goal is passed within this distance"),
      aco::field("stall-time", &S::stall_time, "(0:1e6]", "seconds without progress before the robot replans"),
      aco::field("stall-distance", &S::stall_distance, "(0:100]",
                 "progress: the distance to the intermediate goal shrinking by this much"),
      aco::field("max-replans", &S::max_replans, "0:1000", "replans before the run counts as stuck"),
  });
  return table;
}

// A mapping of settings read through its table; errors name the file and line of the key.
template <class Settings>
Settings read_settings(const std::filesystem::path& file, const YAML::Node& node,
                       const aco::SettingsTable<Settings>& table, const std::string& section) {
  if (!node) return Settings{};
  if (!node.IsMap()) fail(file, node, "'" + section + "' must be a mapping of keys to values");
  std::map<std::string, std::string> given, origins;
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();
    given[key] = scalar(file, entry.second, section + "." + key);
    origins[section + "." + key] = aco::yaml::where(file, entry.first);
  }
  try {
    return table.read(aco::resolve(table.parameters(), given, section + "."));
  } catch (const aco::KeyError& e) {
    const auto it = origins.find(e.key());
    throw aco::Error((it != origins.end() ? it->second : aco::yaml::where(file, node)) + ": " + e.what());
  }
}

Eigen::Vector2d point(const std::filesystem::path& file, const YAML::Node& node, const std::string& key) {
  if (!node || !node.IsSequence() || node.size() != 2)
    fail(file, node ? node : YAML::Node(), "'" + key + "' must be a point [x, y]");
  try {
    return {node[0].as<double>(), node[1].as<double>()};
  } catch (const YAML::Exception&) {
    fail(file, node, "'" + key + "' must be a point [x, y] of numbers");
  }
}

double number(const std::filesystem::path& file, const YAML::Node& node, const std::string& key, double low) {
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    fail(file, node, "'" + key + "' must be a number");
  }
  if (!(value > low) || !std::isfinite(value))
    fail(file, node, "'" + key + "' must be a number above " + aco::to_string(aco::ParamValue(low)));
  return value;
}

MovingObstacle read_moving(const std::filesystem::path& file, const YAML::Node& node) {
  aco::yaml::only_keys(file, node, {"position", "velocity", "route", "speed", "radius"}, "a moving obstacle");
  MovingObstacle m;
  if (node["radius"]) m.radius = number(file, node["radius"], "radius", 0.0);
  if (node["route"]) {
    if (node["position"] || node["velocity"])
      fail(file, node, "a moving obstacle has either a route and a speed, or a position and a velocity");
    if (!node["route"].IsSequence() || node["route"].size() < 2)
      fail(file, node["route"], "'route' must list at least two points");
    for (const auto& p : node["route"]) m.route.push_back(point(file, p, "route"));
    if (!node["speed"]) fail(file, node, "a moving obstacle with a route needs a 'speed'");
    m.speed = number(file, node["speed"], "speed", 0.0);
  } else {
    m.route.push_back(point(file, node["position"], "position"));
    if (node["velocity"]) m.velocity = point(file, node["velocity"], "velocity");
  }
  return m;
}

// The run of the keys; an error names the key where it was written. A key the caller changed
// (`changes`) is named as the caller writes keys, the scenario's own as YAML does.
aco::RunSpec resolve(const aco::KeyedValues& keys, aco::PluginRegistry& registry, const aco::KeyedValues& changes = {},
                     const aco::KeySpelling& spelling = {}) {
  try {
    return aco::resolve_run(keys.keys, registry);
  } catch (const aco::KeyError& e) {
    const std::string origin = keys.origin(e.key());
    if (!changes.keys.count(e.key())) throw aco::Error(origin + e.what());
    try {
      aco::resolve_run(keys.keys, registry, spelling);  // the same error, in the caller's spelling
    } catch (const aco::KeyError& spelled) {
      throw aco::Error(origin + spelled.what());
    }
    throw;
  }
}

// Why the control period does not fit the local planner's horizon, or "".
std::string period_error(const Scenario& s) {
  const aco::ParameterValues& local = s.run.pipeline.at("local").parameters;
  if (!local.contains("horizon") || s.simulation.period <= local.real("horizon")) return "";
  return "the control period " + aco::to_string(aco::ParamValue(s.simulation.period)) +
         " s is longer than the local planner's horizon " + aco::to_string(aco::ParamValue(local.real("horizon"))) +
         " s";
}

}  // namespace

Scenario with_run_keys(const Scenario& scenario, const aco::KeyedValues& changes, aco::PluginRegistry& registry,
                       const aco::KeySpelling& spelling) {
  for (const char* key : {"map", "scen", "scen-index", "start", "goal", "seed"})
    if (changes.keys.count(key))
      throw aco::Error(changes.origin(key) + "'" + spelling(key) + "' is the scenario's, not a run key to change");
  Scenario s = scenario;
  s.keys = aco::overlay(scenario.keys, changes);
  s.run = resolve(s.keys, registry, changes, spelling);
  if (const std::string error = period_error(s); !error.empty())
    throw aco::Error(scenario.file.string() + ": " + error);
  return s;
}

Scenario load_scenario(const std::filesystem::path& file, aco::PluginRegistry& registry) {
  const YAML::Node doc = aco::yaml::load_file(file, "scenario");
  if (!doc.IsMap()) throw aco::Error(file.string() + ": a scenario file is a YAML mapping (run, robot, ...)");
  aco::yaml::only_keys(file, doc, {"run", "robot", "simulation", "unknown", "moving"}, "the scenario");
  if (!doc["run"]) fail(file, doc, "the scenario needs 'run' (map, start, goal and the planner's keys)");
  Scenario s;
  s.file = file;

  const YAML::Node run = doc["run"];
  aco::KeyedValues keys = aco::yaml::read_run_keys(file, run, {"start", "goal"});
  // Naming no pipeline runs the recommended one, as acoplan does.
  // Without its smoother: robust's taut path grazes obstacle corners, which a robot with a body cannot
  // follow; the local planner tracks the grid path (a scenario may name a smoother).
  if (!aco::yaml::names_pipeline(run)) {
    aco::KeyedValues recommended = aco::PipelineSource::choose("", "", aco::MapKind::grid).keys();  // a robot's floor
    aco::drop_slot(recommended.keys, "smoother");
    keys = aco::overlay(recommended, keys);
  }
  for (const char* end : {"start", "goal"}) {
    if (!run[end]) fail(file, run, "'run' needs '" + std::string(end) + "' [x, y]");
    const aco::Cell c = aco::yaml::cell(file, run[end], end);
    keys.keys[end] = std::to_string(c.x) + "," + std::to_string(c.y);
    keys.origins[end] = aco::yaml::where(file, run[end]);
  }
  if (!keys.keys.count("map")) fail(file, run, "'run' needs 'map'");
  for (const char* key : {"scen", "scen-index", "seed"})
    if (keys.keys.count(key)) throw aco::Error(keys.origin(key) + "'" + key + "' is not a scenario key");
  if (const std::filesystem::path map = keys.keys["map"]; map.is_relative())
    keys.keys["map"] = (file.parent_path() / map).lexically_normal().string();
  s.keys = keys;
  s.run = resolve(keys, registry);

  s.robot = read_settings(file, doc["robot"], robot_table(), "robot");
  s.simulation = read_settings(file, doc["simulation"], simulation_table(), "simulation");
  if (const std::string error = period_error(s); !error.empty())
    fail(file, doc["simulation"] ? doc["simulation"] : doc, error);

  const aco::LoadedProblem problem = aco::load_problem(s.run.problem, &registry);
  const auto* grid = dynamic_cast<const aco::OccupancyGrid*>(problem.map.get());
  if (!grid) throw aco::Error(problem.map->name() + ": acosim needs a 2D occupancy grid map, not a terrain");
  s.map = std::make_shared<const aco::OccupancyGrid>(*grid);
  s.start = problem.start;
  s.goal = problem.goal;

  // The obstacles the map does not show; none may touch the robot where it starts.
  const Eigen::Vector2d start(s.start.x, s.start.y);
  if (const YAML::Node unknown = doc["unknown"]) {
    if (!unknown.IsSequence()) fail(file, unknown, "'unknown' must be a list of cells [x, y]");
    for (const auto& entry : unknown) {
      const aco::Cell c = aco::yaml::cell(file, entry, "unknown");
      if (!s.map->contains(c)) fail(file, entry, "unknown obstacle " + aco::to_string(c) + " is outside the map");
      if (aco::distance_to_square(start, {c.x, c.y}, 1.0) < s.robot.radius)
        fail(file, entry,
             "unknown obstacle " + aco::to_string(c) + " overlaps the robot at the start " + aco::to_string(s.start));
      if (c == s.goal) fail(file, entry, "unknown obstacle " + aco::to_string(c) + " is on the goal");
      s.unknown.push_back(c);
    }
  }
  if (const YAML::Node moving = doc["moving"]) {
    if (!moving.IsSequence()) fail(file, moving, "'moving' must be a list of obstacles");
    for (const auto& entry : moving) {
      s.moving.push_back(read_moving(file, entry));
      if ((s.moving.back().position(0.0) - start).norm() < s.moving.back().radius + s.robot.radius)
        fail(file, entry, "the moving obstacle overlaps the robot at the start " + aco::to_string(s.start));
    }
  }
  return s;
}

}  // namespace aco::simulation
