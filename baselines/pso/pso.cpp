#include "pso/pso.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "aco/error.hpp"
#include "aco/parallel.hpp"
#include "aco/rng.hpp"
#include "aco/settings_table.hpp"

namespace aco {
namespace {

const SettingsTable<PsoSettings>& pso_table() {
  using P = PsoSettings;
  static const SettingsTable<P> table({
      field("particles", &P::particles, "1:1000000", "particles in the swarm"),
      field("iterations", &P::iterations, "1:100000000", "swarm updates after the initial swarm"),
      field("waypoints", &P::waypoints, "1:1000", "intermediate waypoints K per particle"),
      field("inertia", &P::inertia, "0:2", "inertia weight w on the previous velocity"),
      field("c1", &P::c1, "0:10", "cognitive coefficient: pull towards the particle's own best"),
      field("c2", &P::c2, "0:10", "social coefficient: pull towards the swarm's best"),
      field("max_velocity", &P::max_velocity, "(0:10]",
            "velocity clamp per coordinate and iteration, as a fraction of the map's width (x) or height (y)"),
      field("penalty", &P::penalty, "(0:1e12]", "fitness added per step into or across a blocked cell"),
  });
  return table;
}

long squared(long v) { return v * v; }

class Swarm {
 public:
  Swarm(const Graph& graph, NodeId start, NodeId goal, const PsoSettings& settings)
      : g_(graph), start_(graph.cell(start)), goal_(graph.cell(goal)), s_(settings), dims_(2 * settings.waypoints) {
    for (int d = 0; d < dims_; ++d) {
      high_.push_back(d % 2 == 0 ? g_.width - 1 : g_.height - 1);
      max_velocity_.push_back(s_.max_velocity * (d % 2 == 0 ? g_.width : g_.height));
    }
  }

  PlannerResult run() {
    PlannerResult r;
    const SearchClock clock;
    std::vector<Particle> swarm(s_.particles);
    aco::parallel_for(0, s_.particles, [&](int i) {
      Rng rng = Rng::stream(s_.seed, 0, static_cast<std::uint64_t>(i));
      Particle& p = swarm[i];
      for (int d = 0; d < dims_; ++d) {
        p.position.push_back(rng.uniform(0.0, high_[d]));
        p.velocity.push_back(rng.uniform(-max_velocity_[d], max_velocity_[d]));
      }
      evaluate(p);
      p.best_position = p.position;
      p.best_fitness = p.fitness;
    });
    std::size_t leader = 0;  // the swarm's best particle (its own best)
    for (int t = 0; t <= s_.iterations; ++t) {
      if (t > 0) {
        const std::vector<double> global = swarm[leader].best_position;
        aco::parallel_for(0, s_.particles, [&](int i) {
          Rng rng = Rng::stream(s_.seed, static_cast<std::uint64_t>(t), static_cast<std::uint64_t>(i));
          move(swarm[i], global, rng);
          evaluate(swarm[i]);
        });
      }
      r.evaluations += swarm.size();
      // In particle order, so ties go to the lowest index whatever the thread count.
      for (std::size_t i = 0; i < swarm.size(); ++i) {
        Particle& p = swarm[i];
        if (p.fitness < p.best_fitness) {
          p.best_fitness = p.fitness;
          p.best_position = p.position;
        }
        if (p.best_fitness < swarm[leader].best_fitness) leader = i;
        if (p.walk.infeasible == 0 && p.walk.length < r.length) {
          r.length = p.walk.length;
          r.path = p.walk.nodes;
        }
      }
      if (t > 0) {
        r.best_so_far.push_back(r.length);
        clock.record(r, r.evaluations);
      }
    }
    r.iterations = s_.iterations;
    r.solved = !r.path.empty();
    r.finish();
    return r;
  }

 private:
  struct Particle {
    std::vector<double> position, velocity, best_position;
    WaypointWalk walk;
    double fitness = 0.0;
    double best_fitness = 0.0;
  };

