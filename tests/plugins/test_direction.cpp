#include <catch2/catch.hpp>
#include <cmath>

#include "aco/path.hpp"
#include "aco/engine/pipeline.hpp"
#include "support.hpp"

namespace {

// The candidates of a step from `from` after arriving from `before`, and their factors.
std::map<std::pair<int, int>, double> factors_after(const aco::Graph& g, aco::Heuristic& h, const aco::Context& c,
                                                    aco::Cell before, aco::Cell from) {
  const aco::Ant walk = test::ant(g, {before, from});
  std::vector<aco::EdgeId> candidates;
  const aco::NodeId n = g.node(from);
  for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) candidates.push_back(e);
  std::vector<double> factors(candidates.size());
  h.step_factors(c, walk, candidates, factors);
  std::map<std::pair<int, int>, double> by_cell;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const aco::Cell to = g.cell(g.targets[candidates[i]]);
    by_cell[{to.x, to.y}] = factors[i];
  }
  return by_cell;
}

}  // namespace

TEST_CASE("direction: eta = 1 / (d(next, goal) + gamma * |turn| / pi), raised to beta", "[plugin][direction]") {
  const auto map = test::grid({".....", ".....", ".....", ".....", "....."});
  const aco::Graph g = aco::build_graph(map, {});
  auto context = test::context(g, {0, 2}, {4, 4});
  context.beta = 2.0;
  auto h = test::make<aco::Heuristic>("heuristic", "direction", {{"gamma", "3"}});
  REQUIRE(h->specs().uses_walk);
  std::vector<double> eta(g.num_edges());
  h->compute(context, eta);
  // The table holds the turn-free part, 1 / d(next, goal).
  CHECK(eta[g.find_edge(g.node({1, 2}), g.node({2, 3}))] == Approx(1 / std::sqrt(5.0)));
  // Heading +x (from (0,2) to (1,2)). The factor turns 1/d into 1/(d + gamma*turn) at power beta.
  const auto f = factors_after(g, *h, context, {0, 2}, {1, 2});
  auto expected = [&](aco::Cell to, double turn) {
    const double d = std::hypot(4 - to.x, 4 - to.y);
    return std::pow(d / (d + 3 * turn), 2.0);
  };
  CHECK(f.at({2, 2}) == Approx(1.0));  // straight on
  CHECK(f.at({2, 3}) == Approx(expected({2, 3}, 0.25)));  // 45 degrees
  CHECK(f.at({1, 3}) == Approx(expected({1, 3}, 0.5)));  // 90 degrees
  CHECK(f.at({0, 3}) == Approx(expected({0, 3}, 0.75)));  // 135 degrees
  CHECK(f.at({0, 2}) == Approx(expected({0, 2}, 1.0)));  // U-turn
  CHECK(f.at({2, 1}) == Approx(f.at({2, 3})).epsilon(0.3));  // left and right turns: same angle
  CHECK(f.at({2, 1}) == Approx(expected({2, 1}, 0.25)));
  // Before the first move there is no heading: every factor is 1.
  std::vector<aco::EdgeId> first{g.edges_begin(g.node({0, 2}))};
  std::vector<double> one(1, 0.0);
  aco::Ant start;
  start.nodes = {g.node({0, 2})};
  h->step_factors(context, start, first, one);
  CHECK(one[0] == 1.0);
}

TEST_CASE("direction with gamma 0 is the distance heuristic, and distance=step uses the step length",
          "[plugin][direction]") {
  const auto map = test::grid({"....", "....", "...."});
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::sixteen, false});
  const auto context = test::context(g, {0, 0}, {3, 2});
  std::vector<double> a(g.num_edges()), b(g.num_edges());
  auto flat = test::make<aco::Heuristic>("heuristic", "direction", {{"gamma", "0"}});
  flat->compute(context, a);
  test::make<aco::Heuristic>("heuristic", "distance")->compute(context, b);
  for (std::size_t e = 0; e < a.size(); ++e) CHECK(a[e] == Approx(b[e]));
  for (const auto& [cell, factor] : factors_after(g, *flat, context, {0, 1}, {1, 1})) CHECK(factor == 1.0);

  auto step = test::make<aco::Heuristic>("heuristic", "direction", {{"gamma", "1"}, {"distance", "step"}});
  step->compute(context, a);
  for (aco::EdgeId e = 0; e < g.num_edges(); ++e) CHECK(a[e] == Approx(1.0 / g.cost(e)));
  // Knight move (1,2) after heading +x: d = sqrt 5, turn = atan2(2,1) / pi.
  const auto f = factors_after(g, *step, context, {0, 0}, {1, 0});
  const double turn = std::atan2(2.0, 1.0) / M_PI;
  CHECK(f.at({2, 2}) == Approx(std::sqrt(5.0) / (std::sqrt(5.0) + turn)));  // beta = 1 in test::context
}

TEST_CASE("direction gives fewer turns than distance on an open map", "[plugin][direction]") {
  std::vector<std::string> rows(20, std::string(30, '.'));
  const auto map = test::grid(rows);
  const aco::Graph g = aco::build_graph(map, {});
  auto mean_turns = [&](const std::string& heuristic) {
    double turns = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const auto p = aco::instantiate(test::plugins(), test::pipeline({{"heuristic", heuristic}}));
      aco::ColonySettings s;
      s.seed = seed;
      s.iterations = 50;
      const auto r = aco::run_colony(g, g.node({0, 2}), g.node({29, 17}), p.strategies(), s);
      REQUIRE(r.solved);
      turns += aco::count_turns(aco::to_waypoints(g, r.path));
    }
    return turns / 20;
  };
  const double with_direction = mean_turns("direction"), with_distance = mean_turns("distance");
  INFO("mean turns: direction " << with_direction << ", distance " << with_distance);
  CHECK(with_direction < with_distance);
}
