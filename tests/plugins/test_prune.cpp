// smoother/prune: greedy line-of-sight shortcutting of the grid path (paper 003, section 2.4).
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "aco/astar.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/robot.hpp"
#include "support.hpp"

namespace {

std::vector<aco::NodeId> nodes(const aco::Graph& g, const std::vector<aco::Cell>& cells) {
  std::vector<aco::NodeId> v;
  for (const auto& c : cells) v.push_back(g.node(c));
  return v;
}

aco::Waypoints points(const std::vector<aco::Cell>& cells) {
  aco::Waypoints w;
  for (const auto& c : cells) w.emplace_back(c.x, c.y, 0.0);
  return w;
}

aco::Waypoints prune(const aco::Graph& g, const std::vector<aco::NodeId>& path,
                     const std::map<std::string, std::string>& params = {}) {
  const auto smoother = test::make<aco::Smoother>("smoother", "prune", params);
  return smoother->smooth(test::context(g, g.cell(path.front()), g.cell(path.back())), path);
}

// Checks everything a pruned path must satisfy, independently of the plugin's own code:
// - it starts at the start and ends at the goal, and is never longer than the grid path;
// - its waypoints are path nodes in path order;
// - every segment that skips path nodes is free by the reference segment rule; a segment
//   between consecutive path nodes is a graph edge (checked by path_length) and kept as is;
// - greedy and farthest: from each waypoint no later path node beyond the chosen one (within
//   the lookahead) is in line of sight, and a kept grid step means none was.
// Returns the number of segments that shortcut at least one node.
int check_pruned(const aco::Graph& g, const std::vector<aco::NodeId>& path, const aco::Waypoints& pruned,
                 std::size_t lookahead = 0) {
  REQUIRE(!path.empty());
  REQUIRE(!pruned.empty());
  CHECK(pruned.front() == g.position(path.front()));
  CHECK(pruned.back() == g.position(path.back()));
  const double grid = aco::path_length(g, path);
  CHECK(aco::polyline_length(pruned) <= grid + 1e-9);
  // Waypoint k sits at path index index[k].
  std::vector<std::size_t> index;
  std::size_t from = 0;
  for (const auto& p : pruned) {
    while (from < path.size() && g.position(path[from]) != p) ++from;
    REQUIRE(from < path.size());
    index.push_back(from++);
  }
  REQUIRE(index.front() == 0);
  REQUIRE(index.back() == path.size() - 1);
  const std::size_t last = path.size() - 1;
  int shortcuts = 0;
  bool all_ok = true;
  for (std::size_t k = 0; k + 1 < index.size(); ++k) {
    const std::size_t i = index[k], j = index[k + 1];
    const aco::Cell a = g.cell(path[i]);
    if (j > i + 1) {
      ++shortcuts;
      all_ok &= test::reference_segment_clear(*g.map, a, g.cell(path[j]), g.options.corner_cutting);
    }
    const std::size_t farthest = lookahead == 0 ? last : std::min(last, i + lookahead);
    for (std::size_t m = std::max(j + 1, i + 2); m <= farthest; ++m)
      all_ok &= !test::reference_segment_clear(*g.map, a, g.cell(path[m]), g.options.corner_cutting);
  }
  CHECK(all_ok);
  return shortcuts;
}

// A random walk of up to `steps` moves from `start`, with its loops erased (when the walk comes
// back to a node, everything since that node's earlier visit is dropped): a valid loop-free path.
std::vector<aco::NodeId> loop_free_walk(const aco::Graph& g, aco::NodeId start, int steps, std::mt19937& rng) {
  std::vector<aco::NodeId> walk{start};
  std::vector<int> position(g.num_nodes(), -1);
  position[start] = 0;
  for (int s = 0; s < steps; ++s) {
    const aco::NodeId n = walk.back();
    if (g.degree(n) == 0) break;
    const aco::NodeId next = g.targets[g.edges_begin(n) + std::uniform_int_distribution<int>(0, g.degree(n) - 1)(rng)];
    if (position[next] >= 0) {
      while (walk.back() != next) {
        position[walk.back()] = -1;
        walk.pop_back();
      }
    } else {
      position[next] = static_cast<int>(walk.size());
      walk.push_back(next);
    }
  }
  return walk;
}

}  // namespace

