#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "support.hpp"

namespace {
struct Fixture {
  aco::OccupancyGrid map = test::grid({"....", "....", "...."});
  aco::Graph graph = aco::build_graph(map, {});
  aco::Context context = test::context(graph, {0, 0}, {3, 2});
  // Straight then diagonal: 1 + 1 + sqrt 2... and a longer one.
  aco::Ant best = test::ant(graph, {{0, 0}, {1, 0}, {2, 1}, {3, 2}});
  aco::Ant other = test::ant(graph, {{0, 0}, {0, 1}, {1, 2}, {2, 2}, {3, 2}});
  double edge(const std::vector<double>& tau, aco::Cell u, aco::Cell v) const {
    return tau[graph.find_edge(graph.node(u), graph.node(v))];
  }
  // Stuetzle's bound with ACOTSP's average number of choices, (mean degree + 1) / 2.
  double tau_min(double tau_max, double p_best) const {
    const double choices = 0.5 * (1.0 + double(graph.num_edges()) / graph.num_nodes());
    const double p_dec = std::pow(p_best, 1.0 / double(best.edges.size()));
    return tau_max * (1.0 - p_dec) / (choices * p_dec);
  }
};
}  // namespace

TEST_CASE("max_min keeps tau within [tau_min, tau_max] and only the chosen ant deposits", "[plugin][max_min]") {
  Fixture f;
  auto update = test::make<aco::PheromoneUpdate>(
      "update", "max_min", {{"rho", "0.2"}, {"q", "1"}, {"p_best", "0.05"}, {"best_so_far_every", "1000"}});
  std::vector<double> tau(f.graph.num_edges(), 5.0);
  update->begin_run(f.context);
  update->start(f.context, tau);
  const std::vector<aco::Ant> ants{f.other, f.best};
  const double tau_max = 1.0 / (0.2 * f.best.length);
  const double tau_min = f.tau_min(tau_max, 0.05);
  // First update: the field is scaled to tau_max, so everything sits at the upper bound.
  update->update(f.context, {ants, &ants[1], &ants[1]}, tau);
  for (double t : tau) CHECK(t == Approx(tau_max));
  // Later updates: the best path stays at tau_max (evaporation and deposit balance exactly),
  // the rest evaporates geometrically until it reaches tau_min.
  for (int it = 1; it <= 30; ++it) {
    f.context.iteration = it;
    update->update(f.context, {ants, &ants[1], &ants[1]}, tau);
    const double expected_other = std::max(tau_min, tau_max * std::pow(0.8, it));
    CHECK(f.edge(tau, {0, 0}, {1, 0}) == Approx(tau_max));
    CHECK(f.edge(tau, {2, 1}, {3, 2}) == Approx(tau_max));
    CHECK(f.edge(tau, {0, 0}, {0, 1}) == Approx(expected_other));
  }
  for (double t : tau) {
    CHECK(t >= tau_min * (1 - 1e-12));
    CHECK(t <= tau_max * (1 + 1e-12));
  }
}

TEST_CASE("max_min alternates iteration-best and best-so-far deposits on its schedule", "[plugin][max_min]") {
  Fixture f;
  auto update = test::make<aco::PheromoneUpdate>("update", "max_min", {{"rho", "0.5"}, {"best_so_far_every", "2"}});
  std::vector<double> tau(f.graph.num_edges(), 1.0);
  update->begin_run(f.context);
  update->start(f.context, tau);
  // This iteration's best is `other`; the run's best so far is `best`.
  const std::vector<aco::Ant> ants{f.other};
  const aco::Iteration view{ants, &ants[0], &f.best};
  const aco::EdgeId only_other = f.graph.find_edge(f.graph.node({0, 0}), f.graph.node({0, 1}));
  const aco::EdgeId only_best = f.graph.find_edge(f.graph.node({0, 0}), f.graph.node({1, 0}));
  const double tau_max = 1.0 / (0.5 * f.best.length);
  const double tau_min = f.tau_min(tau_max, 0.05);
  auto bounded = [&](double t) { return std::clamp(t, tau_min, tau_max); };
  update->update(f.context, view, tau);  // first update: everything at tau_max
  f.context.iteration = 2;  // (2 + 1) % 2 != 0: the iteration best deposits
  update->update(f.context, view, tau);
  CHECK(tau[only_other] == Approx(bounded(0.5 * tau_max + 1.0 / f.other.length)));
  CHECK(tau[only_best] == Approx(bounded(0.5 * tau_max)));
  f.context.iteration = 3;  // (3 + 1) % 2 == 0: the best so far deposits
  const double before_best = tau[only_best], before_other = tau[only_other];
  update->update(f.context, view, tau);
  CHECK(tau[only_best] == Approx(bounded(0.5 * before_best + 1.0 / f.best.length)));
  CHECK(tau[only_other] == Approx(bounded(0.5 * before_other)));
  CHECK(tau[only_best] > tau[only_other]);
}

TEST_CASE("max_min restarts the trail after the set number of iterations without improvement", "[plugin][max_min]") {
  Fixture f;
  auto update = test::make<aco::PheromoneUpdate>("update", "max_min", {{"rho", "0.5"}, {"restart_after", "3"}});
  std::vector<double> tau(f.graph.num_edges(), 1.0);
  update->begin_run(f.context);
  update->start(f.context, tau);
  const std::vector<aco::Ant> ants{f.best};
  const double tau_max = 1.0 / (0.5 * f.best.length);
  for (int it = 0; it < 3; ++it) {
    f.context.iteration = it;
    update->update(f.context, {ants, &ants[0], &ants[0]}, tau);
  }
  CHECK(f.edge(tau, {0, 0}, {0, 1}) < tau_max);
  f.context.iteration = 3;
  update->update(f.context, {ants, &ants[0], &ants[0]}, tau);
  for (double t : tau) CHECK(t == Approx(tau_max));
}

