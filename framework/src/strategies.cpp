#include "aco/strategies.hpp"

#include <cmath>

namespace aco {

// Out-of-line destructors give each interface one home for its vtable and type_info (in
// libaco), so dynamic_cast and exceptions work across plugin libraries.
Strategy::~Strategy() = default;
PheromoneInit::~PheromoneInit() = default;
Heuristic::~Heuristic() = default;
PheromoneUpdate::~PheromoneUpdate() = default;
DeadlockPolicy::~DeadlockPolicy() = default;
Smoother::~Smoother() = default;

void Heuristic::compute_powered(const Context& context, std::span<double> eta_beta) {
  compute(context, eta_beta);
  if (context.beta == 1.0) return;
  for (double& v : eta_beta) v = std::pow(v, context.beta);
}

void Heuristic::step_factors(const Context&, const Ant&, std::span<const EdgeId>, std::span<double> factors) const {
  for (double& f : factors) f = 1.0;
}

void PheromoneUpdate::start(const Context&, std::span<double>) {}

void DeadlockPolicy::after_iteration(const Context&, const Iteration&, std::span<double>, std::vector<std::uint8_t>&) {}

}  // namespace aco
