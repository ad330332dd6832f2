// MAX-MIN Ant System (Stuetzle and Hoos 2000), with the details of Stuetzle's ACOTSP reference
// code: one ant deposits, tau kept in [tau_min, tau_max], optional restart on stagnation.
#include <algorithm>
#include <cmath>
#include <limits>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double rho = 0.1;
  double q = 1.0;
  double p_best = 0.05;
  std::int64_t best_so_far_every = 0;
  std::int64_t restart_after = 0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "(0:1]", "evaporation rate"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q: the depositing ant adds Q / L"),
    aco::field("p_best", &Parameters::p_best, "(0:1)",
               "probability that a converged colony rebuilds the best path; sets tau_min relative to tau_max"),
    aco::field(
        "best_so_far_every", &Parameters::best_so_far_every, "0:1000000",
        "the best-so-far ant deposits every n-th iteration, the iteration best otherwise; 0 = ACOTSP's schedule "
        "(every 25th iteration before iteration 25, 5th before 75, 3rd before 125, 2nd before 250, then always)"),
    aco::field("restart_after", &Parameters::restart_after, "0:1000000",
               "reset every edge to tau_max after this many iterations without a shorter best-so-far path (0 = never)"),
});

class MaxMinUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit MaxMinUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  void begin_run(const aco::Context& c) override {
    bounded_ = false;
    best_length_ = std::numeric_limits<double>::infinity();
    last_improvement_ = 0;
    // ACOTSP's "average number of choices" is (candidates + 1) / 2; here the candidates of a
    // decision are the neighbours, so the mean degree of the passable nodes.
    const aco::Graph& g = *c.graph;
    int nodes = 0;
    for (aco::NodeId n = 0; n < g.num_nodes(); ++n) nodes += g.degree(n) > 0;
    choices_ = 0.5 * (1.0 + double(g.num_edges()) / std::max(nodes, 1));
  }

  void start(const aco::Context& c, std::span<double>) override {
    c.add("restarts", 0);  // in every run's figures, the runs without a restart too
  }

  // Evaporation and the bounds cost the engine nothing per edge (aco::Trail); per iteration only
  // the depositing ant's edges are written, so a run on a 2048x2048 map is not a pass over its
  // 33 M edges per iteration.
  void update_trail(const aco::Context& c, const aco::Iteration& it, aco::Trail& trail) override {
    if (it.best_so_far == nullptr) {  // nothing to deposit, no bounds known yet
      trail.evaporate(p_.rho);
      return;
    }
    const aco::Ant& best = *it.best_so_far;
    const double tau_max = p_.q / (p_.rho * best.length);
    const double p_dec = std::pow(p_.p_best, 1.0 / std::max<double>(1.0, double(best.edges.size())));
    const double tau_min = std::min(tau_max, tau_max * (1.0 - p_dec) / (choices_ * p_dec));

    if (best.length < best_length_) {
      best_length_ = best.length;
      last_improvement_ = c.iteration;
    }
    if (p_.restart_after > 0 && c.iteration - last_improvement_ >= p_.restart_after) {
      trail.fill(tau_max);  // forget the trail; the engine keeps the best path
      last_improvement_ = c.iteration;
      c.add("restarts");
      return;
    }
    const aco::Ant& depositor =
        it.best == nullptr || (c.iteration + 1) % best_so_far_period(c.iteration) == 0 ? best : *it.best;
    // ACOTSP's order, evaporate every edge, deposit, then bound every edge: the depositor's
    // edges get their evaporated values (within the last bounds) plus the deposit, bounded with
    // the rest by bound().
    evaporated_.clear();
    if (!bounded_) {
      // MMAS starts at tau_max, which the first solution fixes: scale the init plugin's field
      // to it here, keeping its shape (once per run, over every edge).
      trail.evaporate(p_.rho);
      const std::span<double> tau = trail.values();
      const double top = *std::max_element(tau.begin(), tau.end());
      if (top > 0.0)
        for (double& t : tau) t *= tau_max / top;
      bounded_ = true;
      for (aco::EdgeId e : depositor.edges) evaporated_.push_back(trail[e]);
    } else {
      for (aco::EdgeId e : depositor.edges) evaporated_.push_back((1.0 - p_.rho) * trail[e]);
      trail.evaporate(p_.rho);
    }
    trail.bound(tau_min, tau_max);
    for (std::size_t i = 0; i < depositor.edges.size(); ++i)
      trail.set(depositor.edges[i], evaporated_[i] + p_.q / depositor.length);
  }

  // The same rule on plain values (callers other than the engine): every edge evaporated and
  // bounded at once.
  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    aco::Trail trail(tau);
    update_trail(c, it, trail);
    trail.values();
  }

 private:
  int best_so_far_period(int iteration) const {
    if (p_.best_so_far_every > 0) return static_cast<int>(p_.best_so_far_every);
    return iteration < 25 ? 25 : iteration < 75 ? 5 : iteration < 125 ? 3 : iteration < 250 ? 2 : 1;
  }

  Parameters p_;
  double choices_ = 1.0;
  double best_length_ = std::numeric_limits<double>::infinity();
  int last_improvement_ = 0;
  bool bounded_ = false;
  std::vector<double> evaporated_;  // per edge of the depositor, reused from iteration to iteration
};

}  // namespace

ACO_PLUGIN(
    update, max_min, MaxMinUpdate, "1.0",
    "MAX-MIN Ant System: only the iteration-best (or best-so-far) ant deposits; tau bounded in [tau_min, tau_max]",
    kParams)
