#pragma once
// Building blocks shared by pheromone update plugins. The whole-field operations run in
// parallel (element-wise, so the result does not depend on the thread count): on large maps
// they, not the ants, would otherwise dominate an iteration.
#include <boost/config.hpp>
#include <span>

#include "aco/strategies.hpp"

namespace aco {

// tau = (1 - rho) * tau on every edge.
BOOST_SYMBOL_VISIBLE void evaporate(std::span<double> tau, double rho);

// tau = clamp(tau, low, high) on every edge.
BOOST_SYMBOL_VISIBLE void clamp(std::span<double> tau, double low, double high);

// Multiplies the field so its mean over edges is `mean`, keeping its shape.
BOOST_SYMBOL_VISIBLE void rescale_mean(std::span<double> tau, double mean);

// tau += amount on every edge of the ant's walk.
inline void deposit(std::span<double> tau, const Ant& ant, double amount) {
  for (EdgeId e : ant.edges) tau[e] += amount;
}

}  // namespace aco
