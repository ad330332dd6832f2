// Which corridor a path runs through (aco/corridor.hpp): hand-made obstacles passed on either
// side, obstacles that cannot be gone around, and A* paths against the any-angle optimum.
#include <catch2/catch.hpp>

#include <array>
#include <random>

#include "aco/any_angle.hpp"
#include "aco/astar.hpp"
#include "aco/corridor.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "support.hpp"

namespace {

aco::Waypoints polyline(std::initializer_list<std::pair<double, double>> points) {
  aco::Waypoints w;
  for (const auto& [x, y] : points) w.emplace_back(x, y, 0.0);
  return w;
}

// A block in the way of (0,4) -> (9,5), the goal nearer its lower side.
aco::OccupancyGrid block_in_the_way() {
  return test::grid({
      "..........",
      "..........",
      "....##....",
      "....##....",
      "....##....",
      "..........",
  });
}

}  // namespace

TEST_CASE("Corridors: an obstacle passed on either side", "[corridor]") {
  const auto map = test::grid({
      ".........",
      ".........",
      "...###...",
      "...###...",
      ".........",
      ".........",
  });
  const aco::CorridorTest test(map);
  CHECK(test.obstacles() == 1);
  const auto above = polyline({{0, 2}, {2, 0}, {6, 0}, {8, 2}});
  const auto above_too = polyline({{0, 2}, {1, 1}, {2.5, 1.5}, {5.5, 1.5}, {8, 2}});
  const auto below = polyline({{0, 2}, {2, 5}, {6, 5}, {8, 2}});
  CHECK(test.same(above, above_too));
  CHECK(test.same(above, above));
  CHECK_FALSE(test.same(above, below));
  CHECK_FALSE(test.same(below, above_too));
  // A path circling the obstacle once before going on is another class too.
  const auto circling = polyline({{0, 2}, {2, 0}, {7, 0}, {7, 5}, {2, 5}, {2, 0}, {6, 0}, {8, 2}});
  CHECK_FALSE(test.same(above, circling));
  // The same answers from the corridors' keys.
  const aco::CorridorKeys keys(map);
  CHECK(keys.obstacles() == 1);
  CHECK(keys.key(above) == keys.key(above_too));
  CHECK(keys.key(above) != keys.key(below));
  CHECK(keys.key(above) != keys.key(circling));
  CHECK(keys.key(below) != keys.key(circling));
}

TEST_CASE("Corridors: obstacles at the map's edge and diagonal cells", "[corridor]") {
  SECTION("a wall from the edge is no obstacle to go round") {
    const auto map = test::grid({
        "...#...",
        "...#...",
        ".......",
    });
    CHECK(aco::CorridorTest(map).obstacles() == 0);
  }
  SECTION("cells touching at a corner are one obstacle: no path passes between them") {
    const auto map = test::grid({
        "......",
        ".#....",
        "..#...",
        "...#..",
        "......",
    });
    CHECK(aco::CorridorTest(map).obstacles() == 1);
  }
  SECTION("two obstacles: between them is a third corridor") {
    const auto map = test::grid({
        ".......",
        "..#.#..",
        ".......",
    });
    const aco::CorridorTest test(map);
    CHECK(test.obstacles() == 2);
    const auto between = polyline({{3, 0}, {3, 2}});
    const auto left = polyline({{3, 0}, {1, 1}, {3, 2}});
    const auto right = polyline({{3, 0}, {5, 1}, {3, 2}});
    CHECK_FALSE(test.same(between, left));
    CHECK_FALSE(test.same(between, right));
    CHECK_FALSE(test.same(left, right));
  }
}

TEST_CASE("Corridors: optimal grid paths lie in the any-angle optimum's corridor", "[corridor]") {
  SECTION("a block in the way, the goal nearer its lower side") {
    const auto map = block_in_the_way();
    const aco::Graph graph = aco::build_graph(map, {});
    const aco::Cell start{0, 4}, goal{9, 5};
    const aco::OptimalCorridor corridor(map, start, goal);
    REQUIRE(corridor.optimum());
    const auto astar = aco::astar(graph, graph.node(start), graph.node(goal));
    REQUIRE(astar);
    CHECK(corridor.contains(aco::to_waypoints(graph, astar->nodes)) == true);
    CHECK(corridor.contains(polyline({{0, 4}, {3, 1}, {6, 1}, {9, 5}})) == false);
  }
  SECTION("random maps: symmetric and transitive over A*, Theta* and the optimum") {
    std::mt19937 rng(7);
    int compared = 0;
    for (int i = 0; i < 40; ++i) {
      const aco::OccupancyGrid map = test::random_grid(rng, 14, 12);
      const aco::Graph graph = aco::build_graph(map, {});
      const aco::Cell start{0, 0}, goal{13, 11};
      if (!map.passable(start) || !map.passable(goal)) continue;
      const aco::OptimalCorridor corridor(map, start, goal);
      const auto astar = aco::astar(graph, graph.node(start), graph.node(goal));
      REQUIRE(bool(corridor.optimum()) == bool(astar));
      if (!astar) continue;
      // The optimum is in its own corridor; the test is symmetric and transitive over A*,
      // Theta* and the optimum.
      CHECK(corridor.contains(corridor.optimum()->waypoints) == true);
      const aco::CorridorTest test(map);
      const aco::Waypoints grid_path = aco::to_waypoints(graph, astar->nodes);
      const auto theta = aco::theta_star(graph, graph.node(start), graph.node(goal));
      REQUIRE(theta);
      const auto& best = corridor.optimum()->waypoints;
      CHECK(test.same(grid_path, best) == test.same(best, grid_path));
      CHECK(test.same(grid_path, theta->waypoints) == test.same(theta->waypoints, grid_path));
      if (test.same(grid_path, theta->waypoints) && test.same(theta->waypoints, best))
        CHECK(test.same(grid_path, best));
      ++compared;
    }
    CHECK(compared > 5);
  }
  SECTION("no optimum: nothing known") {
    const auto map = test::grid({
        "..#..",
        "..#..",
        "..#..",
    });
    const aco::OptimalCorridor corridor(map, {0, 0}, {4, 0});
    CHECK_FALSE(corridor.optimum());
    CHECK_FALSE(corridor.contains(polyline({{0, 0}, {4, 0}})));
  }
}

