// The exact reference planner: published optimal lengths (classic20, Moving AI) and path shape.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <queue>
#include <random>
#include <string>
#include <vector>

#include "aco/astar.hpp"
#include "aco/best_first.hpp"
#include "aco/graph.hpp"
#include "aco/engine/map_io.hpp"
#include "support.hpp"

namespace fs = std::filesystem;

namespace {

// Checks that a path is a valid walk from start to goal whose length is the reported one.
void check_path(const aco::Graph& g, const aco::ShortestPath& path, aco::NodeId start, aco::NodeId goal) {
  REQUIRE_FALSE(path.nodes.empty());
  CHECK(path.nodes.front() == start);
  CHECK(path.nodes.back() == goal);
  for (std::size_t i = 1; i < path.nodes.size(); ++i) {
    INFO("step " << i << ": " << aco::to_string(g.cell(path.nodes[i - 1])) << " -> "
                 << aco::to_string(g.cell(path.nodes[i])));
    CHECK(g.find_edge(path.nodes[i - 1], path.nodes[i]) >= 0);
  }
  CHECK(aco::path_length(g, path.nodes) == Approx(path.length).epsilon(1e-12));
}

// Plain Dijkstra over the same graph, as an independent reference.
double dijkstra(const aco::Graph& g, aco::NodeId start, aco::NodeId goal) {
  std::vector<double> dist(g.num_nodes(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, aco::NodeId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  dist[start] = 0;
  open.push({0.0, start});
  while (!open.empty()) {
    const auto [d, n] = open.top();
    open.pop();
    if (d > dist[n]) continue;
    if (n == goal) return d;
    for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) {
      const double nd = d + g.cost(e);
      if (nd < dist[g.targets[e]]) {
        dist[g.targets[e]] = nd;
        open.push({nd, g.targets[e]});
      }
    }
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

TEST_CASE("A* matches the classic20 table of optimal lengths", "[astar]") {
  struct Row {
    const char* file;
    double cutting, no_cutting, four;
  };
  // data/maps/classic20/README.md
  const Row table[] = {
      {"map1.txt", 34.3848, 37.8995, 42.0}, {"map2.txt", 28.6274, 29.7990, 38.0}, {"map3.txt", 30.9706, 33.3137, 38.0}};
  for (const Row& row : table) {
    INFO(row.file);
    const auto map = aco::load_map(test::data_dir() / "maps/classic20" / row.file);
    REQUIRE(map->width() == 20);
    REQUIRE(map->height() == 20);
    struct Case {
      aco::Neighbourhood n;
      bool cc;
      double expected;
    };
    for (const Case& c :
         {Case{aco::Neighbourhood::eight, true, row.cutting}, Case{aco::Neighbourhood::eight, false, row.no_cutting},
          Case{aco::Neighbourhood::four, false, row.four}}) {
      const aco::Graph g = aco::build_graph(*map, {c.n, c.cc});
      INFO(aco::describe(g.options));
      const aco::NodeId start = g.node({0, 0}), goal = g.node({19, 19});
      const auto path = aco::astar(g, start, goal);
      REQUIRE(path.has_value());
      CHECK(path->length == Approx(c.expected).margin(1e-4).epsilon(0));
      check_path(g, *path, start, goal);
    }
  }
}

TEST_CASE("A* matches Moving AI optimal lengths (8-neighbourhood, no corner cutting)", "[astar][slow]") {
  const fs::path root = test::data_dir() / "maps/movingai";
  const char* files[] = {"arena.map.scen",
                         "dao/arena2.map.scen",
                         "dao/lak304d.map.scen",
                         "room/64room_000.map.scen",
                         "room/8room_000.map.scen",
                         "maze/maze512-1-0.map.scen",
                         "random/random512-10-0.map.scen",
                         "street/Berlin_0_512.map.scen"};
  for (const char* name : files) {
    const fs::path scen = root / name;
    INFO(scen.string());
    const auto scenarios = aco::load_scenarios(scen);
    REQUIRE(scenarios.size() > 1);
    const auto map = aco::load_map(aco::scenario_map_file(scen));
    const aco::Graph g = aco::build_graph(*map, {aco::Neighbourhood::eight, false});
    // About 40 scenarios per file, evenly spread (buckets grow in length), always the last one.
    const std::size_t n = scenarios.size();
    const std::size_t k = std::max<std::size_t>(1, (n + 39) / 40);
    std::vector<std::size_t> sample;
    for (std::size_t i = 0; i < n; i += k) sample.push_back(i);
    if (sample.back() != n - 1) sample.push_back(n - 1);
    CHECK(sample.size() >= 40);
    CHECK(sample.size() <= 41);
    for (std::size_t i : sample) {
      const aco::Scenario& s = scenarios[i];
      INFO("scenario " << i << ": " << aco::to_string(s.start) << " -> " << aco::to_string(s.goal) << ", optimal "
                       << s.optimal_length);
      REQUIRE(s.width == map->width());
      REQUIRE(s.height == map->height());
      REQUIRE(map->passable(s.start));
      REQUIRE(map->passable(s.goal));
      const auto path = aco::astar(g, g.node(s.start), g.node(s.goal));
      REQUIRE(path.has_value());
      CHECK(path->length == Approx(s.optimal_length).epsilon(1e-3));
      if (i == sample.back()) check_path(g, *path, g.node(s.start), g.node(s.goal));
    }
  }
}

TEST_CASE("A* returns nothing for an unreachable goal", "[astar]") {
  const auto map = test::grid({"..#..", "..#..", ".#..."});
  const auto strict = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  CHECK_FALSE(aco::astar(strict, strict.node({0, 0}), strict.node({4, 2})).has_value());
  CHECK_FALSE(aco::astar(aco::build_graph(map, {aco::Neighbourhood::four, false}), 0, 14).has_value());
  CHECK_FALSE(aco::astar(aco::build_graph(map, {aco::Neighbourhood::sixteen, false}), 0, 14).has_value());
  // The diagonal gap at (1,1)-(2,2) opens with corner cutting.
  const auto cutting = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  const auto path = aco::astar(cutting, 0, 14);
  REQUIRE(path.has_value());
  CHECK(path->length == Approx(2 * std::sqrt(2.0) + 2.0));
  check_path(cutting, *path, 0, 14);
  // A blocked goal is unreachable too.
  const auto walled = test::grid({"...", "...", "..#"});
  const auto g = aco::build_graph(walled, {aco::Neighbourhood::eight, false});
  CHECK_FALSE(aco::astar(g, 0, g.node({2, 2})).has_value());
}

TEST_CASE("A* path shape on small maps", "[astar]") {
  SECTION("start equals goal") {
    const auto map = test::grid({"...", "..."});
    const auto g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
    const auto path = aco::astar(g, 4, 4);
    REQUIRE(path.has_value());
    CHECK(path->nodes == std::vector<aco::NodeId>{4});
    CHECK(path->length == 0.0);
  }
  SECTION("open grid: octile, Manhattan and knight lengths") {
    const auto map = test::grid(std::vector<std::string>(6, std::string(8, '.')));
    const aco::Cell a{0, 0}, b{7, 3};
    const auto g8 = aco::build_graph(map, {aco::Neighbourhood::eight, false});
    const auto p8 = aco::astar(g8, g8.node(a), g8.node(b));
    REQUIRE(p8);
    CHECK(p8->length == Approx(3 * std::sqrt(2.0) + 4.0));
    check_path(g8, *p8, g8.node(a), g8.node(b));
    const auto g4 = aco::build_graph(map, {aco::Neighbourhood::four, false});
    const auto p4 = aco::astar(g4, g4.node(a), g4.node(b));
    REQUIRE(p4);
    CHECK(p4->length == Approx(10.0));
    CHECK(p4->nodes.size() == 11);
    check_path(g4, *p4, g4.node(a), g4.node(b));
    const auto g16 = aco::build_graph(map, {aco::Neighbourhood::sixteen, false});
    const auto p16 = aco::astar(g16, g16.node({0, 0}), g16.node({6, 3}));
    REQUIRE(p16);
    CHECK(p16->length == Approx(3 * std::sqrt(5.0)));
    CHECK(p16->nodes.size() == 4);
    check_path(g16, *p16, g16.node({0, 0}), g16.node({6, 3}));
  }
  SECTION("detour around a wall") {
    const auto map = test::grid({
        ".....",
        ".###.",
        "..#..",
        "..#..",
    });
    const auto g = aco::build_graph(map, {aco::Neighbourhood::four, false});
    const auto path = aco::astar(g, g.node({1, 3}), g.node({3, 3}));
    REQUIRE(path);
    CHECK(path->length == Approx(12.0));  // to (0,1), across row 0, down column 4
    check_path(g, *path, g.node({1, 3}), g.node({3, 3}));
    for (aco::NodeId n : path->nodes) CHECK(map.passable(g.cell(n)));
  }
}

TEST_CASE("A* agrees with Dijkstra on random maps", "[astar]") {
  std::mt19937 rng(12345);  // mt19937 output is fully specified: the maps are the same everywhere
  int compared = 0, unreachable = 0;
  for (int trial = 0; trial < 12; ++trial) {
    std::vector<std::string> rows(24, std::string(30, '.'));
    for (auto& row : rows)
      for (auto& c : row) c = rng() % 100 < 28 ? '#' : '.';
    rows[0][0] = '.';
    rows[23][29] = '.';
    const auto map = test::grid(rows);
    for (auto n : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
      for (bool cc : {false, true}) {
        const auto g = aco::build_graph(map, {n, cc});
        for (int q = 0; q < 5; ++q) {
          const aco::NodeId start = q == 0 ? 0 : static_cast<aco::NodeId>(rng() % g.num_nodes());
          const aco::NodeId goal = q == 0 ? g.num_nodes() - 1 : static_cast<aco::NodeId>(rng() % g.num_nodes());
          if (!g.passable(start) || !g.passable(goal)) continue;
          INFO("trial " << trial << ", " << aco::describe(g.options) << ", " << aco::to_string(g.cell(start)) << " -> "
                        << aco::to_string(g.cell(goal)));
          const double reference = dijkstra(g, start, goal);
          const auto path = aco::astar(g, start, goal);
          CHECK(path.has_value() == std::isfinite(reference));
          CHECK(path.has_value() == aco::reachable(g, start, goal));
          if (path) {
            CHECK(path->length == Approx(reference).epsilon(1e-12));
            check_path(g, *path, start, goal);
            ++compared;
          } else {
            ++unreachable;
          }
        }
      }
    }
  }
  CHECK(compared > 100);
  CHECK(unreachable > 0);
}

TEST_CASE("Best-first search takes equal keys smaller node first, each node once", "[astar]") {
  // The order every exact search's result hangs on (aco/best_first.hpp).
  aco::BestFirstSearch search(8, [](aco::NodeId n) { return n == 6 ? 1.0 : 0.0; });
  for (const aco::NodeId n : {5, 3, 7, 4}) search.relax(n, 2.0, -1);
  search.relax(6, 1.0, -1);  // key 2 too: heuristic 1
  search.relax(5, 1.5, 3);  // improved: opened again at 1.5, its old entry skipped
  std::vector<aco::NodeId> expanded;
  search.run(7, [&](aco::NodeId n) { expanded.push_back(n); });
  CHECK(expanded == std::vector<aco::NodeId>{5, 3, 4, 6});
  CHECK(search.closed(7));
  CHECK(search.path_to(5) == std::vector<aco::NodeId>{3, 5});
  CHECK(search.cost(0) == search.unreached);
}
