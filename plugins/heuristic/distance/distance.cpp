// Inverse distance to the goal: eta_ij = 1 / d(j, goal).
#include <algorithm>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double min_distance = 0.01;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field(
        "min_distance", &Parameters::min_distance, "1e-6:1",
        "d(j, goal) is floored at this value, so stepping onto the goal gets eta = 1/min_distance (100, as in the "
        "MATLAB code)"),
});

class DistanceHeuristic final : public aco::Heuristic {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit DistanceHeuristic(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e)
      eta[e] = 1.0 / std::max(g.distance(g.targets[e], c.goal), p_.min_distance);
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(heuristic, distance, DistanceHeuristic, "1.0",
           "eta = 1 / (straight-line distance from the next node to the goal)", kParams)
