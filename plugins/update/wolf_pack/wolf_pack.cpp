// Wolf-pack pheromone update (paper 003, eq. 10-14): "the strong survive". The best ants of an
// iteration are reinforced, the worst weakened, the ordinary ones deposit under a local
// evaporation factor.
#include <algorithm>
#include <limits>
#include <vector>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double rho = 0.35;
  double q = 10.0;
  double lambda = 0.05;
  double a = 1.0;
  double b = 1.0;
  double c = 1.0;
  std::int64_t best_count = 1;
  std::int64_t worst_count = 1;
  double tau_min = 1e-6;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "0:1", "evaporation rate (paper 003: 0.35)"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q (paper 003: 10)"),
    aco::field("lambda", &Parameters::lambda, "0:1",
               "local evaporation of the ordinary ants' deposit (paper 003: 0.05)"),
    aco::field("a", &Parameters::a, "0:1e6", "weight A of the best ants' reinforcement"),
    aco::field("b", &Parameters::b, "0:1e6", "weight B of the worst ants' weakening"),
    aco::field("c", &Parameters::c, "0:1e6", "weight C of the ordinary ants' deposit"),
    aco::field("best_count", &Parameters::best_count, "1:1000000",
               "how many of the shortest arrived ants count as best"),
    aco::field("worst_count", &Parameters::worst_count, "0:1000000",
               "how many of the longest arrived ants count as worst"),
    aco::field("tau_min", &Parameters::tau_min, "(0:1e12]", "floor: no edge's pheromone falls below it"),
});

class WolfPackUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit WolfPackUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    aco::evaporate(tau, p_.rho);
    const std::vector<const aco::Ant*> ranked = aco::arrived_by_length(it.ants);
    const std::size_t n = ranked.size();
    if (n > 0) {
      const double best = ranked.front()->length, worst = ranked.back()->length, spread = worst - best;
      const std::size_t nb = std::min<std::size_t>(p_.best_count, n);
      const std::size_t nw = std::min<std::size_t>(p_.worst_count, n - nb);
      for (std::size_t i = 0; i < n; ++i) {
        const aco::Ant& ant = *ranked[i];
        if (i < nb)
          aco::deposit(tau, ant, p_.a * p_.q * spread / best);
        else if (i >= n - nw)
          aco::deposit(tau, ant, -p_.b * p_.q * spread / worst);
        else
          aco::deposit(tau, ant, (1.0 - p_.lambda) * p_.c * p_.q / ant.length);
      }
    }
    aco::clamp(tau, p_.tau_min, std::numeric_limits<double>::max());
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(
    update, wolf_pack, WolfPackUpdate, "1.0",
    "paper 003: best ants reinforced by A*Q*(Lw-Lb)/Lb, worst weakened by B*Q*(Lw-Lb)/Lw, others (1-lambda)*C*Q/L",
    kParams)
