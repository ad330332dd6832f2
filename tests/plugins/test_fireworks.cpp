#include <catch2/catch.hpp>

#include "aco/error.hpp"
#include "ifwa/fireworks.hpp"
#include "aco/rng.hpp"
#include "support.hpp"

TEST_CASE("fireworks init: tau0 everywhere, plus Q / L_best on the fireworks path's edges only",
          "[plugin][fireworks]") {
  const auto map = test::classic_map(1);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::Context c = test::context(g, {0, 0}, {19, 19});
  c.seed = 7;
  std::vector<double> tau(g.num_edges(), 0.0);
  test::make<aco::PheromoneInit>("init", "fireworks", {{"tau0", "2"}, {"q", "60"}, {"iterations", "8"}})
      ->initialize(c, tau);

  // The same search, run directly with the seed the plugin derives from the context's.
  aco::FireworksSettings s =
      aco::fireworks_settings(aco::resolve(aco::fireworks_parameters(), {{"iterations", "8"}}, ""));
  s.seed = aco::splitmix64(7);
  const auto best = aco::run_fireworks(g, c.start, c.goal, s);
  REQUIRE(best.solved);
  std::vector<bool> on_path(g.num_edges(), false);
  for (std::size_t i = 1; i < best.path.size(); ++i) on_path[g.find_edge(best.path[i - 1], best.path[i])] = true;
  int raised = 0;
  for (aco::EdgeId e = 0; e < g.num_edges(); ++e) {
    INFO("edge " << aco::to_string(g.cell(g.source(e))) << " -> " << aco::to_string(g.cell(g.targets[e])));
    CHECK(tau[e] == (on_path[e] ? 2.0 + 60.0 / best.length : 2.0));
    raised += tau[e] > 2.0;
  }
  CHECK(raised == static_cast<int>(best.path.size()) - 1);  // the path's direction only
}

TEST_CASE("fireworks init: its table is tau0, q and the fireworks table, and bad values are rejected",
          "[plugin][fireworks]") {
  const auto& d = test::plugins().load("init", "fireworks");
  const auto params = d.parameters();
  REQUIRE(params.size() == 2 + aco::fireworks_parameters().size());
  CHECK(std::string(params[0].name) == "tau0");
  CHECK(std::string(params[1].name) == "q");
  for (std::size_t i = 0; i < aco::fireworks_parameters().size(); ++i)
    CHECK(std::string(params[2 + i].name) == aco::fireworks_parameters()[i].name);
  aco::check_table(params, "init/fireworks");
  CHECK_THROWS_WITH(test::make<aco::PheromoneInit>("init", "fireworks", {{"tau0", "0"}}), Catch::Contains("init.tau0"));
  CHECK_THROWS_WITH(test::make<aco::PheromoneInit>("init", "fireworks", {{"radius", "-1"}}),
                    Catch::Contains("init.radius"));
  CHECK_THROWS_AS(test::make<aco::PheromoneInit>("init", "fireworks", {{"a", "0.9"}}), aco::Error);
}

TEST_CASE("fireworks init: an unreachable goal leaves tau0 everywhere", "[plugin][fireworks]") {
  const auto map = test::grid({"..#..", "..#..", "..#.."});
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  std::vector<double> tau(g.num_edges(), 0.0);
  test::make<aco::PheromoneInit>("init", "fireworks", {{"iterations", "2"}})
      ->initialize(test::context(g, {0, 0}, {4, 2}), tau);
  for (double t : tau) CHECK(t == 8.0);
}
