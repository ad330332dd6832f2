#include <catch2/catch.hpp>

#include "support.hpp"

namespace {
struct Pack {
  aco::OccupancyGrid map = test::grid({".....", ".....", "....."});
  aco::Graph g = aco::build_graph(map, {});
  aco::Context c = test::context(g, {0, 0}, {4, 2});
  // Four arrived ants of different lengths (sharing no edge), one dead ant.
  std::vector<aco::Ant> ants{
      test::ant(g, {{0, 0}, {1, 0}, {2, 0}, {3, 1}, {4, 2}}),  // 2 + 2 sqrt 2 = 4.83 (second)
      test::ant(g, {{0, 0}, {1, 1}, {2, 2}, {3, 2}, {4, 2}}),  // 4.83 too, ties keep order: third
      test::ant(g, {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 1}, {3, 0}, {4, 1}, {4, 2}}),  // the longest
      test::ant(g, {{0, 0}, {1, 0}, {2, 1}, {3, 2}, {4, 2}}),  // 4.83 as well
  };
};
double on(const std::vector<double>& tau, const aco::Ant& ant) { return tau[ant.edges[0]]; }
}  // namespace

TEST_CASE("wolf_pack: best reinforced, worst weakened, ordinary ants (1-lambda)*C*Q/L", "[plugin][wolf_pack]") {
  Pack p;
  // A clearly best ant (it need not end at the goal for this check) and a dead one.
  p.ants.push_back(test::ant(p.g, {{0, 0}, {1, 1}, {2, 1}}));  // length 1 + sqrt 2 = 2.41: the best
  aco::Ant dead = test::ant(p.g, {{0, 0}, {0, 1}, {1, 1}});
  dead.arrived = false;
  p.ants.push_back(dead);
  auto update = test::make<aco::PheromoneUpdate>(
      "update", "wolf_pack",
      {{"rho", "0.5"}, {"q", "2"}, {"lambda", "0.1"}, {"a", "3"}, {"b", "0.5"}, {"c", "1.5"}, {"tau_min", "0.001"}});
  std::vector<double> tau(p.g.num_edges(), 1.0);
  const double lb = p.ants[4].length, lw = p.ants[2].length;
  update->update(p.c, {p.ants, &p.ants[4], &p.ants[4]}, tau);
  // Edges used by exactly one ant, so each deposit can be read off alone.
  const double best_edge = tau[p.ants[4].edges[1]];  // (1,1) -> (2,1)
  CHECK(best_edge == Approx(0.5 + 3 * 2 * (lw - lb) / lb));
  const double worst_edge = tau[p.ants[2].edges[0]];  // (0,0) -> (0,1): also the dead ant's, which deposits nothing
  CHECK(worst_edge == Approx(std::max(0.001, 0.5 - 0.5 * 2 * (lw - lb) / lw)));
  const double ordinary = tau[p.ants[0].edges[1]];  // (1,0) -> (2,0)
  CHECK(ordinary == Approx(0.5 + 0.9 * 1.5 * 2 / p.ants[0].length));
  CHECK(tau[p.g.find_edge(p.g.node({4, 0}), p.g.node({3, 0}))] == Approx(0.5));  // untouched: evaporation only
}

TEST_CASE("wolf_pack never lets tau fall below its floor, and ranks by length with ties in ant order",
          "[plugin][wolf_pack]") {
  Pack p;
  auto update = test::make<aco::PheromoneUpdate>(
      "update", "wolf_pack",
      {{"rho", "0.9"}, {"b", "1000"}, {"best_count", "2"}, {"worst_count", "1"}, {"tau_min", "0.05"}});
  std::vector<double> tau(p.g.num_edges(), 0.06);
  for (int it = 0; it < 20; ++it) update->update(p.c, {p.ants, nullptr, nullptr}, tau);
  for (double t : tau) CHECK(t >= 0.05);
  // Ants 0, 1 and 3 tie at the shortest length: the first two in ant order are "best" (their spread
  // deposit is A*Q*(Lw-Lb)/Lb), ant 3 is ordinary.
  std::vector<double> fresh(p.g.num_edges(), 1.0);
  update->update(p.c, {p.ants, nullptr, nullptr}, fresh);
  const double lb = p.ants[0].length, lw = p.ants[2].length;
  // (0,0)->(1,0) is shared by best ant 0 and ordinary ant 3: both deposits land.
  CHECK(on(fresh, p.ants[0]) == Approx(0.1 + 10 * (lw - lb) / lb + 0.95 * 10 / p.ants[3].length));
  CHECK(fresh[p.ants[1].edges[1]] == Approx(0.1 + 10 * (lw - lb) / lb));
  CHECK(fresh[p.ants[3].edges[1]] == Approx(0.1 + 0.95 * 10 / p.ants[3].length));
}
