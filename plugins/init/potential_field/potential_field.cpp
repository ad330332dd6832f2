// Potential-field initial pheromone (paper 000, eq. 14): tau(0) = tau0 * F'_tot, read per edge
// i -> j as tau0 * (floor + (1 - floor) * s), s = (1 + clamp(F_tot(i) . u_ij / k, -1, 1)) / 2 in
// [0, 1]: the pheromone is high on moves that follow the force at i (towards the goal, away
// from obstacles and high ground) and low on moves against it.
#include <algorithm>
#include <vector>

#include "aco/plugin.hpp"
#include "aco/potential_field.hpp"

namespace {

struct Parameters {
  double tau0 = 8.0;
  double floor = 0.1;
  aco::PotentialFieldGains gains;
};

const aco::SettingsTable<Parameters> kParams(
    {
        aco::field("tau0", &Parameters::tau0, "(0:1e12]",
                   "pheromone of a move along a full-strength force (8 = the uniform plugin's tau0)"),
        aco::field("floor", &Parameters::floor, "(0:1]",
                   "share of tau0 a move straight against a full-strength force keeps; 1 = uniform"),
    },
    aco::nested(&Parameters::gains, aco::potential_field_fields()));

class PotentialFieldInit final : public aco::PheromoneInit {
 public:
  explicit PotentialFieldInit(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  bool supports_voxel_worlds() const override { return true; }

  void initialize(const aco::Context& c, std::span<double> tau) override {
    const aco::Graph& g = *c.graph;
    const aco::PotentialField field(g, c.start, c.goal, p_.gains);
    // The force is measured against k, its strength in the open; with k = 0 against theta.
    const double unit = p_.gains.k > 0.0 ? p_.gains.k : std::max(p_.gains.theta, 1e-300);
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) {
      const double along = field.along(e) / unit;
      const double share = 0.5 * (1.0 + std::clamp(along, -1.0, 1.0));
      tau[e] = p_.tau0 * (p_.floor + (1.0 - p_.floor) * share);
    }
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(init, potential_field, PotentialFieldInit, "1.0",
           "paper 000: tau(0) of a move scaled by how well it follows the potential-field force (goal attracts, high "
           "ground repels)",
           kParams)
