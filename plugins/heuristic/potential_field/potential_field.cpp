// Potential-field heuristic (paper 000, section 4.5): the distance heuristic boosted on moves that
// follow the potential-field force, strongly early and not at all in the last iteration:
//   eta_ij = (1 / d_jE) * (1 + a * w(it) * max(0, cos phi)),  w(it) = ((it_max - it) / it_max)^3,
// phi the angle between the move i -> j and F_tot(i), it = 1..it_max.
#include <algorithm>
#include <cmath>
#include <vector>

#include "aco/plugin.hpp"
#include "aco/potential_field.hpp"

namespace {

struct Parameters {
  double a = 0.1;
  double min_distance = 0.01;
  aco::PotentialFieldGains gains;
};

const aco::SettingsTable<Parameters> kParams(
    {
        aco::field("a", &Parameters::a, "0:1e6",
                   "weight of the force term: a move along the force gets eta x (1 + a) in the first iteration"),
        aco::field("min_distance", &Parameters::min_distance, "1e-6:1",
                   "d(j, goal) is floored at this value, so stepping onto the goal gets 1/min_distance (as in "
                   "heuristic/distance)"),
    },
    aco::nested(&Parameters::gains, aco::potential_field_fields()));

class PotentialFieldHeuristic final : public aco::Heuristic {
 public:
  explicit PotentialFieldHeuristic(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  // Only w changes between iterations, so a node's edges need nothing from earlier iterations.
  aco::HeuristicSpecs specs() const override { return {.varies_by_iteration = true, .updates_by_node = true}; }
  bool supports_voxel_worlds() const override { return true; }

  // Per edge, once per run: the distance heuristic, a * max(0, cos phi) and base^beta.
  void begin_run(const aco::Context& c) override {
    const aco::Graph& g = *c.graph;
    const aco::PotentialField field(g, c.start, c.goal, p_.gains);
    base_.resize(g.num_edges());
    boost_.resize(g.num_edges());
    base_beta_.resize(g.num_edges());
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) {
      base_[e] = 1.0 / std::max(g.distance(g.targets[e], c.goal), p_.min_distance);
      const double strength = field.strength(e);
      boost_[e] = strength > 0.0 ? p_.a * std::max(0.0, field.along(e) / strength) : 0.0;
      base_beta_[e] = std::pow(base_[e], c.beta);
      if (std::isinf(base_beta_[e])) aco::throw_power_overflow(c.beta);
    }
    beta_ = c.beta;
  }

  void compute(const aco::Context& c, std::span<double> eta) override {
    const double w = weight(c);
    for (std::size_t e = 0; e < eta.size(); ++e) eta[e] = base_[e] * (1.0 + w * boost_[e]);
  }

  // eta^beta = base^beta * (1 + w * boost)^beta: the second factor only on edges with a boost,
  // by multiplications when beta is a whole number.
  void compute_powered(const aco::Context& c, std::span<double> eta_beta) override { powered(weight(c), 0, eta_beta); }

  void update_node(const aco::Context& c, aco::NodeId node, int, std::span<double> eta_beta) const override {
    powered(weight(c), c.graph->offsets[node], eta_beta);
  }

 private:
  // eta^beta of the edges first, first + 1, ... for the weight w.
  void powered(double w, aco::EdgeId first, std::span<double> eta_beta) const {
    const bool whole = beta_ >= 0.0 && beta_ <= 64.0 && beta_ == std::floor(beta_);
    for (std::size_t i = 0; i < eta_beta.size(); ++i) {
      const std::size_t e = first + i;
      if (boost_[e] == 0.0 || w == 0.0) {
        eta_beta[i] = base_beta_[e];
      } else {
        const double factor = 1.0 + w * boost_[e];
        eta_beta[i] = base_beta_[e] * (whole ? whole_power(factor, static_cast<int>(beta_)) : std::pow(factor, beta_));
        if (std::isinf(eta_beta[i])) aco::throw_power_overflow(beta_);  // eta is finite: a and beta too large
      }
    }
  }

  // w(it) = ((it_max - it) / it_max)^3 with it = iteration + 1: just under 1 in the first
  // iteration, 0 in the last.
  static double weight(const aco::Context& c) {
    const double left = double(c.max_iterations - (c.iteration + 1)) / c.max_iterations;
    return std::max(0.0, left * left * left);
  }

  static double whole_power(double x, int n) {
    double result = 1.0;
    for (; n > 0; n >>= 1, x *= x)
      if (n & 1) result *= x;
    return result;
  }

  Parameters p_;
  double beta_ = 0.0;
  std::vector<double> base_;  // per edge: 1 / d(j, goal)
  std::vector<double> boost_;  // per edge: a * max(0, cos phi)
  std::vector<double> base_beta_;  // per edge: base^beta
};

}  // namespace

ACO_PLUGIN(heuristic, potential_field, PotentialFieldHeuristic, "1.0",
           "paper 000: eta = (1 / d_jE) * (1 + a * ((it_max - it) / it_max)^3 * max(0, cos phi)), phi between the move "
           "and the force",
           kParams)
