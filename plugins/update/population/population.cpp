// Population-based ACO (Guntsch and Middendorf 2002): the pheromone is the init plugin's field
// plus a fixed deposit on every edge of each path in a small population. A path enters the
// population and later leaves it with the same deposit, so the field never drifts towards one
// path beyond `ratio` times its initial value, whatever the path length: the trail is a bounded,
// scale-free bias, never a lock.
#include <algorithm>
#include <deque>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  std::int64_t size = 5;
  double ratio = 4.0;
  bool by_age = false;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("size", &Parameters::size, "1:1000", "number of paths in the population (k)"),
    aco::field("ratio", &Parameters::ratio, "(1:1e6]",
               "tau_max / tau_init: an edge on every population path has `ratio` times its initial pheromone"),
    aco::choice("replace", &Parameters::by_age, {"quality", "age"}, {false, true},
                "quality = the k shortest distinct paths found so far; age = the last k iteration-best paths (first "
                "in, first out)"),
});

class PopulationUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit PopulationUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  void begin_run(const aco::Context&) override { population_.clear(); }

  void start(const aco::Context&, std::span<double> tau) override {
    // With the field's mean at 1 the deposit is a fraction of it, independent of the map's scale.
    aco::rescale_mean(tau, 1.0);
    delta_ = (p_.ratio - 1.0) / static_cast<double>(p_.size);
  }

  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    if (it.best == nullptr) return;
    const aco::Ant& candidate = *it.best;
    if (p_.by_age) {
      if (population_.size() == static_cast<std::size_t>(p_.size)) leave(population_.begin(), tau);
      enter(population_.end(), candidate, tau);
      return;
    }
    // Quality: shortest first; a path already in the population does not enter twice.
    const auto same = [&](const aco::Ant& a) { return a.length == candidate.length && a.nodes == candidate.nodes; };
    if (std::any_of(population_.begin(), population_.end(), same)) return;
    if (population_.size() == static_cast<std::size_t>(p_.size)) {
      if (candidate.length >= population_.back().length) return;
      leave(population_.end() - 1, tau);
    }
    const auto at = std::upper_bound(population_.begin(), population_.end(), candidate.length,
                                     [](double length, const aco::Ant& a) { return length < a.length; });
    enter(at, candidate, tau);
  }

 private:
  void enter(std::deque<aco::Ant>::iterator at, const aco::Ant& ant, std::span<double> tau) {
    aco::deposit(tau, ant, delta_);
    population_.insert(at, ant);
  }
  void leave(std::deque<aco::Ant>::iterator at, std::span<double> tau) {
    // Subtracting what was added leaves rounding residue of order 1e-16; never below 0 as the
    // initial field is positive.
    for (aco::EdgeId e : at->edges) tau[e] = std::max(tau[e] - delta_, 0.0);
    population_.erase(at);
  }

  Parameters p_;
  double delta_ = 0.0;
  std::deque<aco::Ant> population_;
};

}  // namespace

ACO_PLUGIN(update, population, PopulationUpdate, "1.0",
           "population-based ACO: init field plus a fixed deposit per path of a population of k paths (bounded, "
           "scale-free trail)",
           kParams)
