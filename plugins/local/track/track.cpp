// Blind path tracking: turn towards the intermediate goal, drive at it, and ignore every
// obstacle. The local slot's default, and the baseline that shows what a real local
// planner (local/dwa) buys: on the known map the global path is free, so this robot arrives
// unless something the map did not show is in the way.
#include <algorithm>
#include <cmath>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double gain = 2.0;
  double turn_in_place = 10.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("gain", &Parameters::gain, "(0:100]", "turn rate per radian of heading error (1/s): w = gain * error"),
    aco::field("turn_in_place", &Parameters::turn_in_place, "(0:180]",
               "heading error in degrees above which the robot stops and turns on the spot"),
});

class Track final : public aco::LocalPlanner {
 public:
  explicit Track(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  aco::VelocityCommand command(const aco::LocalView& view) override {
    const aco::RobotState& r = view.robot;
    const Eigen::Vector2d to_goal = view.goal - r.position();
    const double error = aco::wrap_angle(std::atan2(to_goal.y(), to_goal.x()) - r.heading);
    // Drives only when roughly facing the goal, no faster than it can stop there: it follows the
    // path's corners exactly, as far as its limits allow.
    const double stop_speed = std::sqrt(2.0 * view.limits.max_accel * to_goal.norm());
    const double v =
        std::abs(error) <= p_.turn_in_place * aco::kDegree ? std::min(view.limits.max_speed, stop_speed) : 0.0;
    const aco::VelocityCommand wanted{v, p_.gain * error};
    return aco::dynamic_window(r, view.limits, view.period).clamp(wanted);
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(
    local, track, Track, "1.0",
    "blind tracking: heads for the intermediate goal and ignores obstacles (the baseline without a local planner)",
    kParams)
