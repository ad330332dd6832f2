// Dynamic Window Approach (paper 003, section 3; Fox, Burgard and Thrun 1997): sample the
// velocities reachable in one control period; for each, dist(v, w) is how far the robot drives
// along that arc before it would touch an obstacle; keep the velocities it can still brake from
// before that point (eq. 18), and take the best weighted, normalised sum of heading, dist and
// velocity (eq. 21).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double v_resolution = 0.02;
  double w_resolution = 1.0 * aco::kDegree;
  double heading = 0.15;
  double clearance = 0.1;
  double velocity = 0.3;
  double horizon = 3.0;
  double lookahead = 6.0;
  double dist_cap = 1.0;
  double margin = 0.05;
  bool predict = true;
  bool stop_at_goal = true;
  double follow = 0.5;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("v_resolution", &Parameters::v_resolution, "(0:10]",
               "step between sampled velocities v (paper 003: 0.02)"),
    aco::field("w_resolution", &Parameters::w_resolution, "(0:100]",
               "step between sampled yaw rates w in rad/s (paper 003: 1 degree/s); w = 0 is always sampled when in the "
               "window"),
    aco::field("heading", &Parameters::heading, "0:1000", "weight alpha of the heading term (paper 003: 0.15)"),
    aco::field("clearance", &Parameters::clearance, "0:1000", "weight beta of the dist term (paper 003: 0.1)"),
    aco::field("velocity", &Parameters::velocity, "0:1000", "weight gamma of the velocity term (paper 003: 0.3)"),
    aco::field("horizon", &Parameters::horizon, "(0:100]",
               "seconds each sampled velocity is rolled out for the heading term (the heading at the end counts)"),
    aco::field("lookahead", &Parameters::lookahead, "(0:100]",
               "dist(v, w) is searched along the arc up to this distance: a free arc scores this much, and the speed "
               "stays below what can stop within it (6: the paper's 1.5 m/s at 0.2 m/s^2 needs 5.6; a free arc is "
               "searched step by step to its end, so far beyond the sensor range costs time and changes nothing)"),
    aco::field("dist_cap", &Parameters::dist_cap, "(0:1e6]",
               "the dist term counts dist(v, w) up to this distance: obstacles farther along an arc do not steer "
               "(the MATLAB DWA code caps it at 2 x the obstacle radius)"),
    aco::field("margin", &Parameters::margin, "0:1e6", "the robot counts as touching an obstacle closer than this"),
    aco::field("predict", &Parameters::predict, "",
               "roll moving obstacles forward with their sensed velocity (false: as in the paper, they stand where "
               "sensed; preset paper003)"),
    aco::field(
        "stop_at_goal", &Parameters::stop_at_goal, "",
        "the velocity term counts v only up to sqrt(2 a_max d_goal), the speed the robot can stop from at the goal, "
        "so it slows down and turns in instead of circling the goal (false: v, as in the paper)"),
    aco::field("follow", &Parameters::follow, "0:1e6",
               "the heading term aims at the point this far along the global path beyond the point nearest to the "
               "rollout's end, so the robot keeps to the path (through one-cell doors); 0: at the intermediate goal, "
               "as in the paper "
               "(preset paper003)"),
});

