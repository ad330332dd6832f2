// local/dwa (paper 003, section 3) and the robot model it shares with the simulator
// (aco/robot.hpp): motion model, dynamic window, safety of the chosen velocities.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "aco/robot.hpp"
#include "aco/strategies.hpp"
#include "support.hpp"

namespace {

// A robot driven by a local planner among fixed cells: the smallest clearance seen (robot edge
// to the nearest cell) and the final state.
struct Drive {
  double smallest_clearance = 1e9;
  aco::RobotState final;
};

double clearance(const aco::RobotState& r, const std::vector<Eigen::Vector2d>& cells, double radius) {
  double nearest = 1e9;
  for (const auto& c : cells) nearest = std::min(nearest, aco::distance_to_square(r.position(), c, 1.0));
  return nearest - radius;
}

Drive drive(aco::LocalPlanner& planner, aco::RobotState robot, const Eigen::Vector2d& goal,
            const std::vector<Eigen::Vector2d>& cells, int steps) {
  aco::LocalView view;
  view.goal = goal;
  view.cells = cells;
  Drive d;
  for (int i = 0; i < steps; ++i) {
    view.robot = robot;
    const aco::VelocityCommand wanted = planner.command(view);
    const aco::VelocityCommand c = aco::dynamic_window(robot, view.limits, view.period).clamp(wanted);
    CHECK(c.v == Approx(wanted.v).margin(1e-12));  // the planner stays inside the window
    CHECK(c.w == Approx(wanted.w).margin(1e-12));
    robot = aco::move(robot, c, view.period);
    d.smallest_clearance = std::min(d.smallest_clearance, clearance(robot, cells, view.limits.radius));
  }
  d.final = robot;
  return d;
}

}  // namespace

TEST_CASE("motion model: eq. 15-17 against values integrated by hand", "[dwa][robot]") {
  aco::RobotState s;  // at the origin, heading along +x
  const aco::VelocityCommand c{1.0, 0.5};
  s = aco::move(s, c, 0.1);
  CHECK(s.x == Approx(0.1));
  CHECK(s.y == Approx(0.0).margin(1e-15));
  CHECK(s.heading == Approx(0.05));
  s = aco::move(s, c, 0.1);  // x += 0.1 cos 0.05, y += 0.1 sin 0.05
  CHECK(s.x == Approx(0.199875026));
  CHECK(s.y == Approx(0.004997917));
  s = aco::move(s, c, 0.1);  // x += 0.1 cos 0.1, y += 0.1 sin 0.1
  CHECK(s.x == Approx(0.299375443));
  CHECK(s.y == Approx(0.014981259));
  CHECK(s.heading == Approx(0.15));
  CHECK(s.v == 1.0);
  CHECK(s.w == 0.5);
  // The lateral term: heading +y, v_y = 0.5 moves the robot towards -x.
  aco::RobotState up;
  up.heading = M_PI / 2;
  const aco::RobotState side = aco::move(up, {0.0, 0.0}, 2.0, 0.5);
  CHECK(side.x == Approx(-1.0));
  CHECK(side.y == Approx(0.0).margin(1e-12));
}

TEST_CASE("path geometry: the foot of a point on a polyline, and the point at a length along it", "[dwa][robot]") {
  const std::vector<Eigen::Vector2d> path{{0, 0}, {4, 0}, {4, 3}};
  CHECK(aco::foot_on_path(path, {1, 2}) == Approx(1.0));
  CHECK(aco::foot_on_path(path, {6, 2}) == Approx(6.0));  // on the second leg
  CHECK(aco::foot_on_path(path, {-3, 1}) == Approx(0.0));  // before the start: the start
  CHECK(aco::foot_on_path(path, {9, 9}) == Approx(7.0));  // beyond the end: the end
  CHECK(aco::foot_on_path(path, {6, 2}, 3.0) == Approx(4.0));  // the second leg not searched
  CHECK(aco::point_on_path(path, 2.5).isApprox(Eigen::Vector2d(2.5, 0)));
  CHECK(aco::point_on_path(path, 5.0).isApprox(Eigen::Vector2d(4, 1)));
  CHECK(aco::point_on_path(path, 100.0).isApprox(Eigen::Vector2d(4, 3)));
}

