#include <catch2/catch.hpp>

#include "support.hpp"

TEST_CASE("discard lets a stuck ant die and changes nothing else", "[plugin][discard]") {
  const auto map = test::grid({"...", "..."});
  const aco::Graph graph = aco::build_graph(map, {});
  const auto context = test::context(graph, {0, 0}, {2, 1});
  auto policy = test::make<aco::DeadlockPolicy>("deadlock", "discard");
  const std::vector<aco::NodeId> walk{0, 1, 2};
  CHECK(policy->on_stuck(context, walk) == 0);
  std::vector<double> tau(graph.num_edges(), 1.0);
  std::vector<std::uint8_t> forbidden(graph.num_nodes(), 0);
  aco::Ant dead = test::ant(graph, {{0, 0}, {1, 0}});
  dead.arrived = false;
  const std::vector<aco::Ant> ants{dead};
  aco::Trail tau_trail(tau);
  policy->after_iteration(context, {ants, nullptr, nullptr}, tau_trail, forbidden);
  CHECK(tau == std::vector<double>(graph.num_edges(), 1.0));
  CHECK(forbidden == std::vector<std::uint8_t>(graph.num_nodes(), 0));
}
