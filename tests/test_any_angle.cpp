// The any-angle yardstick (aco/any_angle.hpp): the segment rule, hand-made optima, the bound
// ordering euclidean <= any-angle <= Theta* <= octile A* on bundled scenarios, and a brute-force
// visibility graph over every grid vertex on random maps.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/path.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

Eigen::Vector3d at(double x, double y) { return {x, y, 0.0}; }

double euclidean(aco::Cell a, aco::Cell b) { return std::hypot(double(a.x - b.x), double(a.y - b.y)); }

// The optimum's own promises: a valid polyline from start to goal whose length is the one reported.
void check_optimum(const aco::Map& map, const aco::AnyAnglePath& path, aco::Cell start, aco::Cell goal) {
  REQUIRE_FALSE(path.waypoints.empty());
  CHECK(path.waypoints.front() == at(start.x, start.y));
  CHECK(path.waypoints.back() == at(goal.x, goal.y));
  CHECK(aco::polyline_length(path.waypoints) == Approx(path.length).margin(1e-9));
  CHECK(aco::any_angle_path_valid(map, path.waypoints));
  CHECK(path.length >= euclidean(start, goal) - 1e-9);
}

// Every bound at once for one query on a map: any-angle <= Theta* <= A* (8-neighbourhood, no corner
// cutting), all three reachable or none.
void check_bounds(const aco::Map& map, const aco::Graph& graph, aco::AnyAngleSearch& search, aco::Cell start,
                  aco::Cell goal) {
  INFO(aco::to_string(start) << " -> " << aco::to_string(goal));
  const auto exact = search.find(start, goal);
  const auto theta = aco::theta_star(graph, graph.node(start), graph.node(goal));
  const auto octile = aco::astar(graph, graph.node(start), graph.node(goal));
  REQUIRE(exact.has_value() == octile.has_value());
  REQUIRE(theta.has_value() == octile.has_value());
  if (!octile) return;
  check_optimum(map, *exact, start, goal);
  CHECK(exact->length <= theta->length + 1e-9);
  CHECK(theta->length <= octile->length + 1e-9);
  CHECK(aco::polyline_length(theta->waypoints) == Approx(theta->length).margin(1e-9));
  CHECK(aco::any_angle_path_valid(map, theta->waypoints));
}

