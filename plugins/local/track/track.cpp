// Blind path tracking: drive straight at the intermediate goal, turning towards it, and ignore
// every obstacle. The local slot's default, and the baseline that shows what a real local
// planner (local/dwa) buys: on the known map the global path is free, so this robot arrives
// unless something the map did not show is in the way.
#include <algorithm>
#include <cmath>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double gain = 2.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("gain", &Parameters::gain, "(0:100]",
               "turn rate per radian of heading error (1/s): w = gain * error; speed falls as cos(error), 0 beyond 90 degrees"),
});

class Track final : public aco::LocalPlanner {
 public:
  explicit Track(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  aco::VelocityCommand command(const aco::LocalView& view) override {
    const aco::RobotState& r = view.robot;
    const Eigen::Vector2d to_goal = view.goal - r.position();
    const double error = aco::wrap_angle(std::atan2(to_goal.y(), to_goal.x()) - r.heading);
    const aco::VelocityCommand wanted{view.limits.max_speed * std::max(0.0, std::cos(error)), p_.gain * error};
    return aco::dynamic_window(r, view.limits, view.period).clamp(wanted);
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(local, track, Track, "1.0",
           "blind tracking: heads for the intermediate goal and ignores obstacles (the baseline without a local planner)",
           kParams)
