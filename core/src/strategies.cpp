#include "aco/strategies.hpp"

#include "aco/map_reader.hpp"

#include <tbb/blocked_range.h>

#include <atomic>
#include <cmath>
#include <limits>

#include "aco/error.hpp"
#include "aco/parallel.hpp"
#include "aco/parameters.hpp"

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

void Strategy::begin_run(const Context&) {}
bool Strategy::supports_voxel_worlds() const { return false; }

void Heuristic::compute_powered(const Context& context, std::span<double> eta_beta) {
  compute(context, eta_beta);
  if (context.beta == 1.0) return;
  // Element-wise, so the thread count cannot change a value; on a 512x512 map these are two
  // million pow() calls per run.
  std::atomic<bool> overflowed = false;
  aco::parallel_for(tbb::blocked_range<std::size_t>(0, eta_beta.size(), 16384), [&](const auto& range) {
    for (std::size_t e = range.begin(); e != range.end(); ++e) {
      const double eta = eta_beta[e];
      eta_beta[e] = std::pow(eta, context.beta);
      if (std::isinf(eta_beta[e]) && std::isfinite(eta)) overflowed.store(true, std::memory_order_relaxed);
    }
  });
  if (overflowed) throw_power_overflow(context.beta);
}

void throw_power_overflow(double beta) {
  throw Error("eta^beta overflows on some edge (beyond the largest number, " +
              to_string(ParamValue(std::numeric_limits<double>::max())) + "): at beta " + to_string(ParamValue(beta)) +
              " eta must stay below " +
              to_string(ParamValue(std::pow(std::numeric_limits<double>::max(), 1.0 / beta))) +
              "; lower --beta, or the heuristic's parameters that make eta large");
}

void Heuristic::update_node(const Context&, NodeId, int, std::span<double>) const {
  throw Error("the heuristic plugin's specs() say it updates by node but it does not implement update_node()");
}

void Heuristic::step_factors(const Context&, const Ant&, std::span<const EdgeId>, std::span<double> factors) const {
  for (double& f : factors) f = 1.0;
}

void PheromoneUpdate::start(const Context&, std::span<double>) {}

void PheromoneUpdate::update_trail(const Context& context, const Iteration& iteration, Trail& trail) {
  update(context, iteration, trail.values());
}

void DeadlockPolicy::after_iteration(const Context&, const Iteration&, Trail&, std::vector<std::uint8_t>&) {}

namespace {

// Element-wise over the stored values, so the thread count cannot change one.
template <class Body>
void for_each_stored(std::span<double> stored, Body body) {
  aco::parallel_for(tbb::blocked_range<std::size_t>(0, stored.size(), 1 << 15), [&](const auto& range) {
    for (std::size_t e = range.begin(); e != range.end(); ++e) body(stored[e]);
  });
}

}  // namespace

void Trail::evaporate(double rho) {
  scale_ *= 1.0 - rho;
  // Deposits divide by the scale: keep it far from underflow (rho = 1 makes it 0 at once).
  if (scale_ < 1e-100) {
    const double scale = scale_;
    for_each_stored(stored_, [scale](double& s) { s *= scale; });
    scale_ = 1.0;
  }
}

void Trail::bound(double low, double high) {
  low_ = low;
  high_ = high;
}

void Trail::fill(double tau) {
  scale_ = 1.0;
  std::fill(stored_.begin(), stored_.end(), tau);
}

std::span<double> Trail::values() {
  if (!plain()) {
    const double scale = scale_, low = low_, high = high_;
    // A negative or NaN value stays as it is, for the engine's check to name its writer.
    for_each_stored(stored_, [=](double& s) {
      if (s >= 0.0) s = std::clamp(s * scale, low, high);
    });
    scale_ = 1.0;
  }
  return stored_;
}

}  // namespace aco
