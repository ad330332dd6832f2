#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

TEST_CASE("adaptive: eta = (1 / (d_ij + d_jE))^w with w fading from 2 to 1", "[plugin][adaptive]") {
  const auto map = test::grid({".....", "..#..", "....."});
  const aco::Graph g = aco::build_graph(map, {});
  auto h = test::make<aco::Heuristic>("heuristic", "adaptive");
  REQUIRE(h->specs().varies_by_iteration);
  std::vector<double> eta(g.num_edges());
  const aco::EdgeId e = g.find_edge(g.node({0, 0}), g.node({1, 1}));
  const double base = 1.0 / (std::sqrt(2.0) + std::hypot(3.0, 1.0));  // d_ij + d_jE, goal (4,2)
  for (int it : {0, 49, 99}) {
    const auto c = test::context(g, {0, 0}, {4, 2}, it, 100);
    h->compute(c, eta);
    const double w = 1.0 + (100.0 - (it + 1)) / 100.0;
    CHECK(eta[e] == Approx(std::pow(base, w)));
  }
  auto literal = test::make<aco::Heuristic>("heuristic", "adaptive", {{"fade", "factor"}});
  literal->compute(test::context(g, {0, 0}, {4, 2}, 0, 100), eta);
  CHECK(eta[e] == Approx(base * 1.99));
}

TEST_CASE("adaptive's incremental eta^beta equals pow(eta, beta) in every iteration", "[plugin][adaptive]") {
  const auto map = test::grid({"......", "..##..", "......", "......"});
  const aco::Graph g = aco::build_graph(map, {});
  for (const char* fade : {"exponent", "factor"}) {
    auto h = test::make<aco::Heuristic>("heuristic", "adaptive", {{"fade", fade}});
    std::vector<double> fast(g.num_edges()), eta(g.num_edges());
    for (int it = 0; it < 100; ++it) {
      auto c = test::context(g, {0, 0}, {5, 3}, it, 100);
      c.beta = 7.3;
      h->compute_powered(c, fast);
      h->compute(c, eta);
      for (std::size_t e = 0; e < eta.size(); ++e) REQUIRE(fast[e] == Approx(std::pow(eta[e], 7.3)).epsilon(1e-10));
    }
  }
}