TEST_CASE("prune: declared parameters and trivial paths", "[plugin][prune]") {
  const auto& descriptor = test::plugins().load("smoother", "prune");
  REQUIRE(descriptor.parameters().size() == 2);
  CHECK(std::string(descriptor.parameters()[0].name) == "max_lookahead");
  CHECK(std::string(descriptor.parameters()[0].default_value) == "0");
  CHECK(std::string(descriptor.parameters()[1].name) == "clearance");
  CHECK(std::string(descriptor.parameters()[1].default_value) == "0");

  const auto map = test::grid({"...", "..."});
  const auto g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  CHECK(prune(g, nodes(g, {{1, 1}})) == points({{1, 1}}));
  CHECK(prune(g, nodes(g, {{0, 0}, {1, 1}})) == points({{0, 0}, {1, 1}}));
  CHECK(prune(g, nodes(g, {{0, 0}, {1, 0}, {2, 0}})) == points({{0, 0}, {2, 0}}));
  const auto smoother = test::make<aco::Smoother>("smoother", "prune");
  CHECK(smoother->smooth(test::context(g, {0, 0}, {0, 0}), std::vector<aco::NodeId>{}).empty());
}

TEST_CASE("prune: an open map turns a staircase into one segment", "[plugin][prune]") {
  const auto map = test::grid(std::vector<std::string>(6, std::string(8, '.')));
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    const auto g4 = aco::build_graph(map, {aco::Neighbourhood::four, cc});
    const auto stairs = nodes(
        g4, {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {3, 2}, {4, 2}, {4, 3}, {5, 3}, {6, 3}, {6, 4}, {7, 4}, {7, 5}});
    const auto r4 = prune(g4, stairs);
    CHECK(r4 == points({{0, 0}, {7, 5}}));
    CHECK(aco::polyline_length(r4) == Approx(std::hypot(7.0, 5.0)));
    CHECK(aco::path_length(g4, stairs) == 12.0);
    check_pruned(g4, stairs, r4);

    const auto g8 = aco::build_graph(map, {aco::Neighbourhood::eight, cc});
    const auto diag = nodes(g8, {{0, 5}, {1, 4}, {2, 3}, {3, 3}, {4, 2}, {5, 1}, {6, 1}, {7, 0}});
    CHECK(prune(g8, diag) == points({{0, 5}, {7, 0}}));

    const auto g16 = aco::build_graph(map, {aco::Neighbourhood::sixteen, cc});
    const auto knight = nodes(g16, {{7, 5}, {5, 4}, {4, 4}, {2, 3}, {1, 1}, {0, 0}});
    CHECK(prune(g16, knight) == points({{7, 5}, {0, 0}}));
    // An A* path on the open map, too.
    const auto best = aco::astar(g8, g8.node({0, 0}), g8.node({7, 3}));
    REQUIRE(best);
    CHECK(prune(g8, best->nodes) == points({{0, 0}, {7, 3}}));
  }
}

TEST_CASE("prune: an L-shaped corridor keeps its corner", "[plugin][prune]") {
  SECTION("one cell wide: the bend stays, the straight runs collapse") {
    const auto map = test::grid({
        ".....",
        "####.",
        "####.",
        "####.",
    });
    for (auto n : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
      for (bool cc : {false, true}) {
        INFO("neighbourhood " << static_cast<int>(n) << ", corner cutting " << cc);
        const auto g = aco::build_graph(map, {n, cc});
        const auto path = nodes(g, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {4, 2}, {4, 3}});
        const auto r = prune(g, path);
        CHECK(r == points({{0, 0}, {4, 0}, {4, 3}}));
        CHECK(r.size() < path.size());
        CHECK(aco::polyline_length(r) == Approx(aco::path_length(g, path)));
        CHECK(aco::count_turns(r) == 1);
        check_pruned(g, path, r);
      }
    }
  }
  SECTION("two cells wide: the corner is cut, strictly shorter") {
    const auto map = test::grid({
        "......",
        "......",
        "####..",
        "####..",
        "####..",
    });
    for (bool cc : {false, true}) {
      INFO("corner cutting " << cc);
      const auto g = aco::build_graph(map, {aco::Neighbourhood::four, cc});
      const auto path = nodes(g, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {5, 1}, {5, 2}, {5, 3}, {5, 4}});
      const auto r = prune(g, path);
      CHECK(r.size() < path.size());
      CHECK(aco::polyline_length(r) < aco::path_length(g, path) - 0.5);
      CHECK(check_pruned(g, path, r) >= 1);
      // The segment from the start must not clip the wall's corner cell (3,2).
      CHECK(r.size() == 3);
    }
  }
}

