// Deadlock clearing (paper 002, section 2.2): a stuck ant is removed at once, the node where it
// got stuck joins a tabu set K_n that no ant enters again in this run, and the pheromone on the
// ant's walk is cleared.
#include <deque>

#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"keep", aco::ParamType::real, "0", "0:1",
     "share of the pheromone kept on the dead ant's edges (0 = cleared, as in the paper)"},
};

class ClearAndTabu final : public aco::DeadlockPolicy {
 public:
  explicit ClearAndTabu(const aco::ParameterValues& p) : keep_(p.real("keep")) {}

  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override { return 0; }

  void after_iteration(const aco::Context& c, const aco::Iteration& it, std::span<double> tau,
                       std::vector<std::uint8_t>& forbidden) override {
    for (const aco::Ant& ant : it.ants) {
      if (ant.arrived) continue;
      for (aco::EdgeId e : ant.edges) tau[e] *= keep_;
      const aco::NodeId dead_end = ant.nodes.back();
      if (dead_end != c.start && !forbidden[dead_end] && keeps_goal_reachable(c, forbidden, dead_end))
        forbidden[dead_end] = 1;
    }
  }

 private:
  // The paper forbids every dead-end node. An ant can also get stuck in open space, walled in by
  // its own tabu list, and forbidding such a node could cut the only corridor to the goal; so a
  // node is forbidden only if the goal stays reachable without it. A node with at most one open
  // neighbour is a true dead end and cannot disconnect anything, so only other nodes need a search.
  static bool keeps_goal_reachable(const aco::Context& c, const std::vector<std::uint8_t>& forbidden, aco::NodeId node) {
    const aco::Graph& g = *c.graph;
    int open = 0;
    for (aco::EdgeId e = g.edges_begin(node); e < g.edges_end(node); ++e) open += !forbidden[g.targets[e]];
    if (open <= 1) return true;
    std::vector<std::uint8_t> seen(forbidden);
    seen[node] = 1;
    std::deque<aco::NodeId> queue{c.start};
    seen[c.start] = 1;
    while (!queue.empty()) {
      const aco::NodeId n = queue.front();
      queue.pop_front();
      if (n == c.goal) return true;
      for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e)
        if (!seen[g.targets[e]]) {
          seen[g.targets[e]] = 1;
          queue.push_back(g.targets[e]);
        }
    }
    return false;
  }

  double keep_;
};

}  // namespace

ACO_PLUGIN(deadlock, clear_and_tabu, ClearAndTabu, "1.0",
           "paper 002: a stuck ant is removed, its dead-end node becomes tabu for the run, its walk's pheromone cleared",
           kParams)
