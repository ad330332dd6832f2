// Greedy line-of-sight pruning of the grid path: the "secondary path optimisation" of paper 003
// (section 2.4). From the current node, connect straight to the farthest later node whose
// segment is free (aco::line_of_sight with the graph's corner rule); continue from there. A
// segment never is longer than the grid steps it replaces (triangle inequality), so the result
// is never longer than the grid path. If no later node is visible, the original grid step is
// kept unchecked: it is an edge of the graph, valid even where the segment rule is stricter
// than the move rule (a corner-cutting diagonal between two blocked cells).
#include <cstddef>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/plugin.hpp"
#include "aco/path.hpp"

namespace {

struct Parameters {
  std::size_t max_lookahead = 0;
  double clearance = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("max_lookahead", &Parameters::max_lookahead, "0:1000000",
               "farthest later node tried from each waypoint, in path steps; 0 = unlimited (the paper's rule)"),
    aco::field("clearance", &Parameters::clearance, "0:0.5",
               "a shortcut must also pass this far from every blocked cell (a robot's radius); 0 = line of sight only "
               "(the paper's rule)"),
});

class PruneSmoother final : public aco::Smoother {
 public:
  explicit PruneSmoother(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  // In voxel worlds with clearance 0 only: the clearance is measured in the plane. (Claiming them
  // with a clearance, every run there would fail; plan() refuses the object instead.)
  bool supports_voxel_worlds() const override { return p_.clearance <= 0.0; }

  std::vector<Eigen::Vector3d> smooth(const aco::Context& c, std::span<const aco::NodeId> path) const override {
    const aco::Graph& g = *c.graph;
    if (g.volumetric && p_.clearance > 0.0)
      throw aco::Error("prune.clearance is measured in the plane: a voxel world takes prune with clearance 0 only");
    std::vector<Eigen::Vector3d> points;
    for (const std::size_t k : aco::greedy_shortcuts(path.size(), p_.max_lookahead, [&](std::size_t i, std::size_t j) {
           const aco::Cell from = g.cell(path[i]), to = g.cell(path[j]);
           return aco::line_of_sight(*g.map, from, to, g.options.corner_cutting) &&
                  (p_.clearance <= 0.0 || aco::keeps_clear(*g.map, from, to, p_.clearance));
         }))
      points.push_back(g.position(path[k]));
    return points;
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(smoother, prune, PruneSmoother, "1.0",
           "paper 003's secondary optimisation: shortcut to the farthest later node in line of sight", kParams)