TEST_CASE("max_min's lazy trail gives the values of its plain update", "[plugin][max_min]") {
  // The engine keeps one Trail through the run (evaporation a scale, the bounds applied where
  // tau is read); update() on plain values evaporates and bounds every edge at once.
  Fixture f;
  auto lazy = test::make<aco::PheromoneUpdate>("update", "max_min", {{"rho", "0.3"}, {"best_so_far_every", "3"}});
  auto plain = test::make<aco::PheromoneUpdate>("update", "max_min", {{"rho", "0.3"}, {"best_so_far_every", "3"}});
  std::vector<double> stored(f.graph.num_edges(), 1.0), tau(f.graph.num_edges(), 1.0);
  lazy->begin_run(f.context);
  lazy->start(f.context, stored);
  plain->begin_run(f.context);
  plain->start(f.context, tau);
  aco::Trail trail(stored);
  const std::vector<aco::Ant> ants{f.other, f.best};
  for (int it = 0; it < 40; ++it) {
    f.context.iteration = it;
    // The iteration best alternates, so both deposits and both bounds are exercised.
    const aco::Iteration view{ants, &ants[it % 2], &ants[1]};
    lazy->update_trail(f.context, view, trail);
    plain->update(f.context, view, tau);
    for (aco::EdgeId e = 0; e < f.graph.num_edges(); ++e) CHECK(trail[e] == Approx(tau[e]).epsilon(1e-12));
  }
  CHECK_FALSE(trail.plain());
}

TEST_CASE("max_min: after a reset the restart-best walk deposits, on a schedule counted from the reset",
          "[plugin][max_min]") {
  // ACOTSP's mmas_update: the best-so-far would mark the old corridor again at once.
  Fixture f;
  auto update = test::make<aco::PheromoneUpdate>("update", "max_min",
                                                 {{"rho", "0.5"}, {"restart_after", "2"}, {"best_so_far_every", "2"}});
  std::vector<double> tau(f.graph.num_edges(), 1.0);
  update->begin_run(f.context);
  update->start(f.context, tau);
  const std::vector<aco::Ant> bests{f.best}, others{f.other};
  const double tau_max = 1.0 / (0.5 * f.best.length);
  for (int it = 0; it <= 2; ++it) {  // no shorter walk after iteration 0: the reset comes in iteration 2
    f.context.iteration = it;
    update->update(f.context, {bests, &bests[0], &bests[0]}, tau);
  }
  for (double t : tau) REQUIRE(t == Approx(tau_max));
  // Iteration 3, the first after the reset, finds only `other`: the restart-best. (3 + 1 - 2) % 2 == 0,
  // so the scheduled deposit is the restart-best's, not the best-so-far's.
  f.context.iteration = 3;
  update->update(f.context, {others, &others[0], &f.best}, tau);
  const aco::EdgeId only_other = f.graph.find_edge(f.graph.node({0, 0}), f.graph.node({0, 1}));
  const aco::EdgeId only_best = f.graph.find_edge(f.graph.node({0, 0}), f.graph.node({1, 0}));
  const double tau_min = f.tau_min(tau_max, 0.05);
  auto bounded = [&](double t) { return std::clamp(t, tau_min, tau_max); };
  CHECK(tau[only_other] == Approx(bounded(0.5 * tau_max + 1.0 / f.other.length)));
  CHECK(tau[only_best] == Approx(bounded(0.5 * tau_max)));
  // Iteration 4 (an odd count from the reset) finds `best` again: the iteration best deposits it.
  f.context.iteration = 4;
  update->update(f.context, {bests, &bests[0], &bests[0]}, tau);
  CHECK(tau[only_best] == Approx(bounded(0.5 * bounded(0.5 * tau_max) + 1.0 / f.best.length)));
}

TEST_CASE("max_min: restart_branching waits until the colony has converged", "[plugin][max_min]") {
  Fixture f;
  // The first iteration after iteration 0 whose update leaves every edge at tau_max (a reset).
  const auto first_reset = [&f](const char* branching) {
    auto update = test::make<aco::PheromoneUpdate>(
        "update", "max_min", {{"rho", "0.1"}, {"restart_after", "1"}, {"restart_branching", branching}});
    std::vector<double> tau(f.graph.num_edges(), 1.0);
    aco::Context context = f.context;
    update->begin_run(context);
    update->start(context, tau);
    const std::vector<aco::Ant> ants{f.best};
    const double tau_max = 1.0 / (0.1 * f.best.length);
    for (int it = 0; it < 30; ++it) {
      context.iteration = it;
      update->update(context, {ants, &ants[0], &ants[0]}, tau);
      if (it > 0 && std::all_of(tau.begin(), tau.end(), [&](double t) { return t == Approx(tau_max); })) return it;
    }
    return -1;
  };
  CHECK(first_reset("0") == 1);
  // Every walked node keeps all its edges near tau_max until the others evaporate below the
  // lambda cut-off: a few iterations at rho = 0.1.
  const int converged = first_reset("1.5");
  CHECK(converged > 2);
  CHECK(converged < 15);
}
