#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

namespace {
// Mean pheromone over the edges into a cell.
double into(const aco::Graph& g, const std::vector<double>& tau, aco::Cell c) {
  const aco::NodeId n = g.node(c);
  double sum = 0;
  for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) sum += tau[g.reverse_edge(e)];
  return sum / g.degree(n);
}
double on(const aco::Graph& g, const std::vector<double>& tau, aco::Cell a, aco::Cell b) {
  return tau[g.find_edge(g.node(a), g.node(b))];
}
double kernel(double x, double psi = 300, double sigma = 1) {
  return psi / std::sqrt(2 * M_PI * sigma) * std::exp(-x * x / (2 * sigma * sigma));
}
}  // namespace

TEST_CASE("gaussian onto edges: each step, shifted by an offset o, gets Q/L * psi * N(|o|)", "[plugin][gaussian]") {
  std::vector<std::string> rows(9, std::string(9, '.'));
  const auto map = test::grid(rows);
  const aco::Graph g = aco::build_graph(map, {});
  auto update = test::make<aco::PheromoneUpdate>("update", "gaussian", {{"rho", "0.5"}, {"q", "2"}, {"cutoff", "1.5"}});
  std::vector<double> tau(g.num_edges(), 1.0);
  const std::vector<aco::Ant> ants{test::ant(g, {{2, 4}, {3, 4}, {4, 5}})};  // length 1 + sqrt 2
  update->update(test::context(g, {2, 4}, {4, 5}), {ants, &ants[0], &ants[0]}, tau);
  const double scale = 2.0 / (1 + std::sqrt(2.0));
  CHECK(on(g, tau, {2, 4}, {3, 4}) == Approx(0.5 + scale * kernel(0)));  // the step itself
  CHECK(on(g, tau, {2, 5}, {3, 5}) == Approx(0.5 + scale * kernel(1)));  // shifted by (0,1)
  CHECK(on(g, tau, {1, 3}, {2, 3}) == Approx(0.5 + scale * kernel(std::sqrt(2.0))));  // by (-1,-1)
  CHECK(on(g, tau, {3, 5}, {4, 6}) == Approx(0.5 + scale * kernel(1)));  // the second step by (0,1)
  CHECK(on(g, tau, {2, 6}, {3, 6}) == Approx(0.5));  // (0,2) is beyond the cutoff
  CHECK(on(g, tau, {3, 4}, {2, 4}) == Approx(0.5));  // the reverse move gets nothing
}

TEST_CASE("gaussian onto cells: each path cell spreads Q/L * psi * N(x) to cells within the cutoff",
          "[plugin][gaussian]") {
  std::vector<std::string> rows(9, std::string(9, '.'));
  const auto map = test::grid(rows);
  const aco::Graph g = aco::build_graph(map, {});
  auto update = test::make<aco::PheromoneUpdate>("update", "gaussian",
                                                 {{"rho", "0.5"}, {"q", "2"}, {"cutoff", "1.5"}, {"onto", "cells"}});
  std::vector<double> tau(g.num_edges(), 1.0);
  const std::vector<aco::Ant> ants{test::ant(g, {{2, 4}, {3, 4}})};  // a two-cell path, length 1
  update->update(test::context(g, {2, 4}, {3, 4}), {ants, &ants[0], &ants[0]}, tau);
  const double scale = 2.0 / 1.0;  // Q / L
  // (2,5) is 1 from (2,4) and sqrt 2 from (3,4): both contribute.
  CHECK(into(g, tau, {2, 5}) == Approx(0.5 + scale * (kernel(1) + kernel(std::sqrt(2.0)))));
  // (3,4) itself: 0 from itself, 1 from (2,4).
  CHECK(into(g, tau, {3, 4}) == Approx(0.5 + scale * (kernel(0) + kernel(1))));
  // (4,5): sqrt 2 from (3,4), sqrt 5 from (2,4), beyond the cutoff 1.5.
  CHECK(into(g, tau, {4, 5}) == Approx(0.5 + scale * kernel(std::sqrt(2.0))));
  // (5,4) is 2 away from the nearest path cell: evaporation only.
  CHECK(into(g, tau, {5, 4}) == Approx(0.5));
  // Every edge into a cell gets the same deposit.
  const aco::NodeId n = g.node({2, 5});
  for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e)
    CHECK(tau[g.reverse_edge(e)] == Approx(into(g, tau, {2, 5})));
}

TEST_CASE("gaussian deposits more on the inside of a bend than on the outside", "[plugin][gaussian]") {
  std::vector<std::string> rows(12, std::string(12, '.'));
  const auto map = test::grid(rows);
  const aco::Graph g = aco::build_graph(map, {});
  // Right along row 8, then up column 7: the bend is at (7,8); inside is up-left of it.
  std::vector<aco::Cell> cells;
  for (int x = 2; x <= 7; ++x) cells.push_back({x, 8});
  for (int y = 7; y >= 3; --y) cells.push_back({7, y});
  const std::vector<aco::Ant> ants{test::ant(g, cells)};
  for (const char* onto : {"edges", "cells"}) {
    auto update = test::make<aco::PheromoneUpdate>("update", "gaussian", {{"onto", onto}});
    std::vector<double> tau(g.num_edges(), 1.0);
    update->update(test::context(g, cells.front(), cells.back()), {ants, &ants[0], &ants[0]}, tau);
    // Mirror cells at the same distance from the corner cell, inside vs outside the bend.
    for (int k = 1; k <= 2; ++k) {
      const double inside = into(g, tau, {7 - k, 8 - k}), outside = into(g, tau, {7 + k, 8 + k});
      INFO(onto << ", k = " << k << ": inside " << inside << ", outside " << outside);
      CHECK(inside > outside);
    }
    // Beside a straight stretch both sides get the same.
    INFO(onto);
    CHECK(into(g, tau, {4, 7}) == Approx(into(g, tau, {4, 9})));
  }
}
