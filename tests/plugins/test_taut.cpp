// smoother/taut: the shortest continuous path in the grid path's corridor (issue 40).
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/astar.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/terrain.hpp"
#include "support.hpp"

namespace {

aco::Waypoints smooth(const std::string& name, const aco::Graph& g, const std::vector<aco::NodeId>& path,
                      const std::map<std::string, std::string>& params = {}) {
  const auto smoother = test::make<aco::Smoother>("smoother", name, params);
  return smoother->smooth(test::context(g, g.cell(path.front()), g.cell(path.back())), path);
}

aco::Waypoints taut(const aco::Graph& g, const std::vector<aco::NodeId>& path,
                    const std::map<std::string, std::string>& params = {}) {
  return smooth("taut", g, path, params);
}

std::vector<aco::NodeId> nodes(const aco::Graph& g, const std::vector<aco::Cell>& cells) {
  std::vector<aco::NodeId> v;
  for (const auto& c : cells) v.push_back(g.node(c));
  return v;
}

// What plan() demands of a smoother, and what any_angle.hpp demands of a continuous path.
void check_valid(const aco::Graph& g, const std::vector<aco::NodeId>& path, const aco::Waypoints& r) {
  CHECK(aco::waypoint_problem(g, path.front(), path.back(), r) == "");
  CHECK(aco::any_angle_path_valid(*g.map, r));
  CHECK(aco::polyline_length(r) <= aco::path_length(g, path) + 1e-9);
}

}  // namespace

TEST_CASE("taut: declared parameters and trivial paths", "[plugin][taut]") {
  const auto& d = test::plugins().load("smoother", "taut");
  REQUIRE(d.parameters().size() == 3);
  CHECK(d.parameters()[0].name == std::string("corridor_width"));
  CHECK(d.parameters()[1].name == std::string("rounds"));
  CHECK(d.parameters()[2].name == std::string("clearance"));
  const auto map = test::grid({"....", "...."});
  const auto g = aco::build_graph(map, {});
  CHECK(taut(g, nodes(g, {{1, 1}})) == aco::Waypoints{g.position(g.node({1, 1}))});
  const auto step = nodes(g, {{0, 0}, {1, 1}});
  CHECK(taut(g, step) == aco::to_waypoints(g, step));
  CHECK_THROWS(taut(g, step, {{"rounds", "0"}}));
  CHECK_THROWS(taut(g, step, {{"clearance", "0.6"}}));
}

TEST_CASE("taut: around a wall with one way past it, the analytic shortest path", "[plugin][taut]") {
  // The wall hangs from the top edge: the only way round is under its lower end, whose corners
  // (4.5, 3.5) and (5.5, 3.5) the taut path turns at.
  const auto map = test::grid({
      ".....#.....",
      ".....#.....",
      ".....#.....",
      ".....#.....",
      "...........",
      "...........",
  });
  const auto g = aco::build_graph(map, {});
  const auto best = aco::astar(g, g.node({0, 0}), g.node({10, 0}));
  REQUIRE(best);
  const auto r = taut(g, best->nodes);
  check_valid(g, best->nodes, r);
  const double analytic = 2 * std::hypot(4.5, 3.5) + 1;
  CHECK(aco::polyline_length(r) == Approx(analytic).epsilon(1e-12));
  const auto optimum = aco::any_angle_optimum(map, {0, 0}, {10, 0});
  REQUIRE(optimum);
  CHECK(std::abs(aco::polyline_length(r) - optimum->length) <= 1e-9);
  CHECK(r.size() == 4);  // start, the two corners, goal
}

TEST_CASE("taut: a grid path round the far side of a block stays on that side", "[plugin][taut]") {
  // The block (x 5..6, y 2..3) is nearer the top edge: the shortest way passes above it, but the
  // grid path given runs below. The corridor keeps that homotopy class: the result is the
  // shortest path below, turning at the block's lower corners (4.5, 3.5) and (6.5, 3.5).
  const auto map = test::grid({
      "............",
      "............",
      ".....##.....",
      ".....##.....",
      "............",
      "............",
      "............",
      "............",
  });
  const auto g = aco::build_graph(map, {});
  std::vector<aco::Cell> path{{0, 2}, {1, 3}, {2, 4}, {3, 5}};
  for (int x = 4; x <= 7; ++x) path.push_back({x, 5});
  path.insert(path.end(), {{8, 5}, {9, 4}, {10, 3}, {11, 2}});
  const auto p = nodes(g, path);
  const auto r = taut(g, p, {{"corridor_width", "1"}});
  check_valid(g, p, r);
  const double below_length = 2 * std::hypot(4.5, 1.5) + 2;
  CHECK(aco::polyline_length(r) == Approx(below_length).epsilon(1e-12));
  const auto optimum = aco::any_angle_optimum(map, {0, 2}, {11, 2});
  REQUIRE(optimum);
  CHECK(optimum->length == Approx(2 * std::hypot(4.5, 0.5) + 2).epsilon(1e-12));  // above
  CHECK(aco::polyline_length(r) > optimum->length + 0.4);
}

