// Deadlock clearing (paper 002, section 2.2): a stuck ant is removed at once, the node where it
// got stuck joins a tabu set K_n that no ant enters again in this run, and the pheromone on the
// ant's walk is cleared.
#include <algorithm>
#include <vector>

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
  // node is forbidden only if the goal stays reachable without it. Two local tests settle almost
  // every case without a search of the map (on a 512x512 map one search per dead ant cost more
  // than the ants): a node with at most one open neighbour is a true dead end, and a node whose
  // open neighbours are all connected among themselves cannot separate anything, since every
  // path through it can go round it. Only the remaining nodes (corridor cells) need a search.
  bool keeps_goal_reachable(const aco::Context& c, const std::vector<std::uint8_t>& forbidden, aco::NodeId node) {
    const aco::Graph& g = *c.graph;
    open_.clear();
    for (aco::EdgeId e = g.edges_begin(node); e < g.edges_end(node); ++e)
      if (!forbidden[g.targets[e]]) open_.push_back(g.targets[e]);
    if (open_.size() <= 1 || neighbours_connected(g)) return true;
    return reachable_without(c, forbidden, node);
  }

  // Whether the open neighbours form one group through edges among themselves.
  bool neighbours_connected(const aco::Graph& g) {
    std::vector<std::uint8_t> reached(open_.size(), 0);
    std::vector<std::size_t> stack{0};
    reached[0] = 1;
    std::size_t count = 1;
    while (!stack.empty()) {
      const aco::NodeId n = open_[stack.back()];
      stack.pop_back();
      for (std::size_t j = 0; j < open_.size(); ++j)
        if (!reached[j] && g.find_edge(n, open_[j]) >= 0) {
          reached[j] = 1;
          ++count;
          stack.push_back(j);
        }
    }
    return count == open_.size();
  }

  // Breadth-first search from the start avoiding forbidden nodes and `node`; stamps instead of
  // a fresh visited array per search.
  bool reachable_without(const aco::Context& c, const std::vector<std::uint8_t>& forbidden, aco::NodeId node) {
    const aco::Graph& g = *c.graph;
    if (seen_.size() != forbidden.size()) seen_.assign(forbidden.size(), 0), stamp_ = 0;
    if (++stamp_ == 0) std::fill(seen_.begin(), seen_.end(), 0), stamp_ = 1;
    queue_.clear();
    queue_.push_back(c.start);
    seen_[c.start] = seen_[node] = stamp_;
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const aco::NodeId n = queue_[head];
      if (n == c.goal) return true;
      for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) {
        const aco::NodeId t = g.targets[e];
        if (seen_[t] != stamp_ && !forbidden[t]) {
          seen_[t] = stamp_;
          queue_.push_back(t);
        }
      }
    }
    return false;
  }

  std::vector<aco::NodeId> open_;
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
  std::vector<aco::NodeId> queue_;
  double keep_;
};

}  // namespace

ACO_PLUGIN(deadlock, clear_and_tabu, ClearAndTabu, "1.0",
           "paper 002: a stuck ant is removed, its dead-end node becomes tabu for the run, its walk's pheromone cleared",
           kParams)
