// Elite update (paper 000, eq. 10-11) in the paper's Ant Colony System set-up (with the colony
// setting q0 = 0.8, the paper's exploitation): local update of walked edges, then
// tau <- (1 - rho) * tau + d_tau + d_tau_elite, where every arrived ant deposits Q / L_k and the
// best elite_fraction of them also elite_q * (it/it_max)^3 / L_k.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"rho", aco::ParamType::real, "0.2", "0:1", "global evaporation rate (paper 000: 0.2)"},
    {"q", aco::ParamType::real, "1", "(0:1e12]", "deposit constant Q: every arrived ant deposits Q / L"},
    {"elite_fraction", aco::ParamType::real, "0.05", "0:1",
     "share of the arrived ants (the shortest) that are elite: max(1, floor(fraction * arrived)); 0 = no elite"},
    {"elite_q", aco::ParamType::real, "1", "0:1e12",
     "elite deposit constant: an elite ant also deposits elite_q * (it / it_max)^3 / L"},
    {"local_rho", aco::ParamType::real, "0.1", "0:1",
     "local evaporation: every edge an ant walked moves towards its starting value by this much (paper 000: 0.1)"},
    {"tau0", aco::ParamType::real, "0", "0:1e12",
     "mean starting pheromone; 0 = ants * Q / d(start, goal), the grid analogue of Ant System's m / C_nn"},
};

class EliteUpdate final : public aco::PheromoneUpdate {
 public:
  explicit EliteUpdate(const aco::ParameterValues& p)
      : rho_(p.real("rho")),
        q_(p.real("q")),
        elite_fraction_(p.real("elite_fraction")),
        elite_q_(p.real("elite_q")),
        tau0_(p.real("tau0")),
        local_(p.real("local_rho")) {}

  void start(const aco::Context& c, std::span<double> tau) override {
    local_.start(tau, tau0_ > 0.0 ? tau0_ : c.ants * q_ / c.graph->distance(c.start, c.goal));
  }

  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    local_.apply(it.ants, tau);
    aco::evaporate(tau, rho_);
    for (const aco::Ant& ant : it.ants)
      if (ant.arrived) aco::deposit(tau, ant, q_ / ant.length);
    // The shortest ants are the elite; ties go to the lower ant index.
    const std::vector<const aco::Ant*> arrived = aco::arrived_by_length(it.ants);
    const std::size_t elites = elite_count(arrived.size());
    const double progress = double(c.iteration + 1) / c.max_iterations;
    const double elite_q = elite_q_ * progress * progress * progress;
    for (std::size_t k = 0; k < elites; ++k) aco::deposit(tau, *arrived[k], elite_q / arrived[k]->length);
  }

  // max(1, floor(fraction * arrived)): the elite are within the best fraction, and there is at
  // least one while any ant arrived (5 % of 50 ants = 2).
  std::size_t elite_count(std::size_t arrived) const {
    if (arrived == 0 || elite_fraction_ == 0.0) return 0;
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(elite_fraction_ * double(arrived))));
  }

 private:
  double rho_;
  double q_;
  double elite_fraction_;
  double elite_q_;
  double tau0_;
  aco::LocalUpdate local_;
};

}  // namespace

ACO_PLUGIN(update, elite, EliteUpdate, "1.0",
           "paper 000 (with --q0 0.8): ACS-style local update; every arrived ant deposits Q/L, the best 5 % also (it/it_max)^3 / L",
           kParams)
