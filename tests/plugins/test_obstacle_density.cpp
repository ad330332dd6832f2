#include <catch2/catch.hpp>

#include "support.hpp"

TEST_CASE("obstacle_density: tau of every edge into j = gamma * free share of j's 8 neighbours",
          "[plugin][obstacle_density]") {
  const auto map = test::grid({
      "....#",
      ".#...",
      "..#..",
      ".....",
  });
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  std::vector<double> tau(g.num_edges(), 0.0);
  test::make<aco::PheromoneInit>("init", "obstacle_density", {{"gamma", "4"}})
      ->initialize(test::context(g, {0, 0}, {4, 3}), tau);
  // Free neighbours counted by hand (cells outside the map count as blocked).
  const std::vector<std::pair<aco::Cell, int>> expected{
      {{0, 0}, 2},  // corner: (1,0) free, (0,1) free, (1,1) blocked
      {{2, 1}, 6},  // (1,0) (2,0) (3,0) (3,1) (1,2) (3,2) free; (1,1) (2,2) blocked
      {{1, 2}, 6},  // (0,1) (2,1) (0,2) (0,3) (1,3) (2,3) free; (1,1) (2,2) blocked
      {{3, 3}, 4},  // bottom edge: (2,2) blocked, (3,2) (4,2) (2,3) (4,3) free
      {{4, 1}, 4},  // right edge: (4,0) blocked, (3,0) (3,1) (3,2) (4,2) free
  };
  for (const auto& [cell, free] : expected) {
    const aco::NodeId j = g.node(cell);
    INFO("cell " << aco::to_string(cell));
    REQUIRE(g.degree(j) > 0);
    for (aco::EdgeId e = g.edges_begin(j); e < g.edges_end(j); ++e)
      CHECK(tau[g.reverse_edge(e)] == Approx(4.0 * free / 8.0));
  }
  for (double t : tau) CHECK(t > 0.0);
}
