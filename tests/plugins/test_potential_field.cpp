#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "aco/potential_field.hpp"
#include "support.hpp"

namespace {

// A small terrain: one digit per cell is its height, '#' a blocked cell. Row 0 is the top.
class HeightMap final : public aco::Map {
 public:
  explicit HeightMap(std::vector<std::string> rows) : rows_(std::move(rows)) {}
  int width() const override { return static_cast<int>(rows_.front().size()); }
  int height() const override { return static_cast<int>(rows_.size()); }
  bool passable(aco::Cell c) const override { return contains(c) && rows_[c.y][c.x] != '#'; }
  Eigen::Vector3d position(aco::Cell c) const override {
    const char h = rows_[c.y][c.x];
    return {double(c.x), double(c.y), h == '#' ? 0.0 : 100.0 * (h - '0')};  // heights in another unit than cells
  }
  std::string name() const override { return "height map"; }

 private:
  std::vector<std::string> rows_;
};

// Start height 5 (cell (0,0)); a hill of 9 at (2,1), a pit of 1 at (6,1), a rise of 7 at (8,1).
const HeightMap kTerrain({
    "555555555",
    "559555157",
    "555555555",
});

const aco::Graph& terrain_graph() {
  static const aco::Graph g = aco::build_graph(kTerrain, {});
  return g;
}

Eigen::Vector2d force_at(const std::vector<Eigen::Vector2d>& forces, const aco::Graph& g, aco::Cell c) {
  return forces[g.node(c)];
}

double edge_value(const aco::Graph& g, const std::vector<double>& values, aco::Cell from, aco::Cell to) {
  const aco::EdgeId e = g.find_edge(g.node(from), g.node(to));
  REQUIRE(e >= 0);
  return values[e];
}

}  // namespace

TEST_CASE("potential field: on a flat empty map the force is k towards the goal", "[potential_field]") {
  const auto map = test::grid({".......", ".......", ".......", "......."});
  const aco::Graph g = aco::build_graph(map, {});
  const aco::Cell goal{5, 1};
  const auto forces = aco::potential_forces(g, g.node({0, 0}), g.node(goal), {2.0, 1.0, 2.0});
  for (aco::NodeId n = 0; n < g.num_nodes(); ++n) {
    INFO("cell " << aco::to_string(g.cell(n)));
    if (n == g.node(goal)) {
      CHECK(forces[n].norm() == 0.0);
      continue;
    }
    const Eigen::Vector2d to_goal = (g.position(g.node(goal)) - g.position(n)).head<2>().normalized();
    CHECK(forces[n].norm() == Approx(2.0));
    CHECK(forces[n].normalized().dot(to_goal) == Approx(1.0));
  }
}

TEST_CASE("potential field: ground above the start height within rho0 pushes away, lower ground does not",
          "[potential_field]") {
  const aco::Graph& g = terrain_graph();
  const aco::PotentialFieldGains repulsion_only{0.0, 1.0, 2.0};
  const auto forces = aco::potential_forces(g, g.node({0, 0}), g.node({8, 2}), repulsion_only);
  // The hill (h = 1) at distance 1 pushes with (1/1 - 1/2) / 1^2 = 0.5, directly away.
  CHECK(force_at(forces, g, {3, 1}).isApprox(Eigen::Vector2d(0.5, 0.0)));
  CHECK(force_at(forces, g, {1, 1}).isApprox(Eigen::Vector2d(-0.5, 0.0)));
  CHECK(force_at(forces, g, {2, 0}).isApprox(Eigen::Vector2d(0.0, -0.5)));
  // At distance sqrt 2: (1/sqrt2 - 1/2) / 2, along the diagonal away from the hill.
  const double diagonal = (1.0 / std::sqrt(2.0) - 0.5) / 2.0;
  CHECK(force_at(forces, g, {3, 2}).isApprox(diagonal * Eigen::Vector2d(1.0, 1.0).normalized()));
  // The rise of 7 is half as high above the start as the hill (h = 0.5).
  CHECK(force_at(forces, g, {7, 1}).isApprox(Eigen::Vector2d(-0.25, 0.0)));
  // At rho0 and beyond nothing; the pit below the start pushes nothing.
  CHECK(force_at(forces, g, {4, 1}).norm() == 0.0);
  CHECK(force_at(forces, g, {5, 1}).norm() == 0.0);
  CHECK(force_at(forces, g, {6, 0}).norm() == 0.0);

  // Seen from the hilltop nothing is higher: no repulsion anywhere.
  for (const auto& f : aco::potential_forces(g, g.node({2, 1}), g.node({8, 2}), repulsion_only)) CHECK(f.norm() == 0.0);
}

TEST_CASE("potential field: on flat maps obstacles push like the highest ground", "[potential_field]") {
  const auto map = test::grid({".....", "..#..", "....."});
  const aco::Graph g = aco::build_graph(map, {});
  const auto forces = aco::potential_forces(g, g.node({0, 0}), g.node({4, 1}), {1.0, 1.0, 2.0});
  // (3,1): attraction (1, 0) towards the goal next door, plus 0.5 away from the obstacle.
  CHECK(force_at(forces, g, {3, 1}).isApprox(Eigen::Vector2d(1.5, 0.0)));
  // (1,1): attraction (1, 0), repulsion (-0.5, 0): the obstacle slows the approach.
  CHECK(force_at(forces, g, {1, 1}).isApprox(Eigen::Vector2d(0.5, 0.0)));
  CHECK(force_at(forces, g, {2, 1}).norm() == 0.0);  // the obstacle itself
}

