#include "aco/potential_field.hpp"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <cmath>

#include "aco/parallel.hpp"

namespace aco {

std::vector<Eigen::Vector2d> potential_forces(const Graph& graph, NodeId start, NodeId goal,
                                              const PotentialFieldGains& gains) {
  std::vector<Eigen::Vector2d> forces(graph.num_nodes(), Eigen::Vector2d::Zero());
  const auto planar = [&](NodeId n) -> Eigen::Vector2d { return graph.positions[n].head<2>(); };

  const double z0 = graph.positions[start].z();
  double z_max = z0;
  for (NodeId n = 0; n < graph.num_nodes(); ++n)
    if (graph.passable(n)) z_max = std::max(z_max, graph.positions[n].z());
  // Weight of cell m as a source of repulsion: 0 at or below the start height.
  std::vector<double> weight(graph.num_nodes(), 0.0);
  for (NodeId m = 0; m < graph.num_nodes(); ++m) {
    const double z = graph.positions[m].z();
    weight[m] = !graph.passable(m) ? 1.0 : z > z0 ? (z - z0) / (z_max - z0) : 0.0;
  }

  // The cells within rho0 lie in a square window of this many cells around a node.
  const double spacing = graph.width > 1    ? (planar(1) - planar(0)).norm()
                         : graph.height > 1 ? (planar(graph.width) - planar(0)).norm()
                                            : 0.0;
  const int radius = spacing > 0.0 ? static_cast<int>(std::ceil(gains.rho0 / spacing)) : 0;

  // Each node on its own: the result does not depend on the thread count.
  aco::parallel_for(tbb::blocked_range<NodeId>(0, graph.num_nodes()), [&](const tbb::blocked_range<NodeId>& r) {
    for (NodeId n = r.begin(); n != r.end(); ++n) {
      if (!graph.passable(n)) continue;
      Eigen::Vector2d force = Eigen::Vector2d::Zero();
      const Eigen::Vector2d to_goal = planar(goal) - planar(n);
      if (n != goal && to_goal.norm() > 0.0) force += gains.k * to_goal.normalized();
      const Cell c = graph.cell(n);
      for (int y = std::max(0, c.y - radius); y <= std::min(graph.height - 1, c.y + radius); ++y) {
        for (int x = std::max(0, c.x - radius); x <= std::min(graph.width - 1, c.x + radius); ++x) {
          const NodeId m = graph.node({x, y});
          const Eigen::Vector2d away = planar(n) - planar(m);
          const double rho = away.norm();
          if (weight[m] == 0.0 || rho == 0.0 || rho >= gains.rho0) continue;
          force += gains.theta * weight[m] * (1.0 / rho - 1.0 / gains.rho0) / (rho * rho) * (away / rho);
        }
      }
      forces[n] = force;
    }
  });
  return forces;
}

}  // namespace aco
