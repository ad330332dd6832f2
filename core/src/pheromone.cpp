#include "aco/pheromone.hpp"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <functional>

#include "aco/parallel.hpp"

namespace aco {
namespace {

// Chunks large enough that small maps run in one piece, without task overhead.
constexpr std::size_t kGrain = 1 << 15;

template <class Body>
void for_each_chunk(std::span<double> tau, Body body) {
  aco::parallel_for(tbb::blocked_range<std::size_t>(0, tau.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t e = r.begin(); e != r.end(); ++e) body(tau[e]);
                    });
}

}  // namespace

std::vector<const Ant*> arrived_by_length(std::span<const Ant> ants) {
  std::vector<const Ant*> ranked;
  for (const Ant& ant : ants)
    if (ant.arrived) ranked.push_back(&ant);
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ant* x, const Ant* y) { return x->length < y->length; });
  return ranked;
}

void evaporate(std::span<double> tau, double rho) {
  const double keep = 1.0 - rho;
  for_each_chunk(tau, [keep](double& t) { t *= keep; });
}

void clamp(std::span<double> tau, double low, double high) {
  for_each_chunk(tau, [low, high](double& t) { t = std::clamp(t, low, high); });
}

void rescale_mean(std::span<double> tau, double mean) {
  double sum = 0.0;  // serial: a parallel sum's rounding would depend on the thread count
  for (double t : tau) sum += t;
  if (sum <= 0.0) return;
  const double factor = mean * static_cast<double>(tau.size()) / sum;
  for_each_chunk(tau, [factor](double& t) { t *= factor; });
}

void LocalUpdate::start(std::span<double> tau, double mean) {
  rescale_mean(tau, mean);
  const bool uniform = std::adjacent_find(tau.begin(), tau.end(), std::not_equal_to<>()) == tau.end();
  if (uniform) {
    std::vector<double>().swap(start_);
    uniform_start_ = tau.empty() ? 0.0 : tau.front();
  } else {
    start_.assign(tau.begin(), tau.end());
  }
}

void LocalUpdate::apply(std::span<const Ant> ants, std::span<double> tau) const {
  for (const Ant& ant : ants)
    for (EdgeId e : ant.edges) tau[e] = (1.0 - xi_) * tau[e] + xi_ * (start_.empty() ? uniform_start_ : start_[e]);
}

}  // namespace aco
