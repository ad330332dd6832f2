#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

TEST_CASE("distance gives eta = 1 / d(next node, goal), floored near the goal", "[plugin][distance]") {
  const auto map = test::grid({"....", "....", "...."});
  const aco::Graph graph = aco::build_graph(map, {});
  const auto context = test::context(graph, {0, 0}, {3, 2});
  std::vector<double> eta(graph.num_edges());
  auto heuristic = test::make<aco::Heuristic>("heuristic", "distance");
  CHECK_FALSE(heuristic->specs().varies_by_iteration);
  CHECK_FALSE(heuristic->specs().uses_walk);
  heuristic->compute(context, eta);
  // (0,0) -> (1,1): the goal (3,2) is sqrt(2^2 + 1^2) away.
  CHECK(eta[graph.find_edge(graph.node({0, 0}), graph.node({1, 1}))] == Approx(1.0 / std::sqrt(5.0)));
  // (0,0) -> (1,0): sqrt(4 + 4).
  CHECK(eta[graph.find_edge(graph.node({0, 0}), graph.node({1, 0}))] == Approx(1.0 / std::sqrt(8.0)));
  // Stepping onto the goal: distance 0, floored at min_distance 0.01.
  CHECK(eta[graph.find_edge(graph.node({2, 2}), graph.node({3, 2}))] == Approx(100.0));
  // Every edge into the same node has the same eta.
  const aco::NodeId j = graph.node({1, 1});
  for (aco::EdgeId e = graph.edges_begin(j); e < graph.edges_end(j); ++e)
    CHECK(eta[graph.reverse_edge(e)] == Approx(1.0 / std::sqrt(5.0)));
  test::make<aco::Heuristic>("heuristic", "distance", {{"min_distance", "0.5"}})->compute(context, eta);
  CHECK(eta[graph.find_edge(graph.node({2, 2}), graph.node({3, 2}))] == Approx(2.0));
}
