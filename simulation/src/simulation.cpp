#include "aco/simulation/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "aco/error.hpp"
#include "aco/plugin_error.hpp"
#include "aco/graph.hpp"
#include "aco/planning/planning.hpp"
#include "aco/engine/plugin_guard.hpp"

namespace aco::simulation {

Eigen::Vector2d MovingObstacle::position(double t) const {
  if (route.size() < 2) return route.front() + t * velocity;
  double perimeter = 0.0;
  for (std::size_t i = 0; i < route.size(); ++i) perimeter += (route[(i + 1) % route.size()] - route[i]).norm();
  double along = perimeter > 0.0 ? std::fmod(speed * t, perimeter) : 0.0;
  for (std::size_t i = 0;; ++i) {
    const Eigen::Vector2d &a = route[i % route.size()], &b = route[(i + 1) % route.size()];
    const double leg = (b - a).norm();
    if (along <= leg || i + 1 >= route.size()) return leg > 0.0 ? Eigen::Vector2d(a + (b - a) * (along / leg)) : a;
    along -= leg;
  }
}

Eigen::Vector2d MovingObstacle::velocity_at(double t) const {
  if (route.size() < 2) return velocity;
  const double dt = 1e-3;  // the route's direction where the disc is
  return (position(t + dt) - position(t)) / dt;
}

namespace {

Eigen::Vector2d centre(aco::Cell c) { return {double(c.x), double(c.y)}; }
// The cell whose square holds p.
aco::Cell cell_under(const Eigen::Vector2d& p) {
  return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
}

// The world as the simulator knows it: the truth (map plus unknown cells) and the robot's map.
class World {
 public:
  World(const aco::OccupancyGrid& map, const std::vector<aco::Cell>& unknown) : known_(map), truth_(map) {
    for (aco::Cell c : unknown) truth_.set_blocked(c, true);
  }

  const aco::OccupancyGrid& known() const { return known_; }
  // Blocked in the world: an obstacle, or outside the map.
  bool blocked(aco::Cell c) const { return !truth_.passable(c); }

  // The blocked cells whose centre is within `range` of p (cells outside the map included, so
  // the robot stays on it); unknown ones become sensed.
  std::vector<Eigen::Vector2d> sense(const Eigen::Vector2d& p, double range, std::vector<aco::Cell>& sensed) {
    std::vector<Eigen::Vector2d> cells;
    const int r = static_cast<int>(std::ceil(range));
    const aco::Cell at = cell_under(p);
    for (int y = at.y - r; y <= at.y + r; ++y)
      for (int x = at.x - r; x <= at.x + r; ++x) {
        const aco::Cell c{x, y};
        if (!blocked(c) || (centre(c) - p).norm() > range) continue;
        cells.push_back(centre(c));
        if (known_.passable(c)) {
          known_.set_blocked(c, true);  // the robot's map learns it; replans use it
          sensed.push_back(c);
        }
      }
    return cells;
  }

  // Distance from the disc (p, radius) to the nearest blocked cell, and which one.
  double clearance(const Eigen::Vector2d& p, double radius, aco::Cell& nearest) const {
    double best = std::numeric_limits<double>::infinity();
    const int r = static_cast<int>(std::ceil(radius)) + 1;
    const aco::Cell at = cell_under(p);
    for (int y = at.y - r; y <= at.y + r; ++y)
      for (int x = at.x - r; x <= at.x + r; ++x)
        if (blocked({x, y})) {
          const double d = aco::distance_to_square(p, centre({x, y}), 1.0) - radius;
          if (d < best) best = d, nearest = {x, y};
        }
    return best;
  }

