// Ant System (Dorigo 1996): tau = (1 - rho) * tau + sum over arrived ants k of Q / L_k on k's edges.
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double rho = 0.3;
  double q = 1.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "0:1", "evaporation rate"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q: an ant of length L deposits Q / L"),
});

class AntSystemUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit AntSystemUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  void update(const aco::Context&, const aco::Iteration& iteration, std::span<double> tau) override {
    aco::evaporate(tau, p_.rho);
    for (const aco::Ant& ant : iteration.ants)
      if (ant.arrived) aco::deposit(tau, ant, p_.q / ant.length);
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(update, ant_system, AntSystemUpdate, "1.0", "Ant System: evaporate by rho, every arrived ant deposits Q/L",
           kParams)
