#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "support.hpp"

namespace {

const aco::OccupancyGrid kMap = test::grid({"....", "....", "...."});

// Pheromone after one update at the given iteration (0-based, of 100), starting from 1 on every
// edge, local update off so only evaporation and deposits act.
std::vector<double> after_update(aco::PheromoneUpdate& update, const aco::Graph& g, const std::vector<aco::Ant>& ants,
                                 int iteration) {
  const auto c = test::context(g, {0, 0}, {3, 2}, iteration, 100);
  std::vector<double> tau(g.num_edges(), 1.0);
  update.start(c, tau);
  std::fill(tau.begin(), tau.end(), 1.0);
  update.update(c, {ants, &ants[0], &ants[0]}, tau);
  return tau;
}

}  // namespace

TEST_CASE("elite: Ant System deposits plus elite_q * (it/it_max)^3 / L for the best ants", "[plugin][elite]") {
  const aco::Graph g = aco::build_graph(kMap, {});
  // Three edge-disjoint paths of different lengths, and an ant that did not arrive.
  std::vector<aco::Ant> ants{
      test::ant(g, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3, 1}, {3, 2}}),  // the longest
      test::ant(g, {{0, 0}, {1, 1}, {2, 2}, {3, 2}}),  // the shortest
      test::ant(g, {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 1}, {3, 2}}),
      test::ant(g, {{0, 0}, {1, 0}}),
  };
  ants[3].arrived = false;
  const std::map<std::string, std::string> common{{"rho", "0.2"}, {"local_rho", "0"}, {"elite_q", "3"}};
  auto elite = test::make<aco::PheromoneUpdate>("update", "elite", [&] {
    auto p = common;
    p["elite_fraction"] = "0.5";  // floor(0.5 * 3 arrived) = 1 elite: the shortest ant
    return p;
  }());
  auto baseline = test::make<aco::PheromoneUpdate>("update", "ant_system", {{"rho", "0.2"}});

  std::vector<double> extra;
  for (int it : {25, 50, 100}) {
    INFO("iteration " << it);
    const auto with_elite = after_update(*elite, g, ants, it - 1);
    const auto plain = after_update(*baseline, g, ants, it - 1);
    const double shortest = ants[1].length;
    for (aco::EdgeId e : ants[1].edges)
      CHECK(with_elite[e] - plain[e] == Approx(3.0 * std::pow(it / 100.0, 3) / shortest));
    for (std::size_t e = 0; e < plain.size(); ++e)
      if (std::find(ants[1].edges.begin(), ants[1].edges.end(), aco::EdgeId(e)) == ants[1].edges.end())
        CHECK(with_elite[e] == Approx(plain[e]));  // non-elite edges: Ant System exactly
    extra.push_back(with_elite[ants[1].edges[0]] - plain[ants[1].edges[0]]);
  }
  CHECK(extra[1] / extra[0] == Approx(8.0));  // (50/25)^3
  CHECK(extra[2] / extra[0] == Approx(64.0));  // (100/25)^3
}

TEST_CASE("elite: max(1, floor(fraction * arrived)) shortest ants are elite", "[plugin][elite]") {
  const aco::Graph g = aco::build_graph(kMap, {});
  // Every ant walks the same path; only the lengths tell them apart (10, 11, 12, ...).
  const aco::Ant path = test::ant(g, {{0, 0}, {1, 1}, {2, 2}, {3, 2}});
  auto ants_with = [&](int arrived, int stuck) {
    std::vector<aco::Ant> ants;
    for (int k = 0; k < arrived + stuck; ++k) {
      aco::Ant a = path;
      a.length = 10.0 + (arrived + stuck - 1 - k);  // the shortest ants last: order must not matter
      a.arrived = k >= stuck;
      ants.push_back(a);
    }
    return ants;
  };
  auto elite = test::make<aco::PheromoneUpdate>("update", "elite", {{"local_rho", "0"}, {"elite_q", "1"}});
  auto no_elite = test::make<aco::PheromoneUpdate>("update", "elite", {{"local_rho", "0"}, {"elite_fraction", "0"}});
  auto elite_deposit = [&](int arrived, int stuck) {
    const auto ants = ants_with(arrived, stuck);
    const aco::EdgeId e = path.edges[0];
    return after_update(*elite, g, ants, 99)[e] - after_update(*no_elite, g, ants, 99)[e];
  };
  CHECK(elite_deposit(50, 0) == Approx(1.0 / 10 + 1.0 / 11));  // 5 % of 50 = 2.5: 2 elites
  CHECK(elite_deposit(40, 10) == Approx(1.0 / 10 + 1.0 / 11));  // 5 % of the 40 arrived = 2
  CHECK(elite_deposit(39, 0) == Approx(1.0 / 10));  // floor(1.95) = 1
  CHECK(elite_deposit(5, 0) == Approx(1.0 / 10));  // floor(0.25) = 0, at least 1
}

TEST_CASE("elite: local update pulls walked edges towards the start field, scaled to ants * Q / d(S, E)",
          "[plugin][elite]") {
  const aco::Graph g = aco::build_graph(kMap, {});
  auto elite = test::make<aco::PheromoneUpdate>("update", "elite", {{"local_rho", "0.5"}, {"rho", "0"}, {"q", "2"}});
  const auto c = test::context(g, {0, 0}, {3, 2}, 0, 100);  // 10 ants
  std::vector<double> tau(g.num_edges(), 1.0);
  elite->start(c, tau);
  const double tau0 = 10 * 2.0 / std::sqrt(13.0);
  for (double t : tau) CHECK(t == Approx(tau0));
  std::vector<aco::Ant> ants{test::ant(g, {{0, 0}, {1, 0}})};
  ants[0].arrived = false;  // no deposit: only the local update acts
  for (aco::EdgeId e : ants[0].edges) tau[e] = 4.0 * tau0;
  elite->update(c, {ants, nullptr, nullptr}, tau);
  CHECK(tau[ants[0].edges[0]] == Approx(2.5 * tau0));
  CHECK(tau[g.find_edge(g.node({1, 1}), g.node({2, 1}))] == Approx(tau0));
}
