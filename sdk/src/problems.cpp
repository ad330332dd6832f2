// The standard tiny maps, voxel worlds and iterations the plugins are checked on.
#include <algorithm>

#include "aco/astar.hpp"
#include "aco/sdk/conformance.hpp"
#include "aco/path.hpp"

namespace aco::conformance {

Context Problem::context(int iteration, int iterations, std::uint64_t seed) const {
  const ColonySettings colony;
  Context c;
  c.graph = &graph;
  c.start = start;
  c.goal = goal;
  c.ants = 8;
  c.max_iterations = iterations;
  c.alpha = colony.alpha;
  c.beta = colony.beta;
  c.seed = seed;
  c.iteration = iteration;
  return c;
}

std::vector<NodeId> Problem::shortest_path() const {
  const auto path = astar(graph, start, goal);
  if (!path) throw Error("conformance: no path from start to goal on the map '" + name + "'");
  return path->nodes;
}

Problem make_problem(const std::string& name, const std::vector<std::string>& rows, Cell start, Cell goal) {
  auto map =
      std::make_shared<OccupancyGrid>(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), name);
  for (int y = 0; y < map->height(); ++y)
    for (int x = 0; x < map->width(); ++x) map->set_blocked({x, y}, rows[y][x] == '#');
  Problem p{name, map, build_graph(*map, {}), 0, 0};
  p.start = p.graph.node(start);
  p.goal = p.graph.node(goal);
  return p;
}

std::vector<Problem> standard_problems() {
  std::vector<Problem> problems;
  problems.push_back(
      make_problem("open", {"........", "........", "........", "........", "........", "........"}, {0, 0}, {7, 5}));
  problems.push_back(make_problem(
      "obstacles",
      {"..........", "..#####...", "......#...", ".##...#.#.", "..#...#.#.", "..#.###.#.", "..#.....#.", ".........."},
      {0, 0}, {9, 7}));
  // Two pockets (the left column and the box entered at (2,1)) and the walled-in cell (4,4).
  problems.push_back(make_problem(
      "dead end",
      {".........#", ".#.#####.#", ".#.....#..", ".#.###.#..", ".#.#.#.#..", ".#.###.#..", ".#.....#..", ".#######.."},
      {0, 0}, {9, 7}));
  problems.push_back(make_problem("corridor", {"............"}, {0, 0}, {11, 0}));
  return problems;
}

Problem make_voxel_problem(std::shared_ptr<const VoxelMap> world, Cell start, Cell goal, Neighbourhood neighbourhood) {
  GraphOptions options;
  options.neighbourhood = neighbourhood;
  options.corner_cutting = false;
  Problem p{world->name(), world, build_graph(*world, options), 0, 0};
  p.start = p.graph.node(start);
  p.goal = p.graph.node(goal);
  return p;
}

std::vector<Problem> voxel_problems() {
  auto voxels = std::make_shared<VoxelMap>(10, 8, 6, "voxels");
  auto block = [&](int x0, int x1, int y0, int y1, int z0, int z1) {
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) voxels->set_blocked({x, y, z}, true);
  };
  block(5, 5, 0, 7, 0, 5);  // a wall across x = 5 ...
  for (int z = 3; z <= 4; ++z)
    for (int y = 5; y <= 6; ++y) voxels->set_blocked({5, y, z}, false);  // ... with a 2x2 gap high up
  block(2, 2, 2, 2, 0, 5);  // pillars, floor to ceiling
  block(3, 3, 5, 5, 0, 5);
  block(7, 7, 2, 2, 0, 3);  // one that ends below the ceiling
  block(0, 2, 6, 7, 2, 2);  // an overhang
  block(8, 9, 0, 1, 0, 1);  // the corner voxel (9,0,0) walled in: no ant reaches it
  voxels->set_blocked({9, 0, 0}, false);
  auto floors = std::make_shared<VoxelMap>(4, 4, 7, "floors");
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      floors->set_blocked({x, y, 2}, x != 3 || y != 3);  // a floor with a hole at (3,3)
      floors->set_blocked({x, y, 4}, x != 0 || y != 0);  // and one with a hole at (0,0)
    }
  std::vector<Problem> problems;
  problems.push_back(make_voxel_problem(voxels, {0, 0, 0}, {9, 7, 5}));
  problems.push_back(make_voxel_problem(floors, {0, 0, 0}, {3, 3, 6}));
  return problems;
}

Ant walk(const Problem& problem, const std::vector<NodeId>& nodes) {
  Ant ant;
  ant.nodes = nodes;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const EdgeId e = problem.graph.find_edge(nodes[i - 1], nodes[i]);
    if (e < 0) throw Error("conformance: a walk steps between nodes that are not neighbours");
    ant.edges.push_back(e);
    ant.length += problem.graph.cost(e);
  }
  ant.arrived = !nodes.empty() && nodes.back() == problem.goal;
  return ant;
}

Iteration IterationCase::view() const {
  const Ant* best_ant = best >= 0 ? &ants[best] : nullptr;
  return {ants, best_ant, earlier_best ? &*earlier_best : best_ant};
}

std::vector<IterationCase> standard_iterations(const Problem& problem) {
  const std::vector<NodeId> shortest = problem.shortest_path();
  auto prefix = [&](std::size_t n) {
    return walk(problem, {shortest.begin(), shortest.begin() + std::max<std::size_t>(n, 1)});
  };
  // A longer arrived walk: around the middle node of the shortest path, where the map allows.
  std::vector<NodeId> detour = shortest;
  if (shortest.size() > 2) {
    BreadthFirstSearch search;
    if (search.find(problem.graph, problem.start, problem.goal, {}, shortest[shortest.size() / 2]))
      detour = search.path();
  }

  IterationCase arrived{
      "ants arrived", {walk(problem, detour), walk(problem, shortest), prefix(shortest.size() / 2), prefix(1)}, -1, {}};
  arrived.best = arrived.ants[0].length < arrived.ants[1].length ? 0 : 1;
  IterationCase none{"no ant arrived", {prefix(shortest.size() / 2), prefix(shortest.size() / 4), prefix(1)}, -1, {}};
  none.earlier_best = walk(problem, shortest);
  IterationCase dead{"all ants dead", std::vector<Ant>(4, prefix(1)), -1, {}};
  return {arrived, none, dead};
}

}  // namespace aco::conformance
