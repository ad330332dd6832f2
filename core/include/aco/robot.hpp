#pragma once
// A mobile robot on the map for local planning (paper 003, section 3): its state, its limits, the
// motion model and the dynamic window. Shared by the local planner plugins and the simulator, so
// both move the robot the same way. Units are map units (a cell is cell_size wide, 1 on plain
// grids: metres in the paper) and seconds; headings in radians in the map's (x, y) frame.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace aco {

struct RobotState {
  double x = 0.0;
  double y = 0.0;
  double heading = 0.0;  // theta
  double v = 0.0;  // forward velocity
  double w = 0.0;  // angular velocity (yaw rate)

  Eigen::Vector2d position() const { return {x, y}; }
};

inline constexpr double kDegree = M_PI / 180.0;

// Paper 003's robot as defaults. The paper gives 20 "rad/s" and 50 "rad/s^2"; they are the
// degrees of the widely used MATLAB DWA code it follows (toRadian(20), toRadian(50)): at 20 rad/s
// a robot at full speed turns on a 7.5 cm circle, and the planner prefers spinning to driving.
struct RobotLimits {
  double radius = 0.3;  // the robot is a disc of this radius
  double max_speed = 1.5;  // v <= max_speed
  double max_yaw_rate = 20.0 * kDegree;  // |w| <= max_yaw_rate
  double max_accel = 0.2;  // |dv/dt| <= max_accel, braking included
  double max_yaw_accel = 50.0 * kDegree;  // |dw/dt| <= max_yaw_accel
  double min_speed = 0.0;  // v >= min_speed: below 0 the robot may back up (not in the paper)
};

struct VelocityCommand {
  double v = 0.0;
  double w = 0.0;
};

// Eq. 15-17: one step of length dt with the velocities held, the position moved along the
// heading at the start of the step (then the heading turns). lateral_v is the paper's v_y, zero
// for a differential-drive robot.
inline RobotState move(const RobotState& s, const VelocityCommand& c, double dt, double lateral_v = 0.0) {
  RobotState next = s;
  const double cos_h = std::cos(s.heading), sin_h = std::sin(s.heading);
  next.x = s.x + c.v * dt * cos_h - lateral_v * dt * sin_h;
  next.y = s.y + c.v * dt * sin_h + lateral_v * dt * cos_h;
  next.heading = s.heading + c.w * dt;
  next.v = c.v;
  next.w = c.w;
  return next;
}

// Eq. 19-20: the velocities reachable within one control period, inside the robot's limits.
struct DynamicWindow {
  double v_low, v_high, w_low, w_high;

  VelocityCommand clamp(const VelocityCommand& c) const {
    return {std::clamp(c.v, v_low, v_high), std::clamp(c.w, w_low, w_high)};
  }
  // Whether c lies in the window, give or take `tolerance` (false for NaN).
  bool contains(const VelocityCommand& c, double tolerance) const {
    return c.v >= v_low - tolerance && c.v <= v_high + tolerance && c.w >= w_low - tolerance &&
           c.w <= w_high + tolerance;
  }
};

// How far a local planner's command may stray out of the dynamic window by rounding: the
// simulator clamps that much back in, and refuses more (as aco-plugin-check does).
inline constexpr double kWindowTolerance = 1e-9;

inline DynamicWindow dynamic_window(const RobotState& s, const RobotLimits& limits, double period) {
  return {std::max(limits.min_speed, s.v - limits.max_accel * period),
          std::min(limits.max_speed, s.v + limits.max_accel * period),
          std::max(-limits.max_yaw_rate, s.w - limits.max_yaw_accel * period),
          std::min(limits.max_yaw_rate, s.w + limits.max_yaw_accel * period)};
}

// Braking as hard as allowed along the arc the robot is on (the curvature w / v kept, inside the
// yaw limits): what a robot does when no velocity is safe. Speeds were chosen so that it can
// stop on that arc before it touches anything.
inline VelocityCommand brake(const RobotState& s, const RobotLimits& limits, double period) {
  const double dv = limits.max_accel * period;
  const double v = s.v > 0.0 ? std::max(0.0, s.v - dv) : std::min(0.0, s.v + dv);
  const double w = s.v != 0.0 ? s.w * v / s.v : 0.0;
  return dynamic_window(s, limits, period).clamp({v, w});
}

// Distance from point p to the closed square of side `size` centred on `centre` (0 inside).
inline double distance_to_square(const Eigen::Vector2d& p, const Eigen::Vector2d& centre, double size) {
  const double dx = std::max(0.0, std::abs(p.x() - centre.x()) - size / 2);
  const double dy = std::max(0.0, std::abs(p.y() - centre.y()) - size / 2);
  return std::hypot(dx, dy);
}

// Where on a polyline the point nearest to p lies, as the length along the polyline from its
// first point; only the first max_length of the polyline is searched (a path may pass near p
// again much later, behind a wall).
inline double foot_on_path(std::span<const Eigen::Vector2d> path, const Eigen::Vector2d& p,
                           double max_length = std::numeric_limits<double>::infinity()) {
  double best = std::numeric_limits<double>::infinity(), foot = 0.0, start = 0.0;
  for (std::size_t i = 0; i + 1 < path.size() && start <= max_length; ++i) {
    const Eigen::Vector2d leg = path[i + 1] - path[i];
    const double length = leg.norm();
    const double along = length > 0.0 ? std::clamp((p - path[i]).dot(leg) / length, 0.0, length) : 0.0;
    const double d = (path[i] + leg * (length > 0.0 ? along / length : 0.0) - p).squaredNorm();
    if (d < best) best = d, foot = start + along;
    start += length;
  }
  return foot;
}

// The point at `length` along a polyline (its last point beyond its end).
inline Eigen::Vector2d point_on_path(std::span<const Eigen::Vector2d> path, double length) {
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d leg = path[i + 1] - path[i];
    const double leg_length = leg.norm();
    if (length <= leg_length)
      return leg_length > 0.0 ? Eigen::Vector2d(path[i] + leg * (length / leg_length)) : path[i];
    length -= leg_length;
  }
  return path.empty() ? Eigen::Vector2d(0.0, 0.0) : path.back();
}

// Heading difference wrapped to [-pi, pi].
inline double wrap_angle(double a) { return std::remainder(a, 2.0 * M_PI); }

}  // namespace aco
