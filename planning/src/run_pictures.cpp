#include "aco/planning/run_pictures.hpp"

#include <algorithm>

namespace aco {

RunPicture run_picture(const Graph& graph, const PlanRun& run, bool pheromone) {
  RunPicture picture;
  picture.title = run_title(graph.map->name(), run.solved(), run.length, run.seed);
  picture.start = run.start;
  picture.goal = run.goal;
  picture.grid_path = run.search.path;
  picture.path = run.path;
  if (pheromone)
    picture.pheromone =
        run.pheromone_edges.empty() ? run.pheromone : per_edge(graph, run.pheromone_edges, run.pheromone);
  picture.best_so_far = run.search.best_so_far;
  picture.iteration_best = run.iteration_best;
  picture.optimal_length = run.optimal_length.value_or(0.0);
  return picture;
}

std::vector<double> strongest_into(const Graph& graph, std::span<const double> per_edge) {
  std::vector<double> into(static_cast<std::size_t>(graph.num_nodes()), 0.0);
  for (EdgeId e = 0; e < graph.num_edges(); ++e)
    into[graph.targets[e]] = std::max(into[graph.targets[e]], per_edge[static_cast<std::size_t>(e)]);
  return into;
}

VoxelWorldView run_view(const Graph& graph, const PlanRun& run, bool pheromone) {
  VoxelWorldView view(*graph.map);
  view.title = run_title(graph.map->name(), run.solved(), run.length, run.seed);
  view.path = run.path;
  for (NodeId n : run.search.path) view.grid_path.push_back(graph.cell(n));
  view.start = graph.cell(run.start);
  view.goal = graph.cell(run.goal);
  if (!pheromone || run.pheromone.empty()) return view;
  const std::vector<double> into = strongest_into(graph, run.pheromone);
  std::vector<NodeId> nodes;
  for (NodeId n = 0; n < graph.num_nodes(); ++n)
    if (graph.degree(n) > 0) nodes.push_back(n);
  if (nodes.empty()) return view;
  const auto stronger = [&](NodeId a, NodeId b) { return into[a] != into[b] ? into[a] > into[b] : a < b; };
  const auto middle = nodes.begin() + static_cast<std::ptrdiff_t>(nodes.size() / 2);
  std::nth_element(nodes.begin(), middle, nodes.end(), stronger);
  const double median = into[*middle];
  constexpr std::size_t kStrongest = 5000;
  const auto kept = nodes.begin() + static_cast<std::ptrdiff_t>(std::min(kStrongest, nodes.size() / 2));
  std::partial_sort(nodes.begin(), kept, middle, stronger);  // ties by node id: the same picture every run
  for (auto n = nodes.begin(); n != kept && into[*n] > median; ++n)
    view.pheromone.emplace_back(graph.cell(*n), into[*n]);
  return view;
}

}  // namespace aco
