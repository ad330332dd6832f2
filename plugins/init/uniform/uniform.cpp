// Uniform initial pheromone: every edge starts at tau0.
#include <algorithm>

#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"tau0", aco::ParamType::real, "8", "(0:1e12]", "initial pheromone of every edge (the MATLAB code uses 8)"},
};

class UniformInit final : public aco::PheromoneInit {
 public:
  explicit UniformInit(const aco::ParameterValues& p) : tau0_(p.real("tau0")) {}
  void initialize(const aco::Context&, std::span<double> tau) override { std::fill(tau.begin(), tau.end(), tau0_); }

 private:
  double tau0_;
};

}  // namespace

ACO_PLUGIN(init, uniform, UniformInit, "1.0", "every edge starts with the same pheromone tau0", kParams)
