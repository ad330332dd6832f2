#include "aco/strategies.hpp"

#include "aco/map_reader.hpp"

#include <tbb/blocked_range.h>

#include <cmath>

#include "aco/error.hpp"
#include "aco/parallel.hpp"

namespace aco {

// Out-of-line destructors give each interface one home for its vtable and type_info (in
// libaco), so dynamic_cast and exceptions work across plugin libraries.
Strategy::~Strategy() = default;
PheromoneInit::~PheromoneInit() = default;
Heuristic::~Heuristic() = default;
PheromoneUpdate::~PheromoneUpdate() = default;
DeadlockPolicy::~DeadlockPolicy() = default;
Smoother::~Smoother() = default;
LocalPlanner::~LocalPlanner() = default;
MapReader::~MapReader() = default;

void Heuristic::compute_powered(const Context& context, std::span<double> eta_beta) {
  compute(context, eta_beta);
  if (context.beta == 1.0) return;
  // Element-wise, so the thread count cannot change a value; on a 512x512 map these are two
  // million pow() calls per run.
  aco::parallel_for(tbb::blocked_range<std::size_t>(0, eta_beta.size(), 16384), [&](const auto& range) {
    for (std::size_t e = range.begin(); e != range.end(); ++e) eta_beta[e] = std::pow(eta_beta[e], context.beta);
  });
}

void Heuristic::update_node(const Context&, NodeId, int, std::span<double>) const {
  throw Error("the heuristic plugin says it updates by node but does not implement update_node()");
}

void Heuristic::step_factors(const Context&, const Ant&, std::span<const EdgeId>, std::span<double> factors) const {
  for (double& f : factors) f = 1.0;
}

void PheromoneUpdate::start(const Context&, std::span<double>) {}

void DeadlockPolicy::after_iteration(const Context&, const Iteration&, std::span<double>, std::vector<std::uint8_t>&) {}

}  // namespace aco
