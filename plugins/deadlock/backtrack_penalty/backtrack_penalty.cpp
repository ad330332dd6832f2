// Ant death with a backtrack penalty (paper 001, section 2.4): a stuck ant dies, backs off h
// nodes, and the pheromone of those nodes is cut, so later ants avoid the trap (U-shaped
// obstacles).
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  std::int64_t h = 3;
  double penalty = 0.1;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("h", &Parameters::h, "1:1000000", "how many of the dead ant's last nodes are penalised"),
    aco::field("penalty", &Parameters::penalty, "0:1",
               "the pheromone of every edge into those nodes is multiplied by this"),
});

class BacktrackPenalty final : public aco::DeadlockPolicy {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit BacktrackPenalty(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override { return 0; }

  void after_iteration(const aco::Context& c, const aco::Iteration& it, aco::Trail& trail,
                       std::vector<std::uint8_t>&) override {
    const aco::Graph& g = *c.graph;
    for (const aco::Ant& ant : it.ants) {
      if (ant.arrived) continue;
      // The last h nodes of the walk, never the start.
      const std::size_t first = ant.nodes.size() > std::size_t(p_.h) ? ant.nodes.size() - p_.h : 1;
      for (std::size_t i = first; i < ant.nodes.size(); ++i) {
        const aco::NodeId n = ant.nodes[i];
        for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) {
          const aco::EdgeId into = g.reverse_edge(e);
          trail.set(into, trail[into] * p_.penalty);
        }
      }
    }
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(deadlock, backtrack_penalty, BacktrackPenalty, "1.0",
           "paper 001: a stuck ant dies; the pheromone into its last h nodes is multiplied by penalty", kParams)
