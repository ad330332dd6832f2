// Fireworks seeding (paper 004, eq. 10): the improved fireworks algorithm searches a path from
// start to goal first (coarse search); every edge starts at tau0, and the edges of the
// fireworks' best path, in the path's direction, get Q / L_best more.
#include <algorithm>
#include <vector>

#include "ifwa/fireworks.hpp"
#include "aco/plugin.hpp"
#include "aco/rng.hpp"

namespace {

// The plugin's own parameters, then the whole fireworks table (built when the library loads).
const std::vector<aco::ParamSpec> kParams = [] {
  std::vector<aco::ParamSpec> table{
      {"tau0", aco::ParamType::real, "8", "(0:1e12]", "pheromone of every edge before the increment (uniform's default)"},
      {"q", aco::ParamType::real, "320", "0:1e12",
       "increment constant Q: each edge of the fireworks' best path gets Q / L_best more (320: about tau0 on a 20x20 map)"},
  };
  const auto search = aco::fireworks_parameters();
  table.insert(table.end(), search.begin(), search.end());
  return table;
}();

class FireworksInit final : public aco::PheromoneInit {
 public:
  explicit FireworksInit(const aco::ParameterValues& p)
      : tau0_(p.real("tau0")), q_(p.real("q")), search_(aco::fireworks_settings(p)) {}

  void initialize(const aco::Context& c, std::span<double> tau) override {
    std::fill(tau.begin(), tau.end(), tau0_);
    const aco::PlannerResult best = aco::run_fireworks(*c.graph, c.start, c.goal, settings(c));
    if (!best.solved || best.length <= 0.0) return;  // nothing to seed: unreachable goal, or start == goal
    for (std::size_t i = 1; i < best.path.size(); ++i) tau[c.graph->find_edge(best.path[i - 1], best.path[i])] += q_ / best.length;
  }

  // The search's seed is derived from the run's, so the fireworks and the ants (which key their
  // streams the same way) never draw the same numbers.
  aco::FireworksSettings settings(const aco::Context& c) const {
    aco::FireworksSettings s = search_;
    s.seed = aco::splitmix64(c.seed);
    return s;
  }

 private:
  double tau0_;
  double q_;
  aco::FireworksSettings search_;
};

}  // namespace

ACO_PLUGIN(init, fireworks, FireworksInit, "1.0",
           "paper 004: tau0 everywhere plus Q / L_best on the edges of the best path of a fireworks (IFWA) search", kParams)
