#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

TEST_CASE("acs: tau0 scaling, local update towards tau0, global update on best-so-far", "[plugin][acs]") {
  const auto map = test::grid({"....", "....", "...."});
  const aco::Graph graph = aco::build_graph(map, {});
  auto context = test::context(graph, {0, 0}, {3, 2});
  auto update = test::make<aco::PheromoneUpdate>("update", "acs", {{"rho", "0.2"}, {"xi", "0.5"}, {"q", "3"}});
  // start(): the init plugin's shape is kept, its mean becomes tau0 = Q / d(start, goal)^2 = 3 / 13.
  std::vector<double> tau(graph.num_edges(), 1.0);
  tau[0] = 3.0;
  update->start(context, tau);
  double mean = 0;
  for (double t : tau) mean += t / tau.size();
  CHECK(mean == Approx(3.0 / 13.0));
  const double unit = tau[1];
  CHECK(tau[0] == Approx(3.0 * unit));

  const aco::Ant best = test::ant(graph, {{0, 0}, {1, 1}, {2, 2}, {3, 2}});
  const aco::Ant other = test::ant(graph, {{0, 0}, {1, 0}, {2, 1}, {3, 2}});
  const std::vector<aco::Ant> ants{other};
  for (aco::EdgeId e : best.edges) tau[e] = 2.0;
  for (aco::EdgeId e : other.edges) tau[e] = 2.0;
  const std::vector<double> initial = [&] {
    std::vector<double> t(graph.num_edges(), unit);
    t[0] = 3 * unit;
    return t;
  }();
  update->update(context, {ants, &ants[0], &best}, tau);
  // Local: edges the iteration's ants used move halfway (xi = 0.5) back to their initial value.
  for (aco::EdgeId e : other.edges) CHECK(tau[e] == Approx(0.5 * 2.0 + 0.5 * initial[e]));
  // Global: the best-so-far path moves towards Q / L by rho = 0.2 (it was not walked this time).
  for (aco::EdgeId e : best.edges) CHECK(tau[e] == Approx(0.8 * 2.0 + 0.2 * 3.0 / best.length));
  // An edge nobody touched keeps its value.
  CHECK(tau[graph.find_edge(graph.node({1, 2}), graph.node({0, 2}))] == Approx(unit));

  auto fixed = test::make<aco::PheromoneUpdate>("update", "acs", {{"tau0", "0.01"}});
  std::vector<double> t2(graph.num_edges(), 4.0);
  fixed->start(context, t2);
  for (double t : t2) CHECK(t == Approx(0.01));
}
