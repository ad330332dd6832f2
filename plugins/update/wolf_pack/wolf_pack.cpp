// Wolf-pack pheromone update (paper 003, eq. 10-14): "the strong survive". The best ants of an
// iteration are reinforced, the worst weakened, the ordinary ones deposit under a local
// evaporation factor.
#include <algorithm>
#include <limits>
#include <vector>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"rho", aco::ParamType::real, "0.35", "0:1", "evaporation rate (paper 003: 0.35)"},
    {"q", aco::ParamType::real, "10", "(0:1e12]", "deposit constant Q (paper 003: 10)"},
    {"lambda", aco::ParamType::real, "0.05", "0:1", "local evaporation of the ordinary ants' deposit (paper 003: 0.05)"},
    {"a", aco::ParamType::real, "1", "0:1e6", "weight A of the best ants' reinforcement"},
    {"b", aco::ParamType::real, "1", "0:1e6", "weight B of the worst ants' weakening"},
    {"c", aco::ParamType::real, "1", "0:1e6", "weight C of the ordinary ants' deposit"},
    {"best_count", aco::ParamType::integer, "1", "1:1000000", "how many of the shortest arrived ants count as best"},
    {"worst_count", aco::ParamType::integer, "1", "0:1000000", "how many of the longest arrived ants count as worst"},
    {"tau_min", aco::ParamType::real, "1e-6", "(0:1e12]", "floor: no edge's pheromone falls below it"},
};

class WolfPackUpdate final : public aco::PheromoneUpdate {
 public:
  explicit WolfPackUpdate(const aco::ParameterValues& p)
      : rho_(p.real("rho")),
        q_(p.real("q")),
        lambda_(p.real("lambda")),
        a_(p.real("a")),
        b_(p.real("b")),
        c_(p.real("c")),
        best_count_(p.integer("best_count")),
        worst_count_(p.integer("worst_count")),
        tau_min_(p.real("tau_min")) {}

  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    aco::evaporate(tau, rho_);
    const std::vector<const aco::Ant*> ranked = aco::arrived_by_length(it.ants);
    const std::size_t n = ranked.size();
    if (n > 0) {
      const double best = ranked.front()->length, worst = ranked.back()->length, spread = worst - best;
      const std::size_t nb = std::min<std::size_t>(best_count_, n);
      const std::size_t nw = std::min<std::size_t>(worst_count_, n - nb);
      for (std::size_t i = 0; i < n; ++i) {
        const aco::Ant& ant = *ranked[i];
        if (i < nb) aco::deposit(tau, ant, a_ * q_ * spread / best);
        else if (i >= n - nw) aco::deposit(tau, ant, -b_ * q_ * spread / worst);
        else aco::deposit(tau, ant, (1.0 - lambda_) * c_ * q_ / ant.length);
      }
    }
    aco::clamp(tau, tau_min_, std::numeric_limits<double>::max());
  }

 private:
  double rho_, q_, lambda_, a_, b_, c_;
  std::int64_t best_count_, worst_count_;
  double tau_min_;
};

}  // namespace

ACO_PLUGIN(update, wolf_pack, WolfPackUpdate, "1.0",
           "paper 003: best ants reinforced by A*Q*(Lw-Lb)/Lb, worst weakened by B*Q*(Lw-Lb)/Lw, others (1-lambda)*C*Q/L",
           kParams)
