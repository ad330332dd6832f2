// Greedy line-of-sight pruning of the grid path: the "secondary path optimisation" of paper 003
// (section 2.4). From the current node, connect straight to the farthest later node whose
// segment is free (aco::line_of_sight with the graph's corner rule); continue from there. A
// segment never is longer than the grid steps it replaces (triangle inequality), so the result
// is never longer than the grid path. If no later node is visible, the original grid step is
// kept unchecked: it is an edge of the graph, valid even where the segment rule is stricter
// than the move rule (a corner-cutting diagonal between two blocked cells).
#include <algorithm>
#include <cstddef>

#include "aco/graph.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  std::size_t max_lookahead = 0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("max_lookahead", &Parameters::max_lookahead, "0:1000000",
               "farthest later node tried from each waypoint, in path steps; 0 = unlimited (the paper's rule)"),
});

class PruneSmoother final : public aco::Smoother {
 public:
  explicit PruneSmoother(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  std::vector<Eigen::Vector3d> smooth(const aco::Context& c, std::span<const aco::NodeId> path) const override {
    const aco::Graph& g = *c.graph;
    std::vector<Eigen::Vector3d> points;
    if (path.empty()) return points;
    const std::size_t last = path.size() - 1;
    points.push_back(g.positions[path[0]]);
    std::size_t i = 0;
    while (i < last) {
      const aco::Cell from = g.cell(path[i]);
      const std::size_t farthest = p_.max_lookahead == 0 ? last : std::min(last, i + p_.max_lookahead);
      std::size_t next = i + 1;
      for (std::size_t j = farthest; j >= i + 2; --j) {
        if (aco::line_of_sight(*g.map, from, g.cell(path[j]), g.options.corner_cutting)) {
          next = j;
          break;
        }
      }
      points.push_back(g.positions[path[next]]);
      i = next;
    }
    return points;
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(smoother, prune, PruneSmoother, "1.0",
           "paper 003's secondary optimisation: shortcut to the farthest later node in line of sight", kParams)
