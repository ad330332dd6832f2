// The unit test of update/rank_based_as: it loads the plugin from the library the build made.
#define CATCH_CONFIG_MAIN
#include "aco/sdk/testing.hpp"

TEST_CASE("update/rank_based_as passes the conformance checks", "[rank_based_as]") {
  aco::testing::check_conformance(PLUGIN_FILE);
}

// Four arrived ants on a 1x6 corridor walk its first k edges (lengths 5, 4, 3, 2: the goal is
// at their end only for the first, so the others are declared arrived by hand: the rule reads
// lengths and edges, not the map). Edge i of the corridor is used by every ant longer than i.
TEST_CASE("update/rank_based_as: evaporation, then (w - r) Q / L_r for the w - 1 best, w Q / L_best",
          "[rank_based_as]") {
  const auto problem = aco::testing::make_problem("corridor", {"......"}, {0, 0}, {5, 0});
  std::vector<aco::Ant> ants;
  for (const int k : {5, 4, 3, 2}) {
    std::vector<aco::NodeId> nodes;
    for (int x = 0; x <= k; ++x) nodes.push_back(problem.graph.node({x, 0}));
    ants.push_back(aco::testing::walk(problem, nodes));
    ants.back().arrived = true;
  }
  const aco::Ant best_so_far = ants[3];  // length 2
  const aco::Iteration iteration{ants, &ants[3], &best_so_far};
  // w = 3: ranks 1 and 2 (lengths 2 and 3) deposit 2 Q / 2 and 1 Q / 3; the best so far 3 Q / 2.
  auto update = aco::testing::create<aco::PheromoneUpdate>(PLUGIN_FILE, {{"w", "3"}, {"rho", "0.5"}, {"q", "2"}});
  std::vector<double> tau(problem.graph.num_edges(), 1.0);
  update->update(problem.context(), iteration, tau);
  auto edge = [&](int x) {
    return tau[problem.graph.find_edge(problem.graph.node({x, 0}), problem.graph.node({x + 1, 0}))];
  };
  const double rank1 = 2 * 2.0 / 2, rank2 = 1 * 2.0 / 3, best = 3 * 2.0 / 2;
  CHECK(edge(0) == Approx(0.5 + rank1 + rank2 + best));
  CHECK(edge(1) == Approx(0.5 + rank1 + rank2 + best));
  CHECK(edge(2) == Approx(0.5 + rank2));  // only the ant of length 3 (rank 2) walked it
  CHECK(edge(3) == Approx(0.5));  // the ants of length 4 and 5 rank 3 and 4: no deposit
  CHECK(tau[problem.graph.find_edge(problem.graph.node({1, 0}), problem.graph.node({0, 0}))] == Approx(0.5));
}

TEST_CASE("update/rank_based_as: w = 1 leaves the best path so far as the only deposit", "[rank_based_as]") {
  const auto problem = aco::testing::standard_problems().front();
  const aco::testing::IterationCase ants = aco::testing::standard_iterations(problem).front();
  auto update = aco::testing::create<aco::PheromoneUpdate>(PLUGIN_FILE, {{"w", "1"}, {"rho", "0"}});
  std::vector<double> tau(problem.graph.num_edges(), 1.0);
  update->update(problem.context(), ants.view(), tau);
  const aco::Ant& best = *ants.view().best_so_far;
  double total = 0;
  for (const double t : tau) total += t - 1.0;
  CHECK(total == Approx(best.edges.size() * 1.0 / best.length));
}
