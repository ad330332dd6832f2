// Inverse distance to the goal: eta_ij = 1 / d(j, goal).
#include <algorithm>

#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"min_distance", aco::ParamType::real, "0.01", "(0:1]",
     "d(j, goal) is floored at this value, so stepping onto the goal gets eta = 1/min_distance (100, as in the MATLAB code)"},
};

class DistanceHeuristic final : public aco::Heuristic {
 public:
  explicit DistanceHeuristic(const aco::ParameterValues& p) : min_distance_(p.real("min_distance")) {}
  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e)
      eta[e] = 1.0 / std::max(g.distance(g.targets[e], c.goal), min_distance_);
  }

 private:
  double min_distance_;
};

}  // namespace

ACO_PLUGIN(heuristic, distance, DistanceHeuristic, "1.0", "eta = 1 / (straight-line distance from the next node to the goal)",
           kParams)
