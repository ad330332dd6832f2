// Uniform initial pheromone: every edge starts at tau0.
#include <algorithm>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double tau0 = 8.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("tau0", &Parameters::tau0, "(0:1e12]", "initial pheromone of every edge (the MATLAB code uses 8)"),
});

class UniformInit final : public aco::PheromoneInit {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit UniformInit(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  void initialize(const aco::Context&, std::span<double> tau) override { std::fill(tau.begin(), tau.end(), p_.tau0); }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(init, uniform, UniformInit, "1.0", "every edge starts with the same pheromone tau0", kParams)
