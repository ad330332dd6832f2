// Ant Colony System (Dorigo and Gambardella 1997): local update towards tau0, global update on
// the best-so-far path only. Its pseudo-random proportional rule is the colony setting q0.
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double rho = 0.3;
  double xi = 0.1;
  double q = 1.0;
  double tau0 = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "(0:1]", "global evaporation on the best-so-far path"),
    aco::field("xi", &Parameters::xi, "0:1", "local evaporation: every edge an ant used moves towards tau0 by xi"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q: the best-so-far path receives rho * Q / L"),
    aco::field("tau0", &Parameters::tau0, "0:1e12",
               "mean initial pheromone; 0 = Q / d(start, goal)^2, the grid analogue of ACS's 1 / (n * L_nn)"),
});

class AcsUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit AcsUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)), local_(p_.xi) {}

  void start(const aco::Context& c, std::span<double> tau) override {
    const double straight = c.graph->distance(c.start, c.goal);
    local_.start(tau, p_.tau0 > 0.0 ? p_.tau0 : p_.q / (straight * straight));
  }

  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    local_.apply(it.ants, tau);
    if (it.best_so_far == nullptr) return;
    const double target = p_.q / it.best_so_far->length;
    for (aco::EdgeId e : it.best_so_far->edges) tau[e] = (1.0 - p_.rho) * tau[e] + p_.rho * target;
  }

 private:
  Parameters p_;
  aco::LocalUpdate local_;
};

}  // namespace

ACO_PLUGIN(update, acs, AcsUpdate, "1.0",
           "Ant Colony System: local update towards tau0, global update on the best-so-far path (use with --q0 0.7)",
           kParams)
