// Adaptive heuristic (paper 003, eq. 9): eta_ij = 1 / (d_ij + d_jE), faded over the iterations
// by w(Nc) = 1 + (Nc_max - Nc) / Nc_max, which runs from 2 down to 1.
#include <cmath>
#include <vector>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  bool exponent = true;
};

const aco::SettingsTable<Parameters> kParams({
    aco::choice(
        "fade", &Parameters::exponent, {"exponent", "factor"}, {true, false},
        "how w(Nc) applies: eta = base^w (exponent: the heuristic's weight halves over the run) or eta = base * w "
        "(factor: eq. 9 read literally; w is the same for every candidate and cancels in the transition rule)"),
});

class AdaptiveHeuristic final : public aco::Heuristic {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit AdaptiveHeuristic(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  // The same multiplications, in the same order, for the iterations a node missed (update_node()).
  aco::HeuristicSpecs specs() const override { return {.varies_by_iteration = true, .updates_by_node = true}; }

  void compute(const aco::Context& c, std::span<double> eta) override {
    const double w = weight(c);
    const aco::Graph& g = *c.graph;
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) {
      const double base = 1.0 / (g.cost(e) + g.distance(g.targets[e], c.goal));
      eta[e] = p_.exponent ? std::pow(base, w) : base * w;
    }
  }

  // eta^beta = base^(beta * w) (exponent) or (base * w)^beta (factor). w falls by 1/Nc_max each
  // iteration, so each iteration multiplies eta^beta by a per-edge constant: one multiplication
  // per edge instead of a pow().
  void compute_powered(const aco::Context& c, std::span<double> eta_beta) override {
    const aco::Graph& g = *c.graph;
    if (c.iteration == 0 || step_.size() != eta_beta.size()) {
      compute(c, eta_beta);
      step_.resize(eta_beta.size());
      const double dw = -1.0 / c.max_iterations;
      for (aco::EdgeId e = 0; e < g.num_edges(); ++e) {
        const double base = 1.0 / (g.cost(e) + g.distance(g.targets[e], c.goal));
        eta_beta[e] = std::pow(eta_beta[e], c.beta);
        step_[e] = p_.exponent ? std::pow(base, c.beta * dw) : 0.0;
      }
      return;
    }
    advance(c, c.iteration - 1, 0, eta_beta);
  }

  void update_node(const aco::Context& c, aco::NodeId node, int since, std::span<double> eta_beta) const override {
    advance(c, since, c.graph->offsets[node], eta_beta);
  }

 private:
  // Brings eta^beta of the edges first, first + 1, ... from iteration `since` to c.iteration.
  void advance(const aco::Context& c, int since, aco::EdgeId first, std::span<double> eta_beta) const {
    for (int it = since + 1; it <= c.iteration; ++it) {
      if (p_.exponent) {
        for (std::size_t i = 0; i < eta_beta.size(); ++i) eta_beta[i] *= step_[first + i];
      } else {
        // (base * w)^beta: the same factor (w_now / w_before)^beta for every edge.
        const double f = std::pow(weight(it, c.max_iterations) / weight(it - 1, c.max_iterations), c.beta);
        for (double& v : eta_beta) v *= f;
      }
    }
  }

  static double weight(const aco::Context& c) { return weight(c.iteration, c.max_iterations); }
  static double weight(int iteration, int max_iterations) {
    const double nc = iteration + 1, nc_max = max_iterations;
    return 1.0 + (nc_max - nc) / nc_max;
  }

  Parameters p_;
  std::vector<double> step_;  // per edge: what eta^beta is multiplied by each iteration (exponent)
};

}  // namespace

ACO_PLUGIN(heuristic, adaptive, AdaptiveHeuristic, "1.0",
           "paper 003: eta = 1 / (d_ij + d_jE), faded from strong to normal over the iterations", kParams)
