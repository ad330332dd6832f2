// Ant Colony System (Dorigo and Gambardella 1997): pseudo-random proportional rule, local
// update towards tau0, global update on the best-so-far path only.
#include <vector>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"rho", aco::ParamType::real, "0.3", "(0:1]", "global evaporation on the best-so-far path"},
    {"xi", aco::ParamType::real, "0.1", "0:1", "local evaporation: every edge an ant used moves towards tau0 by xi"},
    {"q0", aco::ParamType::real, "0.7", "0:1", "probability of taking the best candidate instead of the roulette"},
    {"q", aco::ParamType::real, "1", "(0:1e12]", "deposit constant Q: the best-so-far path receives rho * Q / L"},
    {"tau0", aco::ParamType::real, "0", "0:1e12",
     "mean initial pheromone; 0 = Q / d(start, goal)^2, the grid analogue of ACS's 1 / (n * L_nn)"},
};

class AcsUpdate final : public aco::PheromoneUpdate {
 public:
  explicit AcsUpdate(const aco::ParameterValues& p)
      : rho_(p.real("rho")), xi_(p.real("xi")), q0_(p.real("q0")), q_(p.real("q")), tau0_(p.real("tau0")) {}

  double exploitation() const override { return q0_; }

  void start(const aco::Context& c, std::span<double> tau) override {
    const double straight = c.graph->distance(c.start, c.goal);
    aco::rescale_mean(tau, tau0_ > 0.0 ? tau0_ : q_ / (straight * straight));
    initial_.assign(tau.begin(), tau.end());
  }

  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    // Local update. Ants are built in parallel on one pheromone snapshot, so it is applied
    // here, edge by edge in ant order, which keeps runs independent of the thread count.
    for (const aco::Ant& ant : it.ants)
      for (aco::EdgeId e : ant.edges) tau[e] = (1.0 - xi_) * tau[e] + xi_ * initial_[e];
    if (it.best_so_far == nullptr) return;
    const double target = q_ / it.best_so_far->length;
    for (aco::EdgeId e : it.best_so_far->edges) tau[e] = (1.0 - rho_) * tau[e] + rho_ * target;
  }

 private:
  double rho_;
  double xi_;
  double q0_;
  double q_;
  double tau0_;
  std::vector<double> initial_;
};

}  // namespace

ACO_PLUGIN(update, acs, AcsUpdate, "1.0",
           "Ant Colony System: q0 exploitation, local update towards tau0, global update on the best-so-far path",
           kParams)
