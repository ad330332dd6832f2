// Progress towards the goal per unit of step cost: eta_ij = f + (1 - f) (1 + r_ij) / 2 with
// r_ij = (d(i, goal) - d(j, goal)) / c_ij in [-1, 1]. Unlike 1/d(j, goal), it does not fade with
// the distance to the goal, so a step straight at the goal is preferred as strongly 500 cells
// away as next to it.
#include <algorithm>
#include <cmath>

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
  // Computed by node, when an ant first stands on one (HeuristicSpecs::updates_by_node): on a
  // large map the ants see a fraction of its edges.
  aco::HeuristicSpecs specs() const override { return {.updates_by_node = true}; }

  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    for (aco::NodeId i = 0; i < g.num_nodes(); ++i) {
      const double from = g.distance(i, c.goal);
      for (aco::EdgeId e = g.edges_begin(i); e < g.edges_end(i); ++e) eta[e] = of_edge(g, c.goal, from, e);
    }
  }

  // compute_powered()'s values for one node: eta, raised to beta as the engine's default does.
  void update_node(const aco::Context& c, aco::NodeId node, int, std::span<double> eta_beta) const override {
    const aco::Graph& g = *c.graph;
    const double from = g.distance(node, c.goal);
    for (aco::EdgeId e = g.edges_begin(node); e < g.edges_end(node); ++e) {
      const double eta = of_edge(g, c.goal, from, e);
      eta_beta[static_cast<std::size_t>(e - g.edges_begin(node))] = c.beta == 1.0 ? eta : std::pow(eta, c.beta);
    }
  }

 private:
  // eta of edge e, whose source node is `from` cells (its distance) from the goal.
  double of_edge(const aco::Graph& g, aco::NodeId goal, double from, aco::EdgeId e) const {
    const double r = std::clamp((from - g.distance(g.targets[e], goal)) / g.cost(e), -1.0, 1.0);
    return p_.floor + (1.0 - p_.floor) * 0.5 * (1.0 + r);
  }

  Parameters p_;
};

}  // namespace

ACO_PLUGIN(heuristic, progress, ProgressHeuristic, "1.0",
           "eta = floor + (1 - floor) (1 + r) / 2, r = progress towards the goal per unit step cost: scale-free, for "
           "large maps",
           kParams)