TEST_CASE("taut on random maps: valid, never below the optimum, never above prune", "[plugin][taut]") {
  std::mt19937 rng(40);
  int shorter_than_prune = 0, optimal = 0, runs = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto [map, s, t] = test::random_problem(rng, 4, 30);
    for (auto n : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
      for (bool cc : {false, true}) {
        INFO("trial " << trial << ", neighbourhood " << static_cast<int>(n) << ", corner cutting " << cc);
        const auto g = aco::build_graph(map, {n, cc});
        const auto best = aco::astar(g, g.node(s), g.node(t));
        if (!best) continue;
        const auto r = taut(g, best->nodes);
        CHECK(aco::waypoint_problem(g, best->nodes.front(), best->nodes.back(), r) == "");
        const double length = aco::polyline_length(r);
        CHECK(length <= best->length + 1e-9);
        CHECK(taut(g, best->nodes) == r);  // deterministic
        if (cc) continue;  // a corner-cutting squeeze is no path of any_angle.hpp's rule
        ++runs;
        CHECK(aco::any_angle_path_valid(map, r));
        const auto optimum = aco::any_angle_optimum(map, s, t);
        REQUIRE(optimum);
        CHECK(length >= optimum->length - 1e-9);
        optimal += length <= optimum->length + 1e-9;
        const double pruned = aco::polyline_length(smooth("prune", g, best->nodes));
        CHECK(length <= pruned + 1e-9);
        shorter_than_prune += length < pruned - 1e-9;
      }
    }
  }
  CHECK(shorter_than_prune > runs / 4);
  CHECK(optimal > runs / 2);
}

TEST_CASE("taut with clearance: prune's rule with that clearance", "[plugin][taut]") {
  for (int m = 1; m <= 3; ++m) {
    const auto map = test::classic_map(m);
    const auto g = aco::build_graph(map, {});
    const auto best = aco::astar(g, g.node({0, 0}), g.node({19, 19}));
    REQUIRE(best);
    const auto clear = taut(g, best->nodes, {{"clearance", "0.4"}});
    CHECK(clear == smooth("prune", g, best->nodes, {{"clearance", "0.4"}}));
    CHECK(aco::polyline_length(clear) > aco::polyline_length(taut(g, best->nodes)));
  }
}

TEST_CASE("taut on terrain: shortcuts only where the surface is shorter", "[plugin][taut]") {
  // A ridge 10 high across x = 4 with a gap at the bottom row, cells 2 wide: the chord over the
  // ridge is short in the plane but long over the surface, so the path keeps to the gap.
  std::vector<double> heights;
  const int w = 9, h = 5;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) heights.push_back(x == 4 && y < h - 1 ? 10.0 : 0.0);
  const aco::TerrainMap ridge(w, h, 2.0, heights, 90, "ridge");
  const auto g = aco::build_graph(ridge, {});
  const auto best = aco::astar(g, g.node({0, 0}), g.node({8, 0}));
  REQUIRE(best);
  const auto r = taut(g, best->nodes);
  CHECK(aco::waypoint_problem(g, best->nodes.front(), best->nodes.back(), r) == "");
  CHECK(aco::polyline_length(r) <= best->length + 1e-9);
  CHECK(r.size() == 3);  // straight runs joined: start, the gap, goal
  for (const auto& p : r) CHECK(p.z() < 10.0);  // never on the ridge
  // prune's chords cross the ridge; its reported length is the chord's, not the surface's.
  const auto pruned = smooth("prune", g, best->nodes);
  CHECK(pruned.size() == 2);

  // On a flat terrain the result is the straight line, measured in planning units.
  const aco::TerrainMap flat(w, h, 2.0, std::vector<double>(w * h, 3.0), 90, "flat");
  const auto gf = aco::build_graph(flat, {});
  const auto straight = aco::astar(gf, gf.node({0, 0}), gf.node({8, 3}));
  REQUIRE(straight);
  const auto rf = taut(gf, straight->nodes);
  CHECK(aco::polyline_length(rf) == Approx(2 * std::hypot(8, 3)).epsilon(1e-12));
  CHECK(rf.front() == gf.position(gf.node({0, 0})));
  CHECK(rf.back() == gf.position(gf.node({8, 3})));
}
