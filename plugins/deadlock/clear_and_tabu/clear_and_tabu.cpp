// Deadlock clearing (paper 002, section 2.2): a stuck ant is removed at once, the node where it
// got stuck joins a tabu set K_n that no ant enters again in this run, and the pheromone on the
// ant's walk is cleared.
#include <algorithm>
#include <vector>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double keep = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("keep", &Parameters::keep, "0:1",
               "share of the pheromone kept on the dead ant's edges (0 = cleared, as in the paper)"),
});

class ClearAndTabu final : public aco::DeadlockPolicy {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit ClearAndTabu(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override { return 0; }

  // The witness is of this run's map, start and goal.
  void begin_run(const aco::Context& c) override {
    witness_.clear();
    on_witness_.assign(static_cast<std::size_t>(c.graph->num_nodes()), -1);
  }

  void after_iteration(const aco::Context& c, const aco::Iteration& it, aco::Trail& trail,
                       std::vector<std::uint8_t>& forbidden) override {
    std::int64_t newly_forbidden = 0;
    for (const aco::Ant& ant : it.ants) {
      if (ant.arrived) continue;
      for (aco::EdgeId e : ant.edges) trail.set(e, trail[e] * p_.keep);
      const aco::NodeId dead_end = ant.nodes.back();
      if (dead_end != c.start && !forbidden[dead_end] && keeps_goal_reachable(c, forbidden, dead_end)) {
        forbidden[dead_end] = 1;
        ++newly_forbidden;
      }
    }
    c.add("nodes_forbidden", newly_forbidden);
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
    if (!witness_valid(c, forbidden)) {
      if (!search_.find(*c.graph, c.start, c.goal, forbidden, -1, kWholeMap)) return false;
      set_witness(search_.path());
    }
    if (on_witness_[node] < 0) return true;
    if (node == c.goal) return false;
    const int at = on_witness_[node];
    if (search_.find(*c.graph, witness_[at - 1], witness_[at + 1], forbidden, node, kNearby)) {
      std::vector<aco::NodeId> walk(witness_.begin(), witness_.begin() + at - 1);
      walk.insert(walk.end(), search_.path().begin(), search_.path().end());
      walk.insert(walk.end(), witness_.begin() + at + 2, witness_.end());
      set_witness(walk);
      return true;
    }
    if (!search_.find(*c.graph, c.start, c.goal, forbidden, node, kWholeMap)) return false;
    set_witness(search_.path());
    return true;
  }

  bool witness_valid(const aco::Context& c, const std::vector<std::uint8_t>& forbidden) const {
    if (witness_.empty() || witness_.front() != c.start || witness_.back() != c.goal) return false;
    return std::none_of(witness_.begin(), witness_.end(), [&](aco::NodeId n) { return forbidden[n] != 0; });
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
  std::vector<aco::NodeId> witness_;  // an open start-goal path, or empty
  std::vector<std::int32_t> on_witness_;  // per node: its position on the witness, or -1
  aco::BreadthFirstSearch search_;  // its path() is that of the last successful search
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(
    deadlock, clear_and_tabu, ClearAndTabu, "1.0",
    "paper 002: a stuck ant is removed, its dead-end node becomes tabu for the run, its walk's pheromone cleared",
    kParams)
