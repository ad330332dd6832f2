// Ant System (Dorigo 1996): tau = (1 - rho) * tau + sum over arrived ants k of Q / L_k on k's edges.
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"rho", aco::ParamType::real, "0.3", "0:1", "evaporation rate"},
    {"q", aco::ParamType::real, "1", "(0:1e12]", "deposit constant Q: an ant of length L deposits Q / L"},
};

class AntSystemUpdate final : public aco::PheromoneUpdate {
 public:
  explicit AntSystemUpdate(const aco::ParameterValues& p) : rho_(p.real("rho")), q_(p.real("q")) {}
  void update(const aco::Context&, const aco::Iteration& iteration, std::span<double> tau) override {
    aco::evaporate(tau, rho_);
    for (const aco::Ant& ant : iteration.ants)
      if (ant.arrived) aco::deposit(tau, ant, q_ / ant.length);
  }

 private:
  double rho_;
  double q_;
};

}  // namespace

ACO_PLUGIN(update, ant_system, AntSystemUpdate, "1.0", "Ant System: evaporate by rho, every arrived ant deposits Q/L",
           kParams)