TEST_CASE("potential_field init: positive, finite, higher on moves that follow the force",
          "[plugin][potential_field]") {
  const auto map = test::grid({".....", ".....", "....."});
  const aco::Graph g = aco::build_graph(map, {});
  std::vector<double> tau(g.num_edges(), 0.0);
  test::make<aco::PheromoneInit>("init", "potential_field", {{"tau0", "4"}, {"floor", "0.2"}})
      ->initialize(test::context(g, {0, 1}, {4, 1}), tau);
  for (double t : tau) {
    CHECK(t > 0.0);
    CHECK(std::isfinite(t));
  }
  // The force at (1,1) is (1, 0): along it tau0, against it tau0 * floor, across it half-way.
  CHECK(edge_value(g, tau, {1, 1}, {2, 1}) == Approx(4.0));
  CHECK(edge_value(g, tau, {1, 1}, {0, 1}) == Approx(4.0 * 0.2));
  CHECK(edge_value(g, tau, {1, 1}, {1, 0}) == Approx(4.0 * (0.2 + 0.8 * 0.5)));
  CHECK(edge_value(g, tau, {1, 1}, {2, 0}) == Approx(4.0 * (0.2 + 0.8 * 0.5 * (1.0 + std::sqrt(0.5)))));

  // On terrain, without attraction: away from the hill beats towards it.
  const aco::Graph& t = terrain_graph();
  std::vector<double> tau_t(t.num_edges(), 0.0);
  test::make<aco::PheromoneInit>("init", "potential_field", {{"k", "0"}})
      ->initialize(test::context(t, {0, 0}, {8, 2}), tau_t);
  CHECK(edge_value(t, tau_t, {3, 1}, {4, 1}) > edge_value(t, tau_t, {3, 1}, {2, 1}));
  CHECK(edge_value(t, tau_t, {5, 1}, {6, 1}) == Approx(edge_value(t, tau_t, {5, 1}, {4, 1})));  // no force by the pit
}

TEST_CASE("potential_field heuristic: the force term fades as ((it_max - it) / it_max)^3",
          "[plugin][potential_field]") {
  const auto map = test::grid({"......", "......", "......"});
  const aco::Graph g = aco::build_graph(map, {});
  auto h = test::make<aco::Heuristic>("heuristic", "potential_field", {{"a", "2"}});
  REQUIRE(h->specs().varies_by_iteration);
  std::vector<double> eta(g.num_edges()), plain(g.num_edges());
  test::make<aco::Heuristic>("heuristic", "distance")->compute(test::context(g, {0, 1}, {5, 1}), plain);
  // At (1,1) the force points east, straight at the goal (5,1).
  const aco::EdgeId east = g.find_edge(g.node({1, 1}), g.node({2, 1}));
  const aco::EdgeId north_east = g.find_edge(g.node({1, 1}), g.node({2, 0}));
  const aco::EdgeId west = g.find_edge(g.node({1, 1}), g.node({0, 1}));
  h->begin_run(test::context(g, {0, 1}, {5, 1}, 0, 100));
  for (int iteration : {0, 49, 99}) {
    INFO("iteration " << iteration + 1);
    h->compute(test::context(g, {0, 1}, {5, 1}, iteration, 100), eta);
    const double w = std::pow((100.0 - (iteration + 1)) / 100.0, 3);
    CHECK(eta[east] == Approx(plain[east] * (1.0 + 2.0 * w)));
    CHECK(eta[north_east] == Approx(plain[north_east] * (1.0 + 2.0 * w * std::sqrt(0.5))));
    CHECK(eta[west] == Approx(plain[west]));  // against the force: no boost
  }
  // In the last iteration it is the plain distance heuristic everywhere, the goal included.
  CHECK(eta == plain);
}

TEST_CASE("potential_field heuristic: fast eta^beta equals pow(eta, beta) in every iteration",
          "[plugin][potential_field]") {
  for (double beta : {7.0, 7.3}) {
    auto h = test::make<aco::Heuristic>("heuristic", "potential_field", {{"a", "0.7"}});
    const aco::Graph& g = terrain_graph();
    std::vector<double> fast(g.num_edges()), eta(g.num_edges());
    for (int it = 0; it < 20; ++it) {
      auto c = test::context(g, {0, 0}, {8, 2}, it, 20);
      c.beta = beta;
      if (it == 0) h->begin_run(c);
      h->compute_powered(c, fast);
      h->compute(c, eta);
      for (std::size_t e = 0; e < eta.size(); ++e) REQUIRE(fast[e] == Approx(std::pow(eta[e], beta)).epsilon(1e-12));
    }
  }
}

TEST_CASE("paper 000 plugins together solve classic map1, bit-identically for any thread count",
          "[plugin][potential_field][elite][determinism]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::ColonySettings settings;
  settings.seed = 3;
  settings.q0 = 0.8;  // paper 000's exploitation
  const aco::ColonyResult result = test::run_on_thread_counts(
      graph, 0, graph.node({19, 19}), settings, {"potential_field", "potential_field", "elite", "discard"});
  REQUIRE(result.solved);
  CHECK(result.length < 1.05 * 34.3848);  // within 5 % of the optimum
}
