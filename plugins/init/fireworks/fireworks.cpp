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
struct Parameters {
  double tau0 = 8.0;
  double q = 320.0;
  aco::FireworksSettings search;
};

// The plugin's own parameters, then the whole fireworks table.
const aco::SettingsTable<Parameters> kParams(
    {
        aco::field("tau0", &Parameters::tau0, "(0:1e12]",
                   "pheromone of every edge before the increment (uniform's default)"),
        aco::field(
            "q", &Parameters::q, "0:1e12",
            "increment constant Q: each edge of the fireworks' best path gets Q / L_best more (320: about tau0 on a "
            "20x20 map)"),
    },
    aco::nested(&Parameters::search, aco::fireworks_table().fields()));

class FireworksInit final : public aco::PheromoneInit {
 public:
  explicit FireworksInit(const aco::ParameterValues& values) : p_(kParams.read(values)) { aco::check(p_.search); }

  void initialize(const aco::Context& c, std::span<double> tau) override {
    std::fill(tau.begin(), tau.end(), p_.tau0);
    const aco::PlannerResult best = aco::run_fireworks(*c.graph, c.start, c.goal, settings(c));
    if (!best.solved || best.length <= 0.0) return;  // nothing to seed: unreachable goal, or start == goal
    for (std::size_t i = 1; i < best.path.size(); ++i)
      tau[c.graph->find_edge(best.path[i - 1], best.path[i])] += p_.q / best.length;
  }

  // The search's seed is derived from the run's, so the fireworks and the ants (which key their
  // streams the same way) never draw the same numbers.
  aco::FireworksSettings settings(const aco::Context& c) const {
    aco::FireworksSettings s = p_.search;
    s.seed = aco::splitmix64(c.seed);
    return s;
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(init, fireworks, FireworksInit, "1.0",
           "paper 004: tau0 everywhere plus Q / L_best on the edges of the best path of a fireworks (IFWA) search",
           kParams)
