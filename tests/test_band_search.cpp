// The band search (aco::BandSearch, ColonySettings::band_search): a walk replaced by the shortest
// path among the nodes within a radius of it.
#include <catch2/catch.hpp>
#include <random>

#include "aco/astar.hpp"
#include "aco/engine/local_search.hpp"
#include "support.hpp"

TEST_CASE("band search: a walk takes the nearer door once the band reaches it", "[band_search]") {
  // A wall across the map with two doors: (2,3) near the straight line, (9,3) far to the right.
  const auto map = test::grid({
      "..........",
      "..........",
      "..........",
      "##.######.",
      "..........",
      "..........",
      "..........",
  });
  const aco::Graph graph = aco::build_graph(map, {});
  const std::vector<std::uint8_t> forbidden(graph.num_nodes(), 0);
  const aco::NodeId start = graph.node({1, 0}), goal = graph.node({1, 6});
  // Through the far door: right along row 1, down the last column, back along row 5.
  std::vector<aco::Cell> cells{{1, 0}};
  for (int x = 2; x <= 8; ++x) cells.push_back({x, 1});
  for (int y = 2; y <= 4; ++y) cells.push_back({9, y});
  for (int x = 8; x >= 2; --x) cells.push_back({x, 5});
  cells.push_back({1, 6});
  const aco::Ant far_door = test::ant(graph, cells);
  REQUIRE(test::walk_problem(graph, far_door, start, goal) == "");
  const double optimum = aco::astar(graph, start, goal)->length;
  // The near door is 2 moves from the walk, (2,1) and (2,5): out of a band of 1, in one of 2.
  aco::BandSearch narrow(graph, forbidden, 1), wide(graph, forbidden, 2);
  aco::Ant a = far_door, b = far_door;
  CHECK_FALSE(narrow.improve(a));
  CHECK(a.nodes == far_door.nodes);
  REQUIRE(wide.improve(b));
  CHECK(b.length == Approx(optimum));
  CHECK(std::find(b.nodes.begin(), b.nodes.end(), graph.node({2, 3})) != b.nodes.end());
  CHECK(test::walk_problem(graph, b, start, goal) == "");
  // A walk that is already the band's shortest is left as it is.
  aco::Ant again = b;
  CHECK_FALSE(wide.improve(again));
  CHECK(again.nodes == b.nodes);
}

TEST_CASE("band search: valid, never longer, around forbidden nodes, and A* once the band is the map",
          "[band_search]") {
  std::mt19937 rng(23);
  int improved = 0, walks = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto problem = test::random_problem(rng, 8, 30);
    const aco::Neighbourhood nbhd = trial % 3 == 0   ? aco::Neighbourhood::sixteen
                                    : trial % 3 == 1 ? aco::Neighbourhood::eight
                                                     : aco::Neighbourhood::four;
    const aco::Graph graph = aco::build_graph(problem.map, {nbhd, trial % 2 == 0});
    const aco::NodeId start = graph.node(problem.start), goal = graph.node(problem.goal);
    const auto optimum = aco::astar(graph, start, goal);
    if (!optimum || start == goal) continue;
    // A walk: the shortest path once a cell in the middle of the optimum is blocked, a detour
    // round it (the optimum itself where that cuts the map).
    aco::OccupancyGrid detour_map = problem.map;
    detour_map.set_blocked(graph.cell(optimum->nodes[optimum->nodes.size() / 2]), true);
    const aco::Graph detour_graph = aco::build_graph(detour_map, graph.options);
    const auto detour =
        start == optimum->nodes[optimum->nodes.size() / 2] || goal == optimum->nodes[optimum->nodes.size() / 2]
            ? std::nullopt
            : aco::astar(detour_graph, start, goal);
    aco::Ant walk;
    walk.nodes = detour ? detour->nodes : optimum->nodes;
    for (std::size_t k = 0; k + 1 < walk.nodes.size(); ++k) {
      walk.edges.push_back(graph.find_edge(walk.nodes[k], walk.nodes[k + 1]));
      walk.length += graph.cost(walk.edges.back());
    }
    walk.arrived = true;
    std::vector<std::uint8_t> forbidden(graph.num_nodes(), 0);
    for (int k = 0; k < 6; ++k) forbidden[rng() % graph.num_nodes()] = 1;
    forbidden[start] = forbidden[goal] = 0;
    for (const int radius : {1, 2, 5}) {
      aco::Ant ant = walk;
      aco::BandSearch band(graph, forbidden, radius);
      improved += band.improve(ant);
      ++walks;
      REQUIRE(test::walk_problem(graph, ant, start, goal) == "");
      REQUIRE(ant.length <= walk.length + 1e-9);
      // A forbidden node only where the walk had it.
      for (aco::NodeId n : ant.nodes)
        if (forbidden[n]) REQUIRE(std::find(walk.nodes.begin(), walk.nodes.end(), n) != walk.nodes.end());
    }
    // A band as wide as the map, nothing forbidden: the map's shortest path.
    const std::vector<std::uint8_t> none(graph.num_nodes(), 0);
    aco::BandSearch whole(graph, none, 64);
    aco::Ant any = walk;
    whole.improve(any);
    CHECK(any.length == Approx(optimum->length));
  }
  CHECK(walks > 100);
  CHECK(improved > walks / 4);  // most detours round one cell are undone within a move or two
}
