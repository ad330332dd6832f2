#include <catch2/catch.hpp>

#include "support.hpp"

TEST_CASE("backtrack_penalty: a stuck ant dies and the pheromone into its last h nodes is cut",
          "[plugin][backtrack_penalty]") {
  std::vector<std::string> rows(3, std::string(8, '.'));
  const auto map = test::grid(rows);
  const aco::Graph g = aco::build_graph(map, {});
  const auto c = test::context(g, {0, 1}, {7, 1});
  auto policy = test::make<aco::DeadlockPolicy>("deadlock", "backtrack_penalty", {{"h", "3"}, {"penalty", "0.25"}});
  aco::Ant dead = test::ant(g, {{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {5, 1}});
  dead.arrived = false;
  CHECK(policy->on_stuck(c, dead.nodes) == 0);  // the ant dies
  aco::Ant alive = test::ant(g, {{0, 1}, {1, 0}, {2, 0}});
  std::vector<double> tau(g.num_edges(), 2.0);
  std::vector<std::uint8_t> forbidden(g.num_nodes(), 0);
  const std::vector<aco::Ant> ants{dead, alive};
  aco::Trail tau_trail(tau);
  policy->after_iteration(c, {ants, nullptr, nullptr}, tau_trail, forbidden);
  for (aco::NodeId n = 0; n < g.num_nodes(); ++n) {
    const aco::Cell cell = g.cell(n);
    const bool penalised = cell.y == 1 && cell.x >= 3 && cell.x <= 5;  // the last three nodes
    for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) {
      INFO("edge into " << aco::to_string(cell));
      CHECK(tau[g.reverse_edge(e)] == Approx(penalised ? 0.5 : 2.0));
    }
  }
  CHECK(forbidden == std::vector<std::uint8_t>(g.num_nodes(), 0));
  // A walk shorter than h never penalises the start.
  aco::Ant short_walk = test::ant(g, {{0, 1}, {1, 1}});
  short_walk.arrived = false;
  std::vector<double> t2(g.num_edges(), 2.0);
  const std::vector<aco::Ant> one{short_walk};
  aco::Trail t2_trail(t2);
  policy->after_iteration(c, {one, nullptr, nullptr}, t2_trail, forbidden);
  const aco::NodeId start = g.node({0, 1});
  for (aco::EdgeId e = g.edges_begin(start); e < g.edges_end(start); ++e) CHECK(t2[g.reverse_edge(e)] == 2.0);
  const aco::NodeId second = g.node({1, 1});
  for (aco::EdgeId e = g.edges_begin(second); e < g.edges_end(second); ++e) CHECK(t2[g.reverse_edge(e)] == Approx(0.5));
}