TEST_CASE("dynamic window: acceleration over one period inside the velocity limits", "[dwa][robot]") {
  const aco::RobotLimits paper;  // 1.5 m/s, 20 degrees/s, 0.2 m/s^2, 50 degrees/s^2
  CHECK(paper.max_yaw_rate == Approx(20 * M_PI / 180));
  CHECK(paper.max_yaw_accel == Approx(50 * M_PI / 180));
  aco::RobotLimits limits;  // round numbers for the arithmetic
  limits.max_yaw_rate = 20.0;
  limits.max_yaw_accel = 50.0;
  aco::RobotState s;
  s.v = 1.0;
  auto w = aco::dynamic_window(s, limits, 0.1);
  CHECK(w.v_low == Approx(0.98));
  CHECK(w.v_high == Approx(1.02));
  CHECK(w.w_low == Approx(-5.0));
  CHECK(w.w_high == Approx(5.0));
  s.v = 0.01, s.w = 18.0;  // no reversing; the yaw-rate limit cuts the window
  w = aco::dynamic_window(s, limits, 0.1);
  CHECK(w.v_low == 0.0);
  CHECK(w.v_high == Approx(0.03));
  CHECK(w.w_low == Approx(13.0));
  CHECK(w.w_high == 20.0);
  s.v = 1.5, s.w = 1.5;
  CHECK(aco::dynamic_window(s, limits, 0.1).v_high == 1.5);
  const aco::VelocityCommand stop = aco::brake(s, limits, 0.1);  // along the same arc
  CHECK(stop.v == Approx(1.48));
  CHECK(stop.w == Approx(1.48));
}

TEST_CASE("dwa drives to a goal in the open straight, speeding up as fast as its limits allow", "[dwa]") {
  auto dwa = test::make<aco::LocalPlanner>("local", "dwa");
  const Drive d = drive(*dwa, aco::RobotState(), {100.0, 0.0}, {}, 100);  // 10 s
  // From rest at 0.2 m/s^2: 0.02 m/s more every 0.1 s up to 1.5 m/s (step 75), then 1.5 m/s.
  CHECK(d.final.v == Approx(1.5));
  CHECK(d.final.x == Approx(0.002 * 75 * 76 / 2 + 25 * 0.15));
  CHECK(d.final.y == 0.0);
  CHECK(d.final.heading == 0.0);
}

TEST_CASE("dwa never takes a velocity that hits a cell, and stops rather than collides when boxed in", "[dwa][slow]") {
  auto dwa = test::make<aco::LocalPlanner>("local", "dwa");
  auto track = test::make<aco::LocalPlanner>("local", "track");
  SECTION("a box with no way out") {
    std::vector<Eigen::Vector2d> box;
    for (int i = -4; i <= 4; ++i)
      for (const auto& c :
           {Eigen::Vector2d(i, -4), Eigen::Vector2d(i, 4), Eigen::Vector2d(-4, i), Eigen::Vector2d(4, i)})
        box.push_back(c);
    aco::RobotState robot;
    robot.v = 1.0;  // braking distance 2.5: it must start braking at once
    const Drive d = drive(*dwa, robot, {10.0, 0.0}, box, 400);
    CHECK(d.smallest_clearance > 0.0);
    CHECK(d.final.v < 0.05);  // at the wall nearest the goal
    // The blind tracker drives into the wall: the property above can fail.
    CHECK(drive(*track, robot, {10.0, 0.0}, box, 400).smallest_clearance < 0.0);
  }
  SECTION("random cluttered worlds: no contact ever") {
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> coordinate(-10, 10);
    for (int world = 0; world < 20; ++world) {
      std::vector<Eigen::Vector2d> cells;
      for (int i = 0; i < 40; ++i) {
        const Eigen::Vector2d c(coordinate(rng), coordinate(rng));
        if (c.norm() > 2.0) cells.push_back(c);
      }
      aco::RobotState robot;
      robot.heading = std::uniform_real_distribution<double>(-M_PI, M_PI)(rng);
      robot.v = 0.5;
      const Drive d = drive(*dwa, robot, {coordinate(rng), coordinate(rng)}, cells, 300);
      CHECK(d.smallest_clearance > 0.0);
    }
  }
}

TEST_CASE("dwa passes an obstacle on the straight way to the goal and gets there", "[dwa]") {
  // With the default dist_cap of 1 an obstacle steers only from close by, too late for this
  // robot's 20 degrees/s at speed: it stops in front and acosim replans. Steering from 3 away:
  auto dwa = test::make<aco::LocalPlanner>("local", "dwa", {{"dist_cap", "3"}});
  const std::vector<Eigen::Vector2d> wall = {{4, 0}};  // the straight way passes 0.5 from its centre
  aco::RobotState robot;
  robot.y = 0.5;
  aco::LocalView view;
  view.goal = {8.0, 0.5};
  view.cells = wall;
  double closest = 1e9;
  for (int i = 0; i < 600 && closest > 0.3; ++i) {
    view.robot = robot;
    robot = aco::move(robot, dwa->command(view), view.period);
    CHECK(clearance(robot, wall, view.limits.radius) > 0.0);
    closest = std::min(closest, (robot.position() - view.goal).norm());
  }
  CHECK(closest <= 0.3);
}