TEST_CASE("prune: an obstacle blocks the direct shortcut", "[plugin][prune]") {
  const auto map = test::grid({
      ".......",
      "...#...",
      ".......",
  });
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    const auto g = aco::build_graph(map, {aco::Neighbourhood::eight, cc});
    const auto path = nodes(g, {{0, 1}, {1, 1}, {2, 0}, {3, 0}, {4, 0}, {5, 1}, {6, 1}});
    const auto r = prune(g, path);
    // (0,1) -> (6,1) and (0,1) -> (5,1) run through (3,1); (0,1) -> (4,0) passes above it.
    CHECK(r == points({{0, 1}, {4, 0}, {6, 1}}));
    CHECK(aco::polyline_length(r) == Approx(std::sqrt(17.0) + std::sqrt(5.0)));
    CHECK(aco::polyline_length(r) < aco::path_length(g, path));
    check_pruned(g, path, r);
  }
}

TEST_CASE("prune: the corner rule decides a shortcut that grazes a blocked corner", "[plugin][prune]") {
  // (0,0) -> (3,1) passes exactly through the vertex (1.5, 0.5), the corner of blocked (1,1).
  const auto map = test::grid({
      "....",
      ".#..",
  });
  const auto strict = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  const auto path = nodes(strict, {{0, 0}, {1, 0}, {2, 0}, {3, 1}});
  CHECK(prune(strict, path) == points({{0, 0}, {2, 0}, {3, 1}}));
  check_pruned(strict, path, prune(strict, path));
  const auto cutting = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  CHECK(prune(cutting, path) == points({{0, 0}, {3, 1}}));
  check_pruned(cutting, path, prune(cutting, path));

  {  // A corner-cutting grid step between two blocked cells is kept as it is.
    const auto squeeze = test::grid({
        "..#",
        ".#.",
        "...",
    });
    const auto g = aco::build_graph(squeeze, {aco::Neighbourhood::eight, true});
    // (1,0) -> (2,1) squeezes between (2,0) and (1,1): an edge of this graph, but no line of sight.
    const auto p = nodes(g, {{0, 0}, {1, 0}, {2, 1}, {2, 2}});
    const auto r = prune(g, p);
    CHECK(r == points({{0, 0}, {1, 0}, {2, 1}, {2, 2}}));
    check_pruned(g, p, r);
  }
}

TEST_CASE("prune: max_lookahead bounds how far a shortcut reaches", "[plugin][prune]") {
  const auto map = test::grid({"........."});
  const auto g = aco::build_graph(map, {aco::Neighbourhood::four, false});
  const auto path = nodes(g, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}, {6, 0}, {7, 0}, {8, 0}});
  CHECK(prune(g, path, {{"max_lookahead", "1"}}) == aco::to_waypoints(g, path));
  CHECK(prune(g, path, {{"max_lookahead", "3"}}) == points({{0, 0}, {3, 0}, {6, 0}, {8, 0}}));
  CHECK(prune(g, path, {{"max_lookahead", "8"}}) == points({{0, 0}, {8, 0}}));
  CHECK(prune(g, path, {{"max_lookahead", "100"}}) == points({{0, 0}, {8, 0}}));
  CHECK_THROWS(prune(g, path, {{"max_lookahead", "-1"}}));
}

