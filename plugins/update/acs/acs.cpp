// Ant Colony System (Dorigo and Gambardella 1997): local update towards tau0, global update on
// the best-so-far path only. Its pseudo-random proportional rule is the colony setting q0.
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"rho", aco::ParamType::real, "0.3", "(0:1]", "global evaporation on the best-so-far path"},
    {"xi", aco::ParamType::real, "0.1", "0:1", "local evaporation: every edge an ant used moves towards tau0 by xi"},
    {"q", aco::ParamType::real, "1", "(0:1e12]", "deposit constant Q: the best-so-far path receives rho * Q / L"},
    {"tau0", aco::ParamType::real, "0", "0:1e12",
     "mean initial pheromone; 0 = Q / d(start, goal)^2, the grid analogue of ACS's 1 / (n * L_nn)"},
};

class AcsUpdate final : public aco::PheromoneUpdate {
 public:
  explicit AcsUpdate(const aco::ParameterValues& p)
      : rho_(p.real("rho")), q_(p.real("q")), tau0_(p.real("tau0")), local_(p.real("xi")) {}

  void start(const aco::Context& c, std::span<double> tau) override {
    const double straight = c.graph->distance(c.start, c.goal);
    local_.start(tau, tau0_ > 0.0 ? tau0_ : q_ / (straight * straight));
  }

  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    local_.apply(it.ants, tau);
    if (it.best_so_far == nullptr) return;
    const double target = q_ / it.best_so_far->length;
    for (aco::EdgeId e : it.best_so_far->edges) tau[e] = (1.0 - rho_) * tau[e] + rho_ * target;
  }

 private:
  double rho_;
  double q_;
  double tau0_;
  aco::LocalUpdate local_;
};

}  // namespace

ACO_PLUGIN(update, acs, AcsUpdate, "1.0",
           "Ant Colony System: local update towards tau0, global update on the best-so-far path (use with --q0 0.7)",
           kParams)