  void move(Particle& p, const std::vector<double>& global, Rng& rng) const {
    for (int d = 0; d < dims_; ++d) {
      double v = s_.inertia * p.velocity[d] + s_.c1 * rng.uniform() * (p.best_position[d] - p.position[d]) +
                 s_.c2 * rng.uniform() * (global[d] - p.position[d]);
      v = std::clamp(v, -max_velocity_[d], max_velocity_[d]);
      double x = p.position[d] + v;
      if (x < 0.0 || x > high_[d]) {  // stop at the map's border
        x = std::clamp(x, 0.0, high_[d]);
        v = 0.0;
      }
      p.position[d] = x;
      p.velocity[d] = v;
    }
  }

  void evaluate(Particle& p) const {
    std::vector<Cell> cells{start_};
    for (int k = 0; k < s_.waypoints; ++k)
      cells.push_back(
          {static_cast<int>(std::lround(p.position[2 * k])), static_cast<int>(std::lround(p.position[2 * k + 1]))});
    cells.push_back(goal_);
    p.walk = walk_waypoints(g_, cells);
    p.fitness = p.walk.length + s_.penalty * p.walk.infeasible;
  }

  const Graph& g_;
  Cell start_;
  Cell goal_;
  PsoSettings s_;
  int dims_;
  std::vector<double> high_;  // per coordinate: the largest cell coordinate
  std::vector<double> max_velocity_;  // per coordinate
};

}  // namespace

std::span<const ParamSpec> pso_parameters() { return pso_table().parameters(); }
PsoSettings pso_settings(const ParameterValues& v) { return pso_table().read(v); }

WaypointWalk walk_waypoints(const Graph& g, std::span<const Cell> cells) {
  WaypointWalk w;
  if (cells.empty()) return w;
  const auto moves = aco::moves(g.options.neighbourhood);
  Cell at = cells[0];
  w.nodes.push_back(g.node(at));
  for (std::size_t leg = 1; leg < cells.size(); ++leg) {
    const Cell from = at, to = cells[leg];
    const long lx = to.x - from.x, ly = to.y - from.y;
    while (at != to) {
      // Among the moves that get closer to the leg's end: the one closest to the leg's line
      // (|cross| = that distance times the leg's length, exact in integers), preferring graph
      // edges; only when no edge gets closer is the step infeasible.
      std::optional<Cell> next;
      bool next_feasible = false;
      long best_off = 0, best_left = 0;
      for (const Move& m : moves) {
        const Cell c{at.x + m.dx, at.y + m.dy};
        const long left = squared(to.x - c.x) + squared(to.y - c.y);
        if (!g.map->contains(c) || left >= squared(to.x - at.x) + squared(to.y - at.y)) continue;
        const bool feasible = g.edge_by_move(g.node(at), m.dx, m.dy) >= 0;
        const long off = std::abs((c.x - from.x) * ly - (c.y - from.y) * lx);
        if (!next || feasible > next_feasible ||
            (feasible == next_feasible && (off < best_off || (off == best_off && left < best_left)))) {
          next = c;
          next_feasible = feasible;
          best_off = off;
          best_left = left;
        }
      }
      const EdgeId e = g.edge_by_move(g.node(at), next->x - at.x, next->y - at.y);
      if (e >= 0) {
        w.length += g.cost(e);
      } else {
        w.length += g.distance(g.node(at), g.node(*next));
        ++w.infeasible;
      }
      at = *next;
      w.nodes.push_back(g.node(at));
    }
  }
  return w;
}

PlannerResult run_pso(const Graph& graph, NodeId start, NodeId goal, const PsoSettings& s) {
  check_endpoints(graph, start, goal, "pso");
  if (s.particles < 1 || s.iterations < 1 || s.waypoints < 1)
    throw Error("pso: particles, iterations and waypoints must be at least 1");
  if (!(s.inertia >= 0 && s.c1 >= 0 && s.c2 >= 0 && s.max_velocity > 0 && s.penalty > 0) ||
      !std::isfinite(s.inertia + s.c1 + s.c2 + s.max_velocity + s.penalty))
    throw Error("pso: inertia, c1 and c2 must be >= 0, max_velocity and penalty > 0, all finite");
  if (start == goal) return PlannerResult::already_there(start);
  return Swarm(graph, start, goal, s).run();
}

}  // namespace aco
