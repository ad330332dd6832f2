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
  double restart_branching = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "1e-6:1", "evaporation rate"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q: the depositing ant adds Q / L"),
    aco::field("p_best", &Parameters::p_best, "(0:1)",
               "probability that a converged colony rebuilds the best path; sets tau_min relative to tau_max"),
    aco::field(
        "best_so_far_every", &Parameters::best_so_far_every, "0:1000000",
        "the best-so-far ant deposits every n-th iteration, the iteration best otherwise; 0 = ACOTSP's schedule "
        "(every 25th iteration before iteration 25, 5th before 75, 3rd before 125, 2nd before 250, then always)"),
    aco::field("restart_after", &Parameters::restart_after, "0:1000000",
               "reset every edge to tau_max after this many iterations without a shorter restart-best path (0 = "
               "never); after a reset the restart-best walk, found since, deposits in place of the best-so-far"),
    aco::field("restart_branching", &Parameters::restart_branching, "0:1000",
               "with restart_after: reset only once the colony has converged, when the mean lambda-branching factor "
               "(lambda 0.05) over the restart-best walk's nodes is below this (ACOTSP: 1.00001); 0 = no such test"),
});

class MaxMinUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit MaxMinUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  void begin_run(const aco::Context& c) override {
    bounded_ = false;
    restart_best_ = {};
    restart_length_ = std::numeric_limits<double>::infinity();
    restart_found_ = restart_iteration_ = restarts_ = 0;
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
    // ACOTSP's restart-best: the best walk since the last reset, which is the best-so-far until the
    // first reset (the engine's, read as it is, so that runs without a reset stay as they were).
    const aco::Ant& best = *it.best_so_far;
    if (restarts_ == 0) {
      if (best.length < restart_length_) restart_length_ = best.length, restart_found_ = c.iteration;
    } else if (it.best != nullptr && (restart_best_.edges.empty() || it.best->length < restart_best_.length)) {
      restart_best_ = *it.best;
      restart_found_ = c.iteration;
    }
    const double tau_max = p_.q / (p_.rho * best.length);
    const double p_dec = std::pow(p_.p_best, 1.0 / std::max<double>(1.0, double(best.edges.size())));
    const double tau_min = std::min(tau_max, tau_max * (1.0 - p_dec) / (choices_ * p_dec));

    if (restart_due(c, restarts_ == 0 ? best : restart_best_, trail, tau_min, tau_max)) {
      trail.fill(tau_max);  // forget the trail; the engine keeps the best path
      restart_best_ = {};
      restart_found_ = restart_iteration_ = c.iteration;
      ++restarts_;
      c.add("restarts");
      return;
    }
    // Right after a reset, until an ant arrives, there is no restart-best: nothing deposits.
    const aco::Ant* scheduled = restarts_ == 0 ? &best : restart_best_.edges.empty() ? nullptr : &restart_best_;
    const int since = c.iteration - restart_iteration_;
    const aco::Ant* depositor =
        it.best == nullptr || (since + 1) % best_so_far_period(since) == 0 ? scheduled : it.best;
    static const aco::Ant kNobody;
    const aco::Ant& depositing = depositor != nullptr ? *depositor : kNobody;
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
      for (aco::EdgeId e : depositing.edges) evaporated_.push_back(trail[e]);
    } else {
      for (aco::EdgeId e : depositing.edges) evaporated_.push_back((1.0 - p_.rho) * trail[e]);
      trail.evaporate(p_.rho);
    }
    trail.bound(tau_min, tau_max);
    for (std::size_t i = 0; i < depositing.edges.size(); ++i)
      trail.set(depositing.edges[i], evaporated_[i] + p_.q / depositing.length);
  }

  // The same rule on plain values (callers other than the engine): every edge evaporated and
  // bounded at once.
  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    aco::Trail trail(tau);
    update_trail(c, it, trail);
    trail.values();
  }

 private:
  // ACOTSP's trigger: the restart-best has not improved for restart_after iterations and (with
  // restart_branching) the colony has converged: the mean lambda-branching factor, over the nodes
  // of the restart-best walk, is below restart_branching. Two readings differ from ACOTSP's, which
  // counts over every city the edges above min + lambda (max - min) of the city's own edges: on a
  // grid most nodes are never walked, so only the walk's nodes count; and the cut-off is lambda of
  // the way from tau_min to tau_max, since a walked node's other edges decay together and would
  // fall below the node's own cut-off after one iteration, long before ants stop taking them.
  bool restart_due(const aco::Context& c, const aco::Ant& restart_best, const aco::Trail& trail, double tau_min,
                   double tau_max) const {
    if (p_.restart_after <= 0 || c.iteration - restart_found_ < p_.restart_after) return false;
    if (p_.restart_branching <= 0.0 || restart_best.edges.empty()) return true;
    const aco::Graph& g = *c.graph;
    const double cutoff = tau_min + kLambda * (tau_max - tau_min);
    double branches = 0.0;
    for (std::size_t i = 0; i + 1 < restart_best.nodes.size(); ++i)
      for (aco::EdgeId e = g.edges_begin(restart_best.nodes[i]); e < g.edges_end(restart_best.nodes[i]); ++e)
        branches += trail[e] > cutoff;
    return branches / double(restart_best.edges.size()) < p_.restart_branching;
  }

  // The best-so-far (after a reset, the restart-best) deposits every period-th iteration,
  // counted from the start or the last reset.
  int best_so_far_period(int iteration) const {
    if (p_.best_so_far_every > 0) return static_cast<int>(p_.best_so_far_every);
    return iteration < 25 ? 25 : iteration < 75 ? 5 : iteration < 125 ? 3 : iteration < 250 ? 2 : 1;
  }

  Parameters p_;
  double choices_ = 1.0;
  static constexpr double kLambda = 0.05;  // ACOTSP's lambda for the branching factor
  int restarts_ = 0;
  double restart_length_ = std::numeric_limits<double>::infinity();  // before the first reset
  aco::Ant restart_best_;  // after a reset: none (no edges) until an ant arrives
  int restart_found_ = 0;  // the iteration restart_best_ was found in, or of the last reset
  int restart_iteration_ = 0;  // of the last reset, 0 before any
  bool bounded_ = false;
  std::vector<double> evaporated_;  // per edge of the depositor, reused from iteration to iteration
};

}  // namespace

ACO_PLUGIN(
    update, max_min, MaxMinUpdate, "1.0",
    "MAX-MIN Ant System: only the iteration-best (or best-so-far) ant deposits; tau bounded in [tau_min, tau_max]",
    kParams)
