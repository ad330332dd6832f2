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
  // node is forbidden only if the goal stays reachable without it. One search of the map per
  // dead ant cost more than the ants on a 512x512 map, so the plugin keeps one open start-goal
  // path as a witness: a node off it can go, since the witness survives without it. For a node
  // on it, a small search for a way round it between its two witness neighbours repairs the
  // witness; only if none is found nearby is the whole map searched. The answers are the same as
  // a search per node.
  bool keeps_goal_reachable(const aco::Context& c, const std::vector<std::uint8_t>& forbidden, aco::NodeId node) {
    if (c.graph != graph_) graph_ = c.graph, seen_.clear(), witness_.clear();  // a new map
    if (seen_.size() != forbidden.size()) {
      seen_.assign(forbidden.size(), 0), stamp_ = 0;
      on_witness_.assign(forbidden.size(), -1);
      parent_.assign(forbidden.size(), -1);
    }
    if (!witness_valid(c, forbidden)) {
      if (!search(c, forbidden, c.start, c.goal, -1, kWholeMap)) return false;
      set_witness(found_);
    }
    if (on_witness_[node] < 0) return true;
    if (node == c.goal) return false;
    const int at = on_witness_[node];
    if (search(c, forbidden, witness_[at - 1], witness_[at + 1], node, kNearby)) {
      std::vector<aco::NodeId> walk(witness_.begin(), witness_.begin() + at - 1);
      walk.insert(walk.end(), found_.begin(), found_.end());
      walk.insert(walk.end(), witness_.begin() + at + 2, witness_.end());
      set_witness(walk);
      return true;
    }
    if (!search(c, forbidden, c.start, c.goal, node, kWholeMap)) return false;
    set_witness(found_);
    return true;
  }

  bool witness_valid(const aco::Context& c, const std::vector<std::uint8_t>& forbidden) const {
    if (witness_.empty() || witness_.front() != c.start || witness_.back() != c.goal) return false;
    return std::none_of(witness_.begin(), witness_.end(), [&](aco::NodeId n) { return forbidden[n] != 0; });
  }

  // Breadth-first search from `from` to `to` avoiding forbidden nodes and `avoid` (-1: none),
  // giving up after `limit` nodes; on success the path is in found_. Stamps instead of fresh
  // arrays per search.
  bool search(const aco::Context& c, const std::vector<std::uint8_t>& forbidden, aco::NodeId from, aco::NodeId to,
              aco::NodeId avoid, std::size_t limit) {
    const aco::Graph& g = *c.graph;
    if (++stamp_ == 0) std::fill(seen_.begin(), seen_.end(), 0), stamp_ = 1;
    queue_.clear();
    queue_.push_back(from);
    seen_[from] = stamp_;
    if (avoid >= 0) seen_[avoid] = stamp_;
    for (std::size_t head = 0; head < queue_.size() && head < limit; ++head) {
      const aco::NodeId n = queue_[head];
      if (n == to) {
        found_.clear();
        for (aco::NodeId m = n; m != from; m = parent_[m]) found_.push_back(m);
        found_.push_back(from);
        std::reverse(found_.begin(), found_.end());
        return true;
      }
      for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) {
        const aco::NodeId t = g.targets[e];
        if (seen_[t] != stamp_ && !forbidden[t]) {
          seen_[t] = stamp_;
          parent_[t] = n;
          queue_.push_back(t);
        }
      }
    }
    return false;
  }

  // The walk with its loops cut out (a repaired witness may cross itself) becomes the witness.
  void set_witness(const std::vector<aco::NodeId>& walk) {
    for (aco::NodeId n : witness_) on_witness_[n] = -1;
    witness_.clear();
    for (aco::NodeId n : walk) {
      if (on_witness_[n] >= 0) {  // a loop back to n: drop everything after n's first visit
        const auto keep = static_cast<std::size_t>(on_witness_[n]) + 1;
        for (std::size_t i = keep; i < witness_.size(); ++i) on_witness_[witness_[i]] = -1;
        witness_.resize(keep);
        continue;
      }
      on_witness_[n] = static_cast<std::int32_t>(witness_.size());
      witness_.push_back(n);
    }
  }

  static constexpr std::size_t kNearby = 1024;  // nodes a repair search may visit
  static constexpr std::size_t kWholeMap = static_cast<std::size_t>(-1);
  const aco::Graph* graph_ = nullptr;
  std::vector<aco::NodeId> witness_;         // an open start-goal path, or empty
  std::vector<std::int32_t> on_witness_;     // per node: its position on the witness, or -1
  std::vector<aco::NodeId> found_;           // the path of the last successful search
  std::vector<aco::NodeId> parent_;          // per node: BFS predecessor, valid where seen_ is current
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;
  std::vector<aco::NodeId> queue_;
  double keep_;
};

}  // namespace

ACO_PLUGIN(deadlock, clear_and_tabu, ClearAndTabu, "1.0",
           "paper 002: a stuck ant is removed, its dead-end node becomes tabu for the run, its walk's pheromone cleared",
           kParams)