// The reference: Dijkstra over the visibility graph of every grid vertex (cell corners) with a free
// cell around it, plus start and goal, edges where any_angle_segment_free says so. A vertex between
// two diagonal blocked cells is no place to turn: a path through it would pass from one free cell
// into the other, and a turn that stays in one free cell is never shorter than cutting across it.
double brute_force(const aco::Map& map, aco::Cell start, aco::Cell goal) {
  std::vector<Eigen::Vector3d> points{at(start.x, start.y), at(goal.x, goal.y)};
  for (int v = 0; v <= map.height(); ++v)
    for (int u = 0; u <= map.width(); ++u) {
      const bool nw = map.passable({u - 1, v - 1}), ne = map.passable({u, v - 1});
      const bool sw = map.passable({u - 1, v}), se = map.passable({u, v});
      const bool pinch = (nw && se && !ne && !sw) || (ne && sw && !nw && !se);
      if ((nw || ne || sw || se) && !pinch) points.push_back(at(u - 0.5, v - 0.5));
    }
  const std::size_t n = points.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<char> done(n, 0);
  dist[0] = 0.0;
  for (std::size_t round = 0; round < n; ++round) {
    std::size_t best = n;
    for (std::size_t i = 0; i < n; ++i)
      if (!done[i] && (best == n || dist[i] < dist[best])) best = i;
    if (best == n || dist[best] == std::numeric_limits<double>::infinity()) break;
    if (best == 1) return dist[1];
    done[best] = 1;
    for (std::size_t i = 0; i < n; ++i) {
      if (done[i]) continue;
      const double through = dist[best] + (points[i] - points[best]).norm();
      if (through < dist[i] && aco::any_angle_segment_free(map, points[best], points[i])) dist[i] = through;
    }
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

TEST_CASE("Any-angle segment rule: grazing and edges allowed, squeezing not", "[any_angle]") {
  const auto map = test::grid({
      "......",
      ".#....",
      "..#...",
      "......",
      "...##.",
  });
  // Straight across free cells, and from a cell centre to a corner vertex.
  CHECK(aco::any_angle_segment_free(map, at(0, 0), at(5, 0)));
  CHECK(aco::any_angle_segment_free(map, at(0, 3), at(5, 3)));
  // Into a blocked cell.
  CHECK_FALSE(aco::any_angle_segment_free(map, at(0, 1), at(3, 1)));
  // Between the diagonal blocked cells (1,1) and (2,2) through their shared vertex (1.5,1.5).
  CHECK_FALSE(aco::any_angle_segment_free(map, at(2, 1), at(1, 2)));
  CHECK_FALSE(aco::any_angle_segment_free(map, at(2.5, 0.5), at(0.5, 2.5)));
  // Along the line x = 1.5 through that vertex: beside a free cell on each side, still a squeeze.
  CHECK_FALSE(aco::any_angle_segment_free(map, at(1.5, 0.5), at(1.5, 2.5)));
  // Grazing one blocked corner: through (1,1)'s corner (0.5,0.5) from (0,1) into (1,0).
  CHECK(aco::any_angle_segment_free(map, at(0, 1), at(1, 0)));
  // Through (2,2)'s corner (2.5,1.5) and on into (2,2).
  CHECK_FALSE(aco::any_angle_segment_free(map, at(3.5, 0.5), at(1.5, 2.5)));
  // Along an obstacle's edge (the top of (1,1)) and along the map's border.
  CHECK(aco::any_angle_segment_free(map, at(0.5, 0.5), at(4.5, 0.5)));
  CHECK(aco::any_angle_segment_free(map, at(-0.5, -0.5), at(5.5, -0.5)));
  CHECK(aco::any_angle_segment_free(map, at(-0.5, -0.5), at(-0.5, 4.5)));
  // Along the top edge of (3,4) and (4,4), free above; between them, nothing free beside it.
  CHECK(aco::any_angle_segment_free(map, at(2.5, 3.5), at(4.5, 3.5)));
  CHECK_FALSE(aco::any_angle_segment_free(map, at(3.5, 3.5), at(3.5, 4.5)));
  // Outside the map.
  CHECK_FALSE(aco::any_angle_segment_free(map, at(0, 0), at(-1, 0)));
  // A point off the half-cell lattice is refused.
  CHECK_THROWS_AS(aco::any_angle_segment_free(map, at(0.25, 0), at(1, 0)), aco::Error);
  // A path may not turn at the squeeze vertex from one free cell into the other either.
  const std::vector<Eigen::Vector3d> squeeze{at(2, 1), at(1.5, 1.5), at(1, 2)};
  CHECK(aco::any_angle_segment_free(map, squeeze[0], squeeze[1]));
  CHECK(aco::any_angle_segment_free(map, squeeze[1], squeeze[2]));
  CHECK_FALSE(aco::any_angle_path_valid(map, squeeze));
  // Around (1,1): up its left edge, then past its top-left corner.
  const std::vector<Eigen::Vector3d> around{at(0, 2), at(0.5, 1.5), at(0.5, 0.5), at(2, 0)};
  CHECK(aco::any_angle_path_valid(map, around));
}

TEST_CASE("Any-angle rule allows every segment line_of_sight allows", "[any_angle]") {
  // Both corner options of line_of_sight are stricter rules: the optimum bounds their paths.
  std::mt19937 rng(7);
  int free_segments = 0;
  for (int k = 0; k < 30; ++k) {
    const aco::OccupancyGrid map = test::random_grid(rng, 9, 8);
    for (int a = 0; a < 72; ++a)
      for (int b = 0; b < 72; ++b) {
        const aco::Cell ca{a % 9, a / 9}, cb{b % 9, b / 9};
        const bool exact = aco::any_angle_segment_free(map, at(ca.x, ca.y), at(cb.x, cb.y));
        INFO(aco::to_string(ca) << " -> " << aco::to_string(cb));
        if (aco::line_of_sight(map, ca, cb, true)) CHECK(exact);
        if (aco::line_of_sight(map, ca, cb, false)) CHECK(exact);
        free_segments += exact;
      }
  }
  CHECK(free_segments > 10000);
}

TEST_CASE("Any-angle optimum on open maps is the Euclidean distance", "[any_angle]") {
  const auto map = test::grid(std::vector<std::string>(7, std::string(11, '.')));
  aco::AnyAngleSearch search(map);
  for (int y0 = 0; y0 < 7; y0 += 3)
    for (int x0 = 0; x0 < 11; x0 += 2)
      for (int y1 = 0; y1 < 7; ++y1)
        for (int x1 = 0; x1 < 11; ++x1) {
          const aco::Cell a{x0, y0}, b{x1, y1};
          INFO(aco::to_string(a) << " -> " << aco::to_string(b));
          const auto path = search.find(a, b);
          REQUIRE(path);
          CHECK(path->length == Approx(euclidean(a, b)).margin(1e-12));
          CHECK(path->waypoints.size() == (a == b ? 1u : 2u));
        }
}

TEST_CASE("Any-angle search gives up when asked, and finds the same path when never asked", "[any_angle]") {
  // A maze's scenarios: searches of thousands of expansions.
  const fs::path scen = test::data_dir() / "maps/generated/maze64-2-s1.map.scen";
  const auto map = aco::load_map(aco::scenario_map_file(scen));
  aco::AnyAngleSearch search(*map);
  int long_searches = 0;
  for (const aco::Scenario& s : aco::load_scenarios(scen)) {
    const aco::Cell a = s.start, b = s.goal;
    INFO(aco::to_string(a) << " -> " << aco::to_string(b));
    const auto plain = search.find(a, b);
    const std::size_t expanded = search.expanded();
    int asked = 0;
    const auto never = search.find(a, b, [&asked] { return ++asked < 0; });
    REQUIRE(plain.has_value() == never.has_value());
    if (plain) CHECK(plain->waypoints == never->waypoints);
    CHECK(asked == static_cast<int>(expanded / 1024));  // asked every 1024 expansions
    if (expanded < 1024) continue;
    ++long_searches;
    CHECK_FALSE(search.find(a, b, [] { return true; }));  // gives up at its first question
    CHECK(search.expanded() == 1024);
  }
  CHECK(long_searches > 0);
}

TEST_CASE("Any-angle optimum on hand-made maps with known optima", "[any_angle]") {
  SECTION("a wall with a gap: around the gap's corner vertices") {
    const auto map = test::grid({
        ".......",
        ".......",
        "###.###",
        ".......",
        ".......",
    });
    const auto path = aco::any_angle_optimum(map, {0, 0}, {0, 4});
    REQUIRE(path);
    CHECK(path->length == Approx(2 * std::sqrt(2.5 * 2.5 + 1.5 * 1.5) + 1.0).margin(1e-12));
    CHECK(path->waypoints == aco::Waypoints{at(0, 0), at(2.5, 1.5), at(2.5, 2.5), at(0, 4)});
    // Straight through the gap needs no turn.
    const auto straight = aco::any_angle_optimum(map, {3, 0}, {3, 4});
    REQUIRE(straight);
    CHECK(straight->length == Approx(4.0).margin(1e-12));
  }
  SECTION("two diagonal blocked cells: no squeezing between them") {
    const auto map = test::grid({
        "....",
        ".#..",
        "..#.",
        "....",
    });
    const auto path = aco::any_angle_optimum(map, {2, 1}, {1, 2});
    REQUIRE(path);
    CHECK(path->length == Approx(2.0 + std::sqrt(2.0)).margin(1e-12));
    CHECK(path->waypoints.size() == 5);
    CHECK(aco::any_angle_path_valid(map, path->waypoints));
  }
  SECTION("around a single blocked cell's corners") {
    const auto map = test::grid({
        "...",
        ".#.",
        "...",
    });
    const auto path = aco::any_angle_optimum(map, {0, 0}, {2, 1});
    REQUIRE(path);
    // The straight line to (2,1) would enter (1,1): the path turns at its corner (1.5,0.5).
    CHECK(path->length == Approx(std::hypot(1.5, 0.5) + std::hypot(0.5, 0.5)).margin(1e-12));
    CHECK(aco::any_angle_optimum(map, {0, 0}, {2, 2})->length == Approx(2 * std::hypot(1.5, 0.5)).margin(1e-12));
  }
  SECTION("unreachable, blocked ends, start == goal") {
    const auto map = test::grid({
        "..#..",
        ".#...",
        "#....",
    });
    CHECK_FALSE(aco::any_angle_optimum(map, {0, 0}, {4, 2}));  // only a squeeze joins them
    CHECK_FALSE(aco::any_angle_optimum(map, {0, 0}, {2, 0}));
    CHECK_FALSE(aco::any_angle_optimum(map, {2, 0}, {0, 0}));
    const auto same = aco::any_angle_optimum(map, {3, 1}, {3, 1});
    REQUIRE(same);
    CHECK(same->length == 0.0);
    CHECK(same->waypoints == aco::Waypoints{at(3, 1)});
  }
}

TEST_CASE("Any-angle bounds on the classic 20x20 maps", "[any_angle]") {
  std::mt19937 rng(2024);
  for (int n = 1; n <= 3; ++n) {
    const fs::path scen = test::data_dir() / "maps/classic20" / ("map" + std::to_string(n) + ".txt.scen");
    INFO(scen.string());
    const auto map = aco::load_map(aco::scenario_map_file(scen));
    const aco::Graph graph = aco::build_graph(*map, {aco::Neighbourhood::eight, false});
    aco::AnyAngleSearch search(*map);
    for (const aco::Scenario& s : aco::load_scenarios(scen)) {
      check_bounds(*map, graph, search, s.start, s.goal);
      const auto octile = aco::astar(graph, graph.node(s.start), graph.node(s.goal));
      CHECK(octile->length == Approx(s.optimal_length).epsilon(1e-6));
    }
    // And 150 random pairs of free cells per map.
    std::uniform_int_distribution<int> coordinate(0, 19);
    for (int k = 0; k < 150;) {
      const aco::Cell a{coordinate(rng), coordinate(rng)}, b{coordinate(rng), coordinate(rng)};
      if (!map->passable(a) || !map->passable(b)) continue;
      check_bounds(*map, graph, search, a, b);
      ++k;
    }
  }
}

TEST_CASE("Any-angle bounds on small bundled scenarios", "[any_angle]") {
  const char* files[] = {"movingai/arena.map.scen",           "generated/random32-25-s1.map.scen",
                         "generated/random32-25-s2.map.scen", "generated/maze32-1-s1.map.scen",
                         "generated/room32-8-s1.map.scen",    "generated/random64-25-s1.map.scen",
                         "generated/maze64-2-s1.map.scen"};
  for (const char* name : files) {
    const fs::path scen = test::data_dir() / "maps" / name;
    INFO(scen.string());
    const auto map = aco::load_map(aco::scenario_map_file(scen));
    const aco::Graph graph = aco::build_graph(*map, {aco::Neighbourhood::eight, false});
    aco::AnyAngleSearch search(*map);
    const auto scenarios = aco::load_scenarios(scen);
    const std::size_t step = std::max<std::size_t>(1, scenarios.size() / 40);
    for (std::size_t i = 0; i < scenarios.size(); i += step) {
      INFO("scenario " << i);
      const aco::Scenario& s = scenarios[i];
      check_bounds(*map, graph, search, s.start, s.goal);
      // The octile optimum of check_bounds is the file's (stored with 4 to 8 digits).
      const auto octile = aco::astar(graph, graph.node(s.start), graph.node(s.goal));
      REQUIRE(octile);
      CHECK(octile->length == Approx(s.optimal_length).epsilon(1e-3));
    }
  }
}

TEST_CASE("Any-angle optimum equals a brute-force visibility graph on random maps", "[any_angle]") {
  std::mt19937 rng(39);  // mt19937 output is fully specified: the maps are the same everywhere
  int compared = 0, unreachable = 0;
  for (int seed = 0; seed < 200; ++seed) {
    const aco::OccupancyGrid map = test::random_grid(rng, 12, 12);
    std::uniform_int_distribution<int> coordinate(0, 11);
    aco::Cell a{coordinate(rng), coordinate(rng)}, b{coordinate(rng), coordinate(rng)};
    aco::OccupancyGrid open = map;
    open.set_blocked(a, false);
    open.set_blocked(b, false);
    INFO("map " << seed << ": " << aco::to_string(a) << " -> " << aco::to_string(b));
    const double reference = brute_force(open, a, b);
    const auto exact = aco::any_angle_optimum(open, a, b);
    if (reference == std::numeric_limits<double>::infinity()) {
      CHECK_FALSE(exact);
      ++unreachable;
      continue;
    }
    REQUIRE(exact);
    CHECK(exact->length == Approx(reference).margin(1e-9));
    check_optimum(open, *exact, a, b);
    ++compared;
  }
  CHECK(compared >= 150);
  CHECK(unreachable >= 1);
}
