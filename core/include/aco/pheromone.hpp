#pragma once
// Building blocks shared by pheromone update plugins. The whole-field operations run in
// parallel (element-wise, so the result does not depend on the thread count): on large maps
// they, not the ants, would otherwise dominate an iteration.
#include <boost/config.hpp>
#include <span>
#include <vector>

#include "aco/strategies.hpp"

namespace aco {

// tau = (1 - rho) * tau on every edge.
BOOST_SYMBOL_VISIBLE void evaporate(std::span<double> tau, double rho);

// tau = clamp(tau, low, high) on every edge.
BOOST_SYMBOL_VISIBLE void clamp(std::span<double> tau, double low, double high);

// Multiplies the field so its mean over edges is `mean`, keeping its shape.
BOOST_SYMBOL_VISIBLE void rescale_mean(std::span<double> tau, double mean);

// The arrived ants, shortest first; ties keep ant order, so the ranking is deterministic.
BOOST_SYMBOL_VISIBLE std::vector<const Ant*> arrived_by_length(std::span<const Ant> ants);

// tau += amount on every edge of the ant's walk.
inline void deposit(std::span<double> tau, const Ant& ant, double amount) {
  for (EdgeId e : ant.edges) tau[e] += amount;
}

// Ant Colony System's local update (Dorigo and Gambardella 1997): every edge an ant walked moves
// back towards its starting value, tau <- (1 - xi) * tau + xi * tau_start. ACS applies it after
// each step; here ants of an iteration are built in parallel on one pheromone snapshot, so it
// is applied after construction, edge by edge in ant order, which keeps runs independent of the
// thread count (ants of one iteration do not repel each other).
class BOOST_SYMBOL_VISIBLE LocalUpdate {
 public:
  explicit LocalUpdate(double xi) : xi_(xi) {}
  // Scales the init plugin's field to the given mean, keeping its shape, and remembers the
  // result as the starting values. Call once per run, from PheromoneUpdate::start().
  void start(std::span<double> tau, double mean);
  // The local update for every step of every ant (arrived or not).
  void apply(std::span<const Ant> ants, std::span<double> tau) const;

 private:
  double xi_;
  // The starting values: one number when they are all equal (the uniform init), else per edge. A
  // copy of a voxel world's field would be the colony's largest array after the field itself.
  std::vector<double> start_;
  double uniform_start_ = 0.0;
};

}  // namespace aco