 private:
  aco::OccupancyGrid known_;
  aco::OccupancyGrid truth_;
};

// The turning points of a path (the start dropped, the goal kept): where its direction changes.
std::vector<Eigen::Vector2d> turning_points(const aco::Waypoints& path) {
  std::vector<Eigen::Vector2d> points;
  for (std::size_t i = 1; i < path.size(); ++i) {
    if (i + 1 < path.size()) {
      const Eigen::Vector2d in = (path[i] - path[i - 1]).head<2>(), out = (path[i + 1] - path[i]).head<2>();
      if (std::abs(in.x() * out.y() - in.y() * out.x()) < 1e-9 && in.dot(out) > 0.0) continue;
    }
    points.push_back(path[i].head<2>());
  }
  return points;
}

// A command out of the window by more than rounding (or NaN) is the local planner's bug: clamped,
// it would hide it, or drive the robot by NaN into every output.
[[noreturn]] void reject_command(const aco::LocalPlanner& planner, const aco::VelocityCommand& c,
                                 const aco::DynamicWindow& window, int step, double t) {
  const auto number = [](double v) {
    std::ostringstream text;
    text << v;
    return text.str();
  };
  throw aco::InvalidValueError(
      aco::describe_plugin(planner, "local") + " returned the command v = " + number(c.v) + ", w = " + number(c.w) +
      " in command() at control step " + std::to_string(step) + " (0-based, t = " + number(t) +
      " s), outside the dynamic window v in [" + number(window.v_low) + ", " + number(window.v_high) + "], w in [" +
      number(window.w_low) + ", " + number(window.w_high) + "] (a command must be finite and inside it)");
}

}  // namespace

SimulationResult simulate(const Scenario& scenario, aco::PluginRegistry& registry) {
  const aco::RunSpec& run = scenario.run;
  const SimulationSettings& sim = scenario.simulation;
  const aco::RobotLimits limits = scenario.robot.limits();
  World world(*scenario.map, scenario.unknown);
  const aco::PipelinePlugins pipeline = aco::instantiate(registry, run.pipeline);
  // The simulation is the local planner's run; it sees the world through LocalView, not a graph.
  aco::Context local_run;
  local_run.seed = run.colony.seed;
  pipeline.local->begin_run(local_run);

  SimulationResult result;
  aco::RobotState robot;
  robot.x = scenario.start.x, robot.y = scenario.start.y;
  const Eigen::Vector2d goal = centre(scenario.goal);
  std::vector<Eigen::Vector2d> goals;  // the current plan's intermediate goals
  std::size_t next = 0;

  // Plans from the cell under the robot on the map as the robot knows it now.
  const auto replan = [&](aco::Cell from) {
    const aco::Graph graph = aco::build_graph(world.known(), run.graph);
    const aco::PlanOutcome outcome = aco::plan(registry, graph, graph.node(from), graph.node(scenario.goal), run);
    if (!outcome.solved()) {
      result.outcome = to_string(Outcome::no_path);
      result.reason = outcome.reason.empty() ? "the planner found no path" : outcome.reason;
      return false;
    }
    goals = turning_points(outcome.path);
    if (goals.empty()) goals.push_back(goal);  // planned from the goal's cell: drive to its centre
    next = 0;
    // The plan starts at the centre of the robot's cell, where the planned path starts: the
    // robot is led back onto it (a line from the robot's own position may graze a wall).
    std::vector<Eigen::Vector2d> plan{outcome.path.front().head<2>()};
    plan.insert(plan.end(), goals.begin(), goals.end());
    result.plans.push_back(plan);
    return true;
  };
  if (!replan(scenario.start)) return result;
  if (!goals.empty()) robot.heading = std::atan2(goals[0].y() - robot.y, goals[0].x() - robot.x);

  const auto moving_at = [&](double t) {
    std::vector<Eigen::Vector2d> at;
    for (const MovingObstacle& m : scenario.moving) at.push_back(m.position(t));
    return at;
  };
  result.frames.push_back({0.0, robot, 0, 0, moving_at(0.0)});
  std::vector<Eigen::Vector2d> path;
  double t = 0.0, best_to_goal = std::numeric_limits<double>::infinity(), last_progress = 0.0;
  while (true) {
    if ((robot.position() - goal).norm() <= sim.goal_tolerance) {
      result.reached = true;
      result.outcome = to_string(Outcome::reached);
      break;
    }
    if (t >= sim.time_limit - 1e-9) {
      result.outcome = to_string(Outcome::timeout);
      result.reason = "the goal was not reached within " + aco::to_string(aco::ParamValue(sim.time_limit)) + " s";
      break;
    }
    while (next + 1 < goals.size() && (robot.position() - goals[next]).norm() <= sim.waypoint_tolerance) {
      ++next;
      best_to_goal = std::numeric_limits<double>::infinity();
    }
    // Progress towards the intermediate goal; none for stall_time means the way is blocked.
    const double to_goal = (robot.position() - goals[next]).norm();
    if (to_goal < best_to_goal - sim.stall_distance || best_to_goal == std::numeric_limits<double>::infinity())
      best_to_goal = to_goal, last_progress = t;
    if (t - last_progress >= sim.stall_time) {
      if (result.replans >= sim.max_replans) {
        result.outcome = to_string(Outcome::stuck);
        result.reason = "no progress after " + std::to_string(result.replans) + " replans";
        break;
      }
      ++result.replans;
      if (!replan(cell_under(robot.position()))) break;
      best_to_goal = std::numeric_limits<double>::infinity(), last_progress = t;
    }

    std::vector<aco::MovingObstacle> seen;
    for (const MovingObstacle& m : scenario.moving) {
      const Eigen::Vector2d p = m.position(t);
      if ((p - robot.position()).norm() - m.radius <= sim.sensor_range) seen.push_back({p, m.velocity_at(t), m.radius});
    }
    const std::vector<Eigen::Vector2d> cells = world.sense(robot.position(), sim.sensor_range, result.sensed);
    // The rest of the plan, from the robot's foot on the leg it is on.
    const std::vector<Eigen::Vector2d>& plan = result.plans.back();  // the start, then goals
    const std::span<const Eigen::Vector2d> leg(plan.data() + next, 2);
    path.assign(1, aco::point_on_path(leg, aco::foot_on_path(leg, robot.position())));
    path.insert(path.end(), goals.begin() + static_cast<std::ptrdiff_t>(next), goals.end());
    aco::LocalView view{robot, limits, sim.period, goals[next], cells, 1.0, seen, path};
    const aco::DynamicWindow window = aco::dynamic_window(robot, limits, sim.period);
    const aco::VelocityCommand wanted = pipeline.local->command(view);
    if (!window.contains(wanted, aco::kWindowTolerance))
      reject_command(*pipeline.local, wanted, window, result.steps, t);
    const aco::VelocityCommand command = window.clamp(wanted);  // rounding's excess only
    const aco::RobotState moved = aco::move(robot, command, sim.period);
    result.distance += (moved.position() - robot.position()).norm();
    robot = moved;
    t += sim.period;
    ++result.steps;
    result.frames.push_back(
        {t, robot, static_cast<int>(next), static_cast<int>(result.plans.size()) - 1, moving_at(t)});

    aco::Cell touched;
    double clearance = world.clearance(robot.position(), limits.radius, touched);
    std::string hit = "the obstacle cell " + aco::to_string(touched);
    const std::vector<Eigen::Vector2d>& discs = result.frames.back().moving;  // where the discs are now
    for (std::size_t i = 0; i < discs.size(); ++i) {
      const double d = (robot.position() - discs[i]).norm() - scenario.moving[i].radius - limits.radius;
      if (d < clearance) clearance = d, hit = "moving obstacle " + std::to_string(i + 1);
    }
    result.min_clearance = std::min(result.min_clearance, clearance);
    if (clearance < 0.0) {
      result.collisions = 1;
      result.outcome = to_string(Outcome::collision);
      result.reason = "the robot touched " + hit + " at t = " + aco::to_string(aco::ParamValue(t)) + " s";
      break;
    }
  }
  result.time = t;
  return result;
}

}  // namespace aco::simulation
