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

struct Parameters {
  double rho = 0.2;
  double q = 1.0;
  double elite_fraction = 0.05;
  double elite_q = 1.0;
  double local_rho = 0.1;
  double tau0 = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "0:1", "global evaporation rate (paper 000: 0.2)"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q: every arrived ant deposits Q / L"),
    aco::field(
        "elite_fraction", &Parameters::elite_fraction, "0:1",
        "share of the arrived ants (the shortest) that are elite: max(1, floor(fraction * arrived)); 0 = no elite"),
    aco::field("elite_q", &Parameters::elite_q, "0:1e12",
               "elite deposit constant: an elite ant also deposits elite_q * (it / it_max)^3 / L"),
    aco::field(
        "local_rho", &Parameters::local_rho, "0:1",
        "local evaporation: every edge an ant walked moves towards its starting value by this much (paper 000: 0.1)"),
    aco::field("tau0", &Parameters::tau0, "0:1e12",
               "mean starting pheromone; 0 = ants * Q / d(start, goal), the grid analogue of Ant System's m / C_nn"),
});

class EliteUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit EliteUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)), local_(p_.local_rho) {}

  void start(const aco::Context& c, std::span<double> tau) override {
    local_.start(tau, p_.tau0 > 0.0 ? p_.tau0 : c.ants * p_.q / c.graph->distance(c.start, c.goal));
  }

  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    local_.apply(it.ants, tau);
    aco::evaporate(tau, p_.rho);
    for (const aco::Ant& ant : it.ants)
      if (ant.arrived) aco::deposit(tau, ant, p_.q / ant.length);
    // The shortest ants are the elite; ties go to the lower ant index.
    const std::vector<const aco::Ant*> arrived = aco::arrived_by_length(it.ants);
    const std::size_t elites = elite_count(arrived.size());
    const double progress = double(c.iteration + 1) / c.max_iterations;
    const double elite_q = p_.elite_q * progress * progress * progress;
    for (std::size_t k = 0; k < elites; ++k) aco::deposit(tau, *arrived[k], elite_q / arrived[k]->length);
  }

  // max(1, floor(fraction * arrived)): the elite are within the best fraction, and there is at
  // least one while any ant arrived (5 % of 50 ants = 2).
  std::size_t elite_count(std::size_t arrived) const {
    if (arrived == 0 || p_.elite_fraction == 0.0) return 0;
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(p_.elite_fraction * double(arrived))));
  }

 private:
  Parameters p_;
  aco::LocalUpdate local_;
};

}  // namespace

ACO_PLUGIN(update, elite, EliteUpdate, "1.0",
           "paper 000 (with --q0 0.8): ACS-style local update; every arrived ant deposits Q/L, the best 5 % also "
           "(it/it_max)^3 / L",
           kParams)
