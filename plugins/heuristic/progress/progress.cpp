// Progress towards the goal per unit of step cost: eta_ij = f + (1 - f) (1 + r_ij) / 2 with
// r_ij = (d(i, goal) - d(j, goal)) / c_ij in [-1, 1]. Unlike 1/d(j, goal), it does not fade with
// the distance to the goal, so a step straight at the goal is preferred as strongly 500 cells
// away as next to it.
#include <algorithm>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double floor = 0.3;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field(
        "floor", &Parameters::floor, "(0:1]",
        "eta of a step straight away from the goal (a step straight at it has 1, a sideways step (1 + floor) / 2)"),
});

class ProgressHeuristic final : public aco::Heuristic {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit ProgressHeuristic(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    for (aco::NodeId i = 0; i < g.num_nodes(); ++i) {
      if (g.degree(i) == 0) continue;
      const double from = g.distance(i, c.goal);
      for (aco::EdgeId e = g.edges_begin(i); e < g.edges_end(i); ++e) {
        const double r = std::clamp((from - g.distance(g.targets[e], c.goal)) / g.cost(e), -1.0, 1.0);
        eta[e] = p_.floor + (1.0 - p_.floor) * 0.5 * (1.0 + r);
      }
    }
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(heuristic, progress, ProgressHeuristic, "1.0",
           "eta = floor + (1 - floor) (1 + r) / 2, r = progress towards the goal per unit step cost: scale-free, for "
           "large maps",
           kParams)