class Dwa final : public aco::LocalPlanner {
 public:
  explicit Dwa(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  aco::VelocityCommand command(const aco::LocalView& view) override {
    gather_near(view);
    const aco::DynamicWindow window = aco::dynamic_window(view.robot, view.limits, view.period);
    candidates_.clear();
    for (double v : samples(window.v_low, window.v_high, p_.v_resolution))
      for (double w : samples(window.w_low, window.w_high, p_.w_resolution)) consider(view, {v, w});
    const double goal_speed = p_.stop_at_goal
                                  ? std::sqrt(2.0 * view.limits.max_accel * (view.goal - view.robot.position()).norm())
                                  : std::numeric_limits<double>::infinity();
    // Measured from the slowest allowed speed, so that the term stays >= 0 for a robot that may
    // back up (and is v itself for one that may not).
    for (Candidate& c : candidates_) c.velocity = std::min(c.command.v, goal_speed) - view.limits.min_speed;
    double total_heading = 0, total_dist = 0, total_velocity = 0;
    for (const Candidate& c : candidates_) {
      total_heading += c.heading;
      total_dist += c.dist;
      total_velocity += c.velocity;
    }
    // sigma of eq. 21: each term as a share of its sum over the admissible velocities.
    const auto share = [](double x, double total) { return total > 0.0 ? x / total : 0.0; };
    const Candidate* best = nullptr;
    double best_value = -std::numeric_limits<double>::infinity();
    for (const Candidate& c : candidates_) {
      const double value = p_.heading * share(c.heading, total_heading) + p_.clearance * share(c.dist, total_dist) +
                           p_.velocity * share(c.velocity, total_velocity);
      if (value > best_value) best_value = value, best = &c;
    }
    return best ? best->command : aco::brake(view.robot, view.limits, view.period);
  }

 private:
  struct Candidate {
    aco::VelocityCommand command;
    double heading;  // pi - |angle from the heading at the horizon to the goal|, in [0, pi]
    double dist;  // free distance along the arc, at most dist_cap
    double velocity = 0.0;  // the velocity term
  };

  // low, low + step, ... up to high, high itself included, and 0 if inside.
  static std::vector<double> samples(double low, double high, double step) {
    std::vector<double> values;
    for (int i = 0; low + i * step < high - 1e-12; ++i) values.push_back(low + i * step);
    values.push_back(high);
    if (low > 0.0 || high < 0.0) return values;
    // Exactly 0, so that the robot can drive straight: a grid value within rounding of it is 0.
    const auto nearest =
        std::min_element(values.begin(), values.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    if (std::abs(*nearest) < 1e-9 * step)
      *nearest = 0.0;
    else
      values.insert(std::upper_bound(values.begin(), values.end(), 0.0), 0.0);
    return values;
  }

  // The obstacles an arc of length lookahead can reach; the others cannot matter this step. The
  // cells go into a small grid (cell centres lie on multiples of the cell size), so that a
  // point's test looks at the few cells around it, not at every cell in sensor range. The grid
  // spans the reachable cells only: a wide reach (a large lookahead or margin) costs nothing more.
  void gather_near(const aco::LocalView& view) {
    const Eigen::Vector2d p = view.robot.position();
    const double reach = p_.lookahead + view.limits.radius + p_.margin, size = view.cell_size;
    const auto index = [size](double v) { return static_cast<int>(std::lround(v / size)); };
    const int low_x = index(p.x() - reach) - 1, low_y = index(p.y() - reach) - 1;
    const int high_x = index(p.x() + reach) + 1, high_y = index(p.y() + reach) + 1;
    std::vector<std::pair<int, int>> near;  // grid positions of the cells within reach on each axis
    for (const Eigen::Vector2d& c : view.cells) {
      const int x = index(c.x()), y = index(c.y());
      if (x >= low_x && x <= high_x && y >= low_y && y <= high_y) near.emplace_back(x, y);
    }
    x0_ = y0_ = 0, columns_ = rows_ = 0;
    if (!near.empty()) {
      const auto [min_x, max_x] = std::minmax_element(near.begin(), near.end());
      const auto [min_y, max_y] =
          std::minmax_element(near.begin(), near.end(), [](auto a, auto b) { return a.second < b.second; });
      x0_ = min_x->first, y0_ = min_y->second;
      columns_ = max_x->first - x0_ + 1, rows_ = max_y->second - y0_ + 1;
    }
    occupied_.assign(static_cast<std::size_t>(columns_) * rows_, 0);
    for (const auto& [x, y] : near) occupied_[static_cast<std::size_t>(y - y0_) * columns_ + (x - x0_)] = 1;
    near_moving_.clear();
    for (const aco::MovingObstacle& m : view.moving) {
      // A predicted obstacle may come from farther away: it moves while the robot drives.
      const double travel = p_.predict ? m.velocity.norm() * p_.lookahead / std::max(view.robot.v, 0.1) : 0.0;
      if ((m.position - p).norm() - m.radius <= reach + travel) near_moving_.push_back(m);
    }
  }

  // Whether the robot at p, at time t from now, touches an obstacle (closer than the margin).
  bool touches(const aco::LocalView& view, const Eigen::Vector2d& p, double t) const {
    const double limit = view.limits.radius + p_.margin, size = view.cell_size;
    // A cell can be within `limit` of p only if its centre is within limit + size / 2 on each axis.
    const int reach = static_cast<int>(std::ceil(limit / size + 0.5));
    const int cx = static_cast<int>(std::lround(p.x() / size)), cy = static_cast<int>(std::lround(p.y() / size));
    // Only the cells of the grid: outside it nothing is occupied.
    for (int y = std::max(cy - reach, y0_); y <= std::min(cy + reach, y0_ + rows_ - 1); ++y)
      for (int x = std::max(cx - reach, x0_); x <= std::min(cx + reach, x0_ + columns_ - 1); ++x) {
        if (!occupied_[static_cast<std::size_t>(y - y0_) * columns_ + (x - x0_)]) continue;
        if (aco::distance_to_square(p, Eigen::Vector2d(x * size, y * size), size) < limit) return true;
      }
    for (const aco::MovingObstacle& m : near_moving_) {
      const Eigen::Vector2d at = p_.predict ? Eigen::Vector2d(m.position + t * m.velocity) : m.position;
      if ((p - at).norm() - m.radius < limit) return true;
    }
    return false;
  }

  // dist(v, w): the arc length driven with (v, w) held before the first contact, searched in
  // steps of a tenth of the robot's radius up to the lookahead (which it returns if the arc is
  // free); backwards when v < 0. Turning on the spot (v = 0) drives nowhere: its arc is free.
  double free_distance(const aco::LocalView& view, const aco::VelocityCommand& c) const {
    if (c.v == 0.0) return p_.lookahead;
    const aco::RobotState& r = view.robot;
    const double step = std::max(view.limits.radius, 1e-3) / 10.0, curvature = c.w / c.v,
                 direction = c.v > 0.0 ? 1.0 : -1.0;
    for (double s = step;; s += step) {
      const double length = std::min(s, p_.lookahead), arc = direction * length, turn = curvature * arc;
      // The exact arc: a straight segment when it does not turn.
      const Eigen::Vector2d at =
          std::abs(turn) < 1e-9 ? Eigen::Vector2d(r.x + arc * std::cos(r.heading), r.y + arc * std::sin(r.heading))
                                : Eigen::Vector2d(r.x + (std::sin(r.heading + turn) - std::sin(r.heading)) / curvature,
                                                  r.y - (std::cos(r.heading + turn) - std::cos(r.heading)) / curvature);
      if (touches(view, at, arc / c.v)) return std::max(0.0, length - step);
      if (length >= p_.lookahead) return p_.lookahead;
    }
  }

  void consider(const aco::LocalView& view, const aco::VelocityCommand& command) {
    const double dist = free_distance(view, command);
    // Eq. 18 in discrete time: driving one period at v, then braking, must end before contact.
    const double speed = std::abs(command.v);
    if (speed * view.period + speed * speed / (2.0 * view.limits.max_accel) > dist) return;
    aco::RobotState s = view.robot;
    const int steps = std::max(1, static_cast<int>(std::ceil(p_.horizon / view.period - 1e-9)));
    // Following the path, a rollout ends where the robot would touch an obstacle: an arc that
    // runs into a door's post does not get past it to line up with the path behind.
    const double reach = p_.follow > 0.0 ? dist : std::numeric_limits<double>::infinity();
    for (int k = 0; k < steps && speed * (k + 1) * view.period <= reach; ++k) s = aco::move(s, command, view.period);
    const Eigen::Vector2d to_goal = aim(view, s.position(), speed * p_.horizon) - s.position();
    const double error =
        to_goal.squaredNorm() > 0.0 ? aco::wrap_angle(std::atan2(to_goal.y(), to_goal.x()) - s.heading) : 0.0;
    candidates_.push_back({command, M_PI - std::abs(error), std::min(dist, p_.dist_cap)});
  }

  // Where the heading term points from `end`, a rollout's end `driven` away along its arc.
  Eigen::Vector2d aim(const aco::LocalView& view, const Eigen::Vector2d& end, double driven) const {
    if (p_.follow == 0.0 || view.path.empty()) return view.goal;
    // Only the part of the path the rollout can have reached is searched for the foot.
    const double foot = aco::foot_on_path(view.path, end, driven + view.limits.radius + 1.0);
    return aco::point_on_path(view.path, foot + p_.follow);
  }

  Parameters p_;
  std::vector<Candidate> candidates_;
  std::vector<std::uint8_t> occupied_;  // the sensed cells near the robot, by grid position
  int x0_ = 0, y0_ = 0, columns_ = 0, rows_ = 0;
  std::vector<aco::MovingObstacle> near_moving_;
};

}  // namespace

ACO_PLUGIN(local, dwa, Dwa, "1.0",
           "paper 003: Dynamic Window Approach, G(v,w) = alpha heading + beta dist + gamma velocity over the "
           "velocities that can still stop",
           kParams)
