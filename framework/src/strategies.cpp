#include "aco/strategies.hpp"

namespace aco {

// Out-of-line destructors give each interface one home for its vtable and type_info (in
// libaco), so dynamic_cast and exceptions work across plugin libraries.
Strategy::~Strategy() = default;
PheromoneInit::~PheromoneInit() = default;
Heuristic::~Heuristic() = default;
PheromoneUpdate::~PheromoneUpdate() = default;
DeadlockPolicy::~DeadlockPolicy() = default;
Smoother::~Smoother() = default;

void Heuristic::step_factors(const Context&, std::span<const NodeId>, std::span<const EdgeId>,
                             std::span<double> factors) const {
  for (double& f : factors) f = 1.0;
}

void PheromoneUpdate::start(const Context&, std::span<double>) {}

void DeadlockPolicy::after_iteration(const Context&, const Iteration&, std::span<double>, std::vector<std::uint8_t>&) {}

}  // namespace aco
