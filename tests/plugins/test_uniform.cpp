#include <catch2/catch.hpp>

#include "aco/error.hpp"
#include "support.hpp"

TEST_CASE("uniform sets every edge to tau0", "[plugin][uniform]") {
  const auto map = test::grid({"...", ".#.", "..."});
  const aco::Graph graph = aco::build_graph(map, {});
  std::vector<double> tau(graph.num_edges(), -1.0);
  test::make<aco::PheromoneInit>("init", "uniform")->initialize(test::context(graph, {0, 0}, {2, 2}), tau);
  for (double t : tau) CHECK(t == 8.0);  // the default, the MATLAB code's value
  test::make<aco::PheromoneInit>("init", "uniform", {{"tau0", "0.25"}})
      ->initialize(test::context(graph, {0, 0}, {2, 2}), tau);
  for (double t : tau) CHECK(t == 0.25);
  CHECK_THROWS_AS(test::make<aco::PheromoneInit>("init", "uniform", {{"tau0", "0"}}), aco::Error);
}
