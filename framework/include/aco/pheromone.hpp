#pragma once
// Building blocks shared by pheromone update plugins.
#include <algorithm>
#include <span>

#include "aco/strategies.hpp"

namespace aco {

// tau = (1 - rho) * tau on every edge.
inline void evaporate(std::span<double> tau, double rho) {
  const double keep = 1.0 - rho;
  for (double& t : tau) t *= keep;
}

// tau += amount on every edge of the ant's walk.
inline void deposit(std::span<double> tau, const Ant& ant, double amount) {
  for (EdgeId e : ant.edges) tau[e] += amount;
}

inline void clamp(std::span<double> tau, double low, double high) {
  for (double& t : tau) t = std::clamp(t, low, high);
}

// Multiplies the field so its mean over edges is `mean`, keeping its shape.
inline void rescale_mean(std::span<double> tau, double mean) {
  double sum = 0.0;
  for (double t : tau) sum += t;
  if (sum <= 0.0) return;
  const double factor = mean * static_cast<double>(tau.size()) / sum;
  for (double& t : tau) t *= factor;
}

}  // namespace aco