TEST_CASE("prune on the classic maps: shorter than the A* grid path, every segment free", "[plugin][prune]") {
  for (int m = 1; m <= 3; ++m) {
    const auto map = test::classic_map(m);
    for (bool cc : {false, true}) {
      for (auto n : {aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
        INFO("map" << m << ", neighbourhood " << static_cast<int>(n) << ", corner cutting " << cc);
        const auto g = aco::build_graph(map, {n, cc});
        const auto best = aco::astar(g, g.node({0, 0}), g.node({19, 19}));
        REQUIRE(best);
        const auto r = prune(g, best->nodes);
        CHECK(check_pruned(g, best->nodes, r) >= 1);
        CHECK(aco::polyline_length(r) < best->length);
        CHECK(r.size() < best->nodes.size());
      }
    }
  }
}

TEST_CASE("prune with clearance: every shortcut passes that far from blocked cells", "[plugin][prune]") {
  // Smallest distance from a segment to any blocked cell (outside the map counts), by sampling.
  const auto nearest = [](const aco::Map& map, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    double d = 1e9;
    for (int k = 0; k <= 200; ++k) {
      const Eigen::Vector2d p = (a + (b - a) * (k / 200.0)).head<2>();
      for (int y = -1; y <= map.height(); ++y)
        for (int x = -1; x <= map.width(); ++x)
          if (!map.passable({x, y})) d = std::min(d, aco::distance_to_square(p, Eigen::Vector2d(x, y), 1.0));
    }
    return d;
  };
  int grazing_without = 0;
  for (int m = 1; m <= 3; ++m) {
    const auto map = test::classic_map(m);
    const auto g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
    const auto best = aco::astar(g, g.node({0, 0}), g.node({19, 19}));
    REQUIRE(best);
    const auto clear = prune(g, best->nodes, {{"clearance", "0.4"}});
    const auto plain = prune(g, best->nodes);
    CHECK(clear.front() == g.position(best->nodes.front()));
    CHECK(clear.back() == g.position(best->nodes.back()));
    CHECK(clear.size() < best->nodes.size());  // still shortcuts
    CHECK(aco::polyline_length(clear) <= best->length + 1e-9);
    for (std::size_t i = 1; i < clear.size(); ++i) CHECK(nearest(map, clear[i - 1], clear[i]) >= 0.4 - 1e-6);
    for (std::size_t i = 1; i < plain.size(); ++i) grazing_without += nearest(map, plain[i - 1], plain[i]) < 0.4;
  }
  CHECK(grazing_without > 0);  // without the clearance some shortcut grazes a corner
}

TEST_CASE("prune on random maps and random grid paths: the properties hold", "[plugin][prune]") {
  std::mt19937 rng(3);
  int paths = 0, shortcuts = 0, strictly_shorter = 0;
  for (int trial = 0; trial < 120; ++trial) {
    const auto [map, s, t] = test::random_problem(rng, 4, 22);
    const int w = map.width(), h = map.height();
    for (auto n : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
      for (bool cc : {false, true}) {
        INFO("trial " << trial << ", neighbourhood " << static_cast<int>(n) << ", corner cutting " << cc);
        const auto g = aco::build_graph(map, {n, cc});
        std::vector<std::vector<aco::NodeId>> grid_paths;
        if (const auto best = aco::astar(g, g.node(s), g.node(t))) grid_paths.push_back(best->nodes);
        grid_paths.push_back(loop_free_walk(g, g.node(s), 4 * (w + h), rng));
        grid_paths.push_back(loop_free_walk(g, g.node(t), 400, rng));
        for (const auto& path : grid_paths) {
          const auto r = prune(g, path);
          shortcuts += check_pruned(g, path, r);
          strictly_shorter += aco::polyline_length(r) < aco::path_length(g, path) - 1e-9;
          ++paths;
          // Idempotent: pruning the pruned node sequence changes nothing (from each waypoint no
          // later waypoint but the next one was visible).
          std::vector<aco::NodeId> kept;
          for (const auto& p : r) kept.push_back(g.node({int(p.x()), int(p.y())}));
          CHECK(prune(g, kept) == r);
          // A bounded lookahead keeps every property, with "farthest" within the bound.
          const std::size_t lookahead = std::uniform_int_distribution<std::size_t>(1, 6)(rng);
          check_pruned(g, path, prune(g, path, {{"max_lookahead", std::to_string(lookahead)}}), lookahead);
        }
      }
    }
  }
  INFO(paths << " paths, " << shortcuts << " shortcuts, " << strictly_shorter << " strictly shorter");
  CHECK(paths > 1800);
  CHECK(shortcuts > 2500);
  CHECK(strictly_shorter > 1200);
}

TEST_CASE("acoplan --smoother prune reports the shortened path", "[plugin][prune]") {
  const auto r = test::acoplan({"--map", (test::data_dir() / "maps/classic20/map1.txt").string(), "--start", "0,0",
                                "--goal", "19,19", "--corner-cutting", "--smoother", "prune", "--ants", "20",
                                "--iterations", "20", "--json"});
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["solved"].get<bool>());
  CHECK(j["length"].get<double>() < j["grid_length"].get<double>());
  CHECK(j["path"].size() < j["grid_path"].size());
  CHECK(j["path"].front() == nlohmann::json::array({0, 0}));
  CHECK(j["path"].back() == nlohmann::json::array({19, 19}));
  CHECK(j["config"]["smoother"] == "prune");
}
