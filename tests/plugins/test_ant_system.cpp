#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

TEST_CASE("ant_system evaporates everywhere and every arrived ant deposits Q/L", "[plugin][ant_system]") {
  const auto map = test::grid({"...", "...", "..."});
  const aco::Graph graph = aco::build_graph(map, {});
  auto update = test::make<aco::PheromoneUpdate>("update", "ant_system", {{"rho", "0.5"}, {"q", "2"}});
  std::vector<double> tau(graph.num_edges(), 1.0);
  // A: the diagonal (length 2 sqrt 2). B: along the top and down the right side (length 4).
  const aco::Ant a = test::ant(graph, {{0, 0}, {1, 1}, {2, 2}});
  const aco::Ant b = test::ant(graph, {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}});
  aco::Ant dead = test::ant(graph, {{0, 0}, {0, 1}, {1, 1}});
  dead.arrived = false;
  const std::vector<aco::Ant> ants{a, b, dead};
  const auto context = test::context(graph, {0, 0}, {2, 2});
  update->update(context, {ants, &ants[0], &ants[0]}, tau);
  const double from_a = 2.0 / (2.0 * std::sqrt(2.0)), from_b = 2.0 / 4.0;
  auto edge = [&](aco::Cell u, aco::Cell v) { return tau[graph.find_edge(graph.node(u), graph.node(v))]; };
  CHECK(edge({0, 0}, {1, 1}) == Approx(0.5 + from_a));
  CHECK(edge({1, 1}, {2, 2}) == Approx(0.5 + from_a));
  CHECK(edge({0, 0}, {1, 0}) == Approx(0.5 + from_b));
  CHECK(edge({2, 1}, {2, 2}) == Approx(0.5 + from_b));
  CHECK(edge({0, 0}, {0, 1}) == Approx(0.5));  // the dead ant deposits nothing
  CHECK(edge({1, 1}, {0, 0}) == Approx(0.5));  // deposits are directed
  double total = 0;
  for (double t : tau) total += t;
  CHECK(total == Approx(0.5 * graph.num_edges() + 2 * from_a + 4 * from_b));
}
