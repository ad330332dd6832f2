#include <catch2/catch.hpp>

#include "support.hpp"

namespace {
struct Fixture {
  aco::OccupancyGrid map = test::grid({"....", "....", "...."});
  aco::Graph graph = aco::build_graph(map, {});
  aco::Context context = test::context(graph, {0, 0}, {3, 2});
  aco::Ant shortest = test::ant(graph, {{0, 0}, {1, 0}, {2, 1}, {3, 2}});  // 1 + 2 sqrt 2
  aco::Ant middle = test::ant(graph, {{0, 0}, {1, 1}, {2, 1}, {3, 2}});  // 1 + 2 sqrt 2 too, other edges
  aco::Ant longest = test::ant(graph, {{0, 0}, {0, 1}, {1, 2}, {2, 2}, {3, 2}});  // 3 + sqrt 2
  double edge(const std::vector<double>& tau, aco::Cell u, aco::Cell v) const {
    return tau[graph.find_edge(graph.node(u), graph.node(v))];
  }
  void offer(aco::PheromoneUpdate& update, const aco::Ant& ant, std::vector<double>& tau) {
    const std::vector<aco::Ant> ants{ant};
    update.update(context, {ants, &ants[0], &ants[0]}, tau);
    ++context.iteration;
  }
};
}  // namespace

TEST_CASE("population: tau = 1 + (ratio - 1) / k per population path on the edge, the init field at mean 1",
          "[plugin][population]") {
  Fixture f;
  auto update = test::make<aco::PheromoneUpdate>("update", "population", {{"size", "2"}, {"ratio", "5"}});
  std::vector<double> tau(f.graph.num_edges(), 0.25);
  update->start(f.context, tau);
  for (double t : tau) CHECK(t == Approx(1.0));
  // k = 2, ratio 5: each path adds (5 - 1) / 2 = 2 to its edges.
  f.offer(*update, f.longest, tau);
  CHECK(f.edge(tau, {0, 0}, {0, 1}) == Approx(3.0));
  CHECK(f.edge(tau, {0, 0}, {1, 0}) == Approx(1.0));
  f.offer(*update, f.shortest, tau);
  CHECK(f.edge(tau, {2, 1}, {3, 2}) == Approx(3.0));
  f.offer(*update, f.shortest, tau);  // already in: no second deposit
  CHECK(f.edge(tau, {2, 1}, {3, 2}) == Approx(3.0));
  // middle is as short as shortest and shares its last edge: the longest path leaves.
  f.offer(*update, f.middle, tau);
  CHECK(f.edge(tau, {0, 0}, {0, 1}) == Approx(1.0));
  CHECK(f.edge(tau, {2, 1}, {3, 2}) == Approx(5.0));  // on both paths: tau_max = ratio
  CHECK(f.edge(tau, {0, 0}, {1, 1}) == Approx(3.0));
  f.offer(*update, f.longest, tau);  // longer than every member: refused
  CHECK(f.edge(tau, {0, 0}, {0, 1}) == Approx(1.0));
  for (double t : tau) CHECK(t <= 5.0 + 1e-12);
}

TEST_CASE("population by age: the last k iteration-best paths, duplicates included", "[plugin][population]") {
  Fixture f;
  auto update =
      test::make<aco::PheromoneUpdate>("update", "population", {{"size", "2"}, {"ratio", "3"}, {"replace", "age"}});
  std::vector<double> tau(f.graph.num_edges(), 7.0);
  update->start(f.context, tau);
  f.offer(*update, f.shortest, tau);
  f.offer(*update, f.longest, tau);
  CHECK(f.edge(tau, {0, 0}, {1, 0}) == Approx(2.0));
  CHECK(f.edge(tau, {0, 0}, {0, 1}) == Approx(2.0));
  f.offer(*update, f.longest, tau);  // the shortest path, oldest, leaves; a longer one enters
  CHECK(f.edge(tau, {0, 0}, {1, 0}) == Approx(1.0));
  CHECK(f.edge(tau, {0, 0}, {0, 1}) == Approx(3.0));
}

TEST_CASE("population: a run restarts with an empty population", "[plugin][population]") {
  Fixture f;
  auto update = test::make<aco::PheromoneUpdate>("update", "population", {{"size", "1"}});
  std::vector<double> tau(f.graph.num_edges(), 1.0);
  update->begin_run(f.context);
  update->start(f.context, tau);
  f.offer(*update, f.shortest, tau);
  std::vector<double> fresh(f.graph.num_edges(), 1.0);
  update->begin_run(f.context);
  update->start(f.context, fresh);
  f.offer(*update, f.longest, fresh);  // would be refused if the first run's population remained
  CHECK(f.edge(fresh, {0, 0}, {0, 1}) == Approx(4.0));
  CHECK(f.edge(fresh, {0, 0}, {1, 0}) == Approx(1.0));
}

TEST_CASE("population solves classic map1 bit-identically for any thread count", "[plugin][population][determinism]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::ColonySettings settings;
  settings.seed = 5;
  settings.ants = 20;
  settings.iterations = 30;
  settings.q0 = 0.5;
  settings.local_search = aco::LocalSearch::straighten;
  const aco::ColonyResult result = test::run_on_thread_counts(
      graph, 0, graph.node({19, 19}), settings, {"uniform", "progress", "population", "backtrack"}, {{"size", "3"}});
  REQUIRE(result.solved);
  CHECK(result.length < 1.05 * 34.3848);  // within 5 % of the optimum
}
