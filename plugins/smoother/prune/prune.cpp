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
#include "aco/robot.hpp"

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

// Distance from the segment a-b to the unit square centred on c, when they do not cross: the
// nearest pair is an end of the segment and the square, or a corner of the square and the segment.
double distance_to_cell(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  double d = std::min(aco::distance_to_square(a, c, 1.0), aco::distance_to_square(b, c, 1.0));
  const Eigen::Vector2d ab = b - a;
  for (const Eigen::Vector2d& corner :
       {Eigen::Vector2d(c.x() - 0.5, c.y() - 0.5), Eigen::Vector2d(c.x() + 0.5, c.y() - 0.5),
        Eigen::Vector2d(c.x() - 0.5, c.y() + 0.5), Eigen::Vector2d(c.x() + 0.5, c.y() + 0.5)}) {
    const double t = ab.squaredNorm() > 0.0 ? std::clamp((corner - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    d = std::min(d, (a + t * ab - corner).norm());
  }
  return d;
}

// Whether every blocked cell (outside the map included) is at least `clearance` from the segment
// between the centres of cells a and b.
bool keeps_clear(const aco::Map& map, aco::Cell a, aco::Cell b, double clearance) {
  const Eigen::Vector2d pa(a.x, a.y), pb(b.x, b.y);
  for (int y = std::min(a.y, b.y) - 1; y <= std::max(a.y, b.y) + 1; ++y)
    for (int x = std::min(a.x, b.x) - 1; x <= std::max(a.x, b.x) + 1; ++x)
      if (!map.passable({x, y}) && distance_to_cell(pa, pb, Eigen::Vector2d(x, y)) < clearance) return false;
  return true;
}

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
        const aco::Cell to = g.cell(path[j]);
        if (aco::line_of_sight(*g.map, from, to, g.options.corner_cutting) &&
            (p_.clearance <= 0.0 || keeps_clear(*g.map, from, to, p_.clearance))) {
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