TEST_CASE("Corridor keys: equal exactly when the paths go round every obstacle alike", "[corridor]") {
  SECTION("random maps and neighbourhoods: a walk's key is its cells' polyline's, and agrees with CorridorTest") {
    std::mt19937 rng(11);
    int pairs = 0, same = 0;
    for (int i = 0; i < 60; ++i) {
      const aco::OccupancyGrid map = test::random_grid(rng, 16, 13);
      const aco::Neighbourhood neighbourhood =
          std::array{aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}[i % 3];
      aco::GraphOptions options;
      options.neighbourhood = neighbourhood;
      options.corner_cutting = i % 2 == 0;
      const aco::Graph graph = aco::build_graph(map, options);
      const aco::Cell start{0, 0}, goal{15, 12};
      if (!map.passable(start) || !map.passable(goal) || !aco::astar(graph, graph.node(start), graph.node(goal)))
        continue;
      const aco::CorridorTest test(map);
      const aco::CorridorKeys keys(map);
      REQUIRE(keys.obstacles() == test.obstacles());
      // Paths through a random free cell: A* there and on to the goal (loops allowed).
      std::vector<aco::Waypoints> paths;
      std::uniform_int_distribution<int> x(0, 15), y(0, 12);
      for (int k = 0; k < 12 && paths.size() < 6; ++k) {
        const aco::Cell via{x(rng), y(rng)};
        if (!map.passable(via)) continue;
        const auto first = aco::astar(graph, graph.node(start), graph.node(via));
        const auto second = aco::astar(graph, graph.node(via), graph.node(goal));
        if (!first || !second) continue;
        std::vector<aco::NodeId> walk = first->nodes;
        walk.insert(walk.end(), second->nodes.begin() + 1, second->nodes.end());
        const aco::Waypoints cells = aco::to_waypoints(graph, walk);
        CHECK(keys.key(graph, walk) == keys.key(cells));
        paths.push_back(cells);
      }
      if (const auto optimum = aco::any_angle_optimum(map, start, goal)) paths.push_back(optimum->waypoints);
      for (std::size_t a = 0; a < paths.size(); ++a)
        for (std::size_t b = a + 1; b < paths.size(); ++b) {
          const bool alike = test.same(paths[a], paths[b]);
          CHECK((keys.key(paths[a]) == keys.key(paths[b])) == alike);
          ++pairs;
          same += alike;
        }
    }
    CHECK(pairs > 200);  // both answers are tested many times
    CHECK(same > 20);
    CHECK(pairs - same > 20);
  }
}

TEST_CASE("Corridors walked: the optimum's corridor among a search's keys", "[corridor]") {
  const auto map = block_in_the_way();
  const aco::Cell start{0, 4}, goal{9, 5};
  const aco::OptimalCorridor corridor(map, start, goal);
  const aco::CorridorKeys keys(map);
  const auto below = keys.key(polyline({{0, 4}, {4, 5}, {9, 5}}));
  const auto above = keys.key(polyline({{0, 4}, {3, 1}, {6, 1}, {9, 5}}));
  const std::vector<std::uint64_t> both{std::min(above, below), std::max(above, below)};
  CHECK(corridor.among(both) == true);
  CHECK(corridor.among(std::vector<std::uint64_t>{below}) == true);
  CHECK(corridor.among(std::vector<std::uint64_t>{above}) == false);
  CHECK(corridor.among(std::vector<std::uint64_t>{}) == false);
  const auto walled = test::grid({"..#..", "..#..", "..#.."});
  CHECK_FALSE(aco::OptimalCorridor(walled, {0, 0}, {4, 0}).among(both));
}
