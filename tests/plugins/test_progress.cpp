#include <catch2/catch.hpp>
#include <cmath>

#include "aco/terrain.hpp"
#include "support.hpp"

TEST_CASE("progress: eta from the progress towards the goal per unit step, by hand", "[plugin][progress]") {
  const auto map = test::grid({".....", ".....", ".....", ".....", "....."});
  const aco::Graph graph = aco::build_graph(map, {});
  const auto context = test::context(graph, {0, 2}, {4, 2});
  std::vector<double> eta(graph.num_edges(), -1.0);
  test::make<aco::Heuristic>("heuristic", "progress", {{"floor", "0.1"}})->compute(context, eta);
  const auto at = [&](aco::Cell a, aco::Cell b) { return eta[graph.find_edge(graph.node(a), graph.node(b))]; };
  // Straight at the goal: r = 1. Straight away: r = -1.
  CHECK(at({0, 2}, {1, 2}) == Approx(1.0));
  CHECK(at({1, 2}, {0, 2}) == Approx(0.1));
  // (1,2) -> (1,1): d from 3 to sqrt(10), cost 1: r = 3 - 3.16228 = -0.16228, eta = 0.1 + 0.45 (1 + r).
  CHECK(at({1, 2}, {1, 1}) == Approx(0.1 + 0.45 * (1 + 3 - std::sqrt(10.0))));
  // (0,2) -> (1,1): d from 4 to sqrt(10), cost sqrt(2): r = 0.59235.
  CHECK(at({0, 2}, {1, 1}) == Approx(0.1 + 0.45 * (1 + (4 - std::sqrt(10.0)) / std::sqrt(2.0))));
  // Onto the goal: like any step straight at it.
  CHECK(at({3, 2}, {4, 2}) == Approx(1.0));
  for (double v : eta) {
    CHECK(v >= 0.1 - 1e-12);
    CHECK(v <= 1.0 + 1e-12);
  }
}

TEST_CASE("progress: a step's eta does not fade with the distance to the goal", "[plugin][progress]") {
  // A long corridor: the step towards the goal has eta 1 and the step away the floor, at 2 cells
  // and at 400 cells from the goal alike (1 / d would be 0.5 against 0.33 there, and 1.0025 apart here).
  const auto map = test::grid({std::string(402, '.')});
  const aco::Graph graph = aco::build_graph(map, {});
  const auto context = test::context(graph, {0, 0}, {401, 0});
  std::vector<double> eta(graph.num_edges());
  test::make<aco::Heuristic>("heuristic", "progress")->compute(context, eta);
  for (const int x : {1, 399}) {
    CHECK(eta[graph.find_edge(graph.node({x, 0}), graph.node({x + 1, 0}))] == Approx(1.0));
    CHECK(eta[graph.find_edge(graph.node({x, 0}), graph.node({x - 1, 0}))] == Approx(0.3));
  }
}

TEST_CASE("progress: on terrain a climbing step makes less progress than a flat one", "[plugin][progress][terrain]") {
  // Two rows, the top one 1 unit higher: a step from the bottom row up costs more in 3D.
  const aco::TerrainMap terrain(3, 2, 1.0, {1, 1, 1, 0, 0, 0}, 90.0, "test");
  const aco::Graph graph = aco::build_graph(terrain, {});
  const auto context = test::context(graph, {0, 1}, {2, 1});
  std::vector<double> eta(graph.num_edges());
  test::make<aco::Heuristic>("heuristic", "progress")->compute(context, eta);
  const auto at = [&](aco::Cell a, aco::Cell b) { return eta[graph.find_edge(graph.node(a), graph.node(b))]; };
  CHECK(at({0, 1}, {1, 1}) == Approx(1.0));
  // Up and towards the goal: d from 2 to sqrt(1 + 1 + 1), cost sqrt(3) in 3D.
  const double r = (2 - std::sqrt(3.0)) / std::sqrt(3.0);
  CHECK(at({0, 1}, {1, 0}) == Approx(0.3 + 0.35 * (1 + r)));
  // The same move on flat ground would make (2 - sqrt(2)) / sqrt(2) = 0.414 per unit, more than r = 0.155.
  CHECK(r < (2 - std::sqrt(2.0)) / std::sqrt(2.0));
}
