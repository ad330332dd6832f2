// The CSR graph: neighbourhoods, corner rule, knight moves, reverse edges, path measures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/rng.hpp"
#include "aco/voxel.hpp"
#include "support.hpp"

namespace {

using test::build;
using test::has_edge;
using test::open_grid;

// Checks the invariants every graph must satisfy.
void check_invariants(const aco::Graph& g) {
  REQUIRE(static_cast<int>(g.offsets.size()) == g.num_nodes() + 1);
  REQUIRE(g.offsets.front() == 0);
  REQUIRE(g.offsets.back() == g.num_edges());
  REQUIRE(g.edge_moves.size() == g.targets.size());
  CHECK(g.terrain_costs.empty());  // a flat grid stores no step lengths and no positions
  CHECK(g.terrain_positions.empty());
  for (aco::NodeId n = 0; n < g.num_nodes(); ++n) {
    if (!g.passable(n)) CHECK(g.degree(n) == 0);
    for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) {
      const aco::NodeId m = g.targets[e];
      CHECK(g.passable(m));
      CHECK(m != n);
      const aco::EdgeId r = g.reverse_edge(e);
      REQUIRE(r >= 0);
      REQUIRE(r < g.num_edges());
      CHECK(g.targets[r] == n);
      CHECK(g.reverse_edge(r) == e);
      CHECK(g.source(e) == n);
      CHECK(g.cost(r) == g.cost(e));
      const aco::Cell a = g.cell(n), b = g.cell(m);
      CHECK(g.cost(e) == Approx(std::hypot(double(a.x - b.x), double(a.y - b.y))));
      CHECK(g.cost(e) == (g.position(n) - g.position(m)).norm());  // bit for bit, as the stored lengths were
    }
  }
}

// Cells (other than the two ends) whose interior the straight segment between two cell centres
// enters, found by sampling the segment: an independent statement of the knight rule.
std::set<std::pair<int, int>> crossed_cells(aco::Cell from, aco::Cell to) {
  std::set<std::pair<int, int>> cells;
  const int samples = 1000;
  for (int i = 1; i < samples; ++i) {
    const double t = (i + 0.5) / samples;
    const double x = from.x + t * (to.x - from.x), y = from.y + t * (to.y - from.y);
    // Skip points on or near a cell border.
    const double fx = x + 0.5 - std::floor(x + 0.5), fy = y + 0.5 - std::floor(y + 0.5);
    if (fx < 1e-6 || fx > 1 - 1e-6 || fy < 1e-6 || fy > 1 - 1e-6) continue;
    const std::pair<int, int> c{int(std::floor(x + 0.5)), int(std::floor(y + 0.5))};
    if (c != std::pair{from.x, from.y} && c != std::pair{to.x, to.y}) cells.insert(c);
  }
  return cells;
}

const std::vector<std::pair<int, int>> kKnightMoves = {{1, 2},  {2, 1},  {-1, 2},  {-2, 1},
                                                       {1, -2}, {2, -1}, {-1, -2}, {-2, -1}};

Eigen::Vector3d p(double x, double y) { return {x, y, 0.0}; }

}  // namespace

TEST_CASE("Open 5x5 grid: edge counts, degrees and costs per neighbourhood", "[graph]") {
  const auto map = test::grid(open_grid(5, 5));
  struct Expect {
    aco::Neighbourhood n;
    int edges, centre, corner, side;
  };
  // Directed edges: 4-conn 2*(5*4 + 5*4) = 80; diagonals add 2*2*4*4 = 64;
  // knight moves add 2*4*(3*4) = 96. Side cell (2,0): 3 / 5 / 5+4.
  for (const Expect& x :
       {Expect{aco::Neighbourhood::four, 80, 4, 2, 3}, Expect{aco::Neighbourhood::eight, 144, 8, 3, 5},
        Expect{aco::Neighbourhood::sixteen, 240, 16, 5, 9}}) {
    for (bool cc : {false, true}) {
      INFO("neighbourhood " << static_cast<int>(x.n) << ", corner cutting " << cc);
      const aco::Graph g = build(map, x.n, cc);
      CHECK(g.width == 5);
      CHECK(g.height == 5);
      CHECK(g.num_nodes() == 25);
      CHECK(g.num_edges() == x.edges);
      CHECK(g.degree(g.node({2, 2})) == x.centre);
      CHECK(g.degree(g.node({0, 0})) == x.corner);
      CHECK(g.degree(g.node({4, 4})) == x.corner);
      CHECK(g.degree(g.node({4, 0})) == x.corner);
      CHECK(g.degree(g.node({2, 0})) == x.side);
      CHECK(g.degree(g.node({0, 2})) == x.side);
      check_invariants(g);
      // The centre reaches exactly the expected offsets, with their Euclidean costs.
      const aco::NodeId c = g.node({2, 2});
      std::set<std::pair<int, int>> offsets;
      for (aco::EdgeId e = g.edges_begin(c); e < g.edges_end(c); ++e) {
        const aco::Cell t = g.cell(g.targets[e]);
        const int dx = t.x - 2, dy = t.y - 2;
        offsets.insert({dx, dy});
        const int manhattan = std::abs(dx) + std::abs(dy);
        const double expected = manhattan == 1 ? 1.0 : manhattan == 2 ? std::sqrt(2.0) : std::sqrt(5.0);
        CHECK(g.cost(e) == Approx(expected));
        CHECK(std::max(std::abs(dx), std::abs(dy)) <= (x.n == aco::Neighbourhood::sixteen ? 2 : 1));
        if (x.n == aco::Neighbourhood::four) CHECK(manhattan == 1);
        if (manhattan == 3) CHECK(std::abs(dx) != std::abs(dy));
      }
      CHECK(static_cast<int>(offsets.size()) == x.centre);
    }
  }
  CHECK(aco::describe({aco::Neighbourhood::eight, false}) == "8-neighbourhood, no corner cutting");
  CHECK(aco::describe({aco::Neighbourhood::sixteen, true}) == "16-neighbourhood, corner cutting");
}

TEST_CASE("Corner rule for diagonal steps", "[graph]") {
  SECTION("both side cells blocked: only with corner cutting") {
    const auto map = test::grid({".#", "#."});
    {  // (a 2x2 map has no room for the 16-neighbourhood's knight moves: an error, see [terrain])
      const auto n = aco::Neighbourhood::eight;
      const auto strict = build(map, n, false);
      CHECK_FALSE(has_edge(strict, {0, 0}, {1, 1}));
      CHECK_FALSE(has_edge(strict, {1, 1}, {0, 0}));
      CHECK(strict.num_edges() == 0);
      const auto cutting = build(map, n, true);
      CHECK(has_edge(cutting, {0, 0}, {1, 1}));
      CHECK(has_edge(cutting, {1, 1}, {0, 0}));
      CHECK(cutting.num_edges() == 2);
      CHECK(cutting.cost(cutting.find_edge(0, 3)) == Approx(std::sqrt(2.0)));
      check_invariants(cutting);
    }
    // The other diagonal, mirrored.
    const auto mirrored = test::grid({"#.", ".#"});
    CHECK_FALSE(has_edge(build(mirrored, aco::Neighbourhood::eight, false), {1, 0}, {0, 1}));
    CHECK(has_edge(build(mirrored, aco::Neighbourhood::eight, true), {1, 0}, {0, 1}));
  }
  SECTION("one side cell blocked: refused without corner cutting, allowed with it") {
    for (const auto& rows : {std::vector<std::string>{".#", ".."}, std::vector<std::string>{"..", "#."}}) {
      INFO(rows[0] << "/" << rows[1]);
      const auto map = test::grid(rows);
      const auto strict = build(map, aco::Neighbourhood::eight, false);
      CHECK_FALSE(has_edge(strict, {0, 0}, {1, 1}));
      CHECK_FALSE(has_edge(strict, {1, 1}, {0, 0}));
      const auto cutting = build(map, aco::Neighbourhood::eight, true);
      CHECK(has_edge(cutting, {0, 0}, {1, 1}));
      CHECK(has_edge(cutting, {1, 1}, {0, 0}));
      check_invariants(strict);
      check_invariants(cutting);
    }
  }
  SECTION("free side cells: diagonal always allowed; blocked target: never") {
    const auto map = test::grid({"..", ".."});
    CHECK(has_edge(build(map, aco::Neighbourhood::eight, false), {0, 0}, {1, 1}));
    CHECK(has_edge(build(map, aco::Neighbourhood::eight, false), {1, 0}, {0, 1}));
    const auto blocked = test::grid({"..", ".#"});
    CHECK_FALSE(has_edge(build(blocked, aco::Neighbourhood::eight, true), {0, 0}, {1, 1}));
    CHECK_FALSE(has_edge(build(blocked, aco::Neighbourhood::four, false), {1, 0}, {1, 1}));
  }
  SECTION("4-neighbourhood has no diagonals even with corner cutting") {
    const auto g = build(test::grid({"..", ".."}), aco::Neighbourhood::four, true);
    CHECK_FALSE(has_edge(g, {0, 0}, {1, 1}));
    CHECK(g.num_edges() == 8);
  }
}

TEST_CASE("Knight moves need the two cells beside the segment midpoint", "[graph]") {
  // The rule as stated for two directions; the sampled geometry must agree with it.
  CHECK(crossed_cells({2, 2}, {3, 4}) == std::set<std::pair<int, int>>{{2, 3}, {3, 3}});
  CHECK(crossed_cells({2, 2}, {4, 3}) == std::set<std::pair<int, int>>{{3, 2}, {3, 3}});
  CHECK(crossed_cells({2, 2}, {3, 3}).empty());  // a diagonal only touches its side cells at a corner

  const aco::Cell centre{2, 2};
  for (const auto& [dx, dy] : kKnightMoves) {
    const aco::Cell target{centre.x + dx, centre.y + dy};
    const auto crossed = crossed_cells(centre, target);
    REQUIRE(crossed.size() == 2);
    // Block each other cell of the 5x5 grid in turn: the move survives unless the cell is crossed.
    for (int by = 0; by < 5; ++by) {
      for (int bx = 0; bx < 5; ++bx) {
        const aco::Cell b{bx, by};
        if (b == centre || b == target) continue;
        auto rows = open_grid(5, 5);
        rows[by][bx] = '#';
        const auto map = test::grid(rows);
        const bool expected = crossed.count({bx, by}) == 0;
        for (bool cc : {false, true}) {
          INFO("move (" << dx << "," << dy << "), blocked " << aco::to_string(b) << ", corner cutting " << cc);
          const auto g = build(map, aco::Neighbourhood::sixteen, cc);
          CHECK(has_edge(g, centre, target) == expected);
          CHECK(has_edge(g, target, centre) == expected);
        }
      }
    }
    // Both crossed cells free but everything else around blocked: still allowed.
    auto rows = std::vector<std::string>(5, std::string(5, '#'));
    rows[centre.y][centre.x] = '.';
    rows[target.y][target.x] = '.';
    for (const auto& [cx, cy] : crossed) rows[cy][cx] = '.';
    const auto map = test::grid(rows);
    for (bool cc : {false, true}) {
      INFO("move (" << dx << "," << dy << ") in a corridor, corner cutting " << cc);
      const auto g = build(map, aco::Neighbourhood::sixteen, cc);
      CHECK(has_edge(g, centre, target));
      CHECK(g.cost(g.find_edge(g.node(centre), g.node(target))) == Approx(std::sqrt(5.0)));
      check_invariants(g);
    }
  }
}

TEST_CASE("A knight move never jumps a one-cell wall", "[graph]") {
  const auto map = test::grid({"..#..", "..#..", "..#.."});
  for (bool cc : {false, true}) {
    const auto g = build(map, aco::Neighbourhood::sixteen, cc);
    CHECK_FALSE(has_edge(g, {1, 0}, {3, 1}));
    CHECK_FALSE(has_edge(g, {1, 1}, {3, 0}));
    CHECK_FALSE(has_edge(g, {1, 2}, {3, 1}));
    CHECK_FALSE(aco::reachable(g, g.node({0, 0}), g.node({4, 2})));
  }
}

TEST_CASE("Reverse edges, find_edge and blocked cells on a map with obstacles", "[graph]") {
  const auto map = test::grid({
      "....#...",
      ".##.#.#.",
      "....#...",
      "#.#...#.",
      "...#....",
      ".#...##.",
  });
  for (auto n : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
    for (bool cc : {false, true}) {
      INFO("neighbourhood " << static_cast<int>(n) << ", corner cutting " << cc);
      const auto g = build(map, n, cc);
      check_invariants(g);
      CHECK(g.degree(g.node({4, 0})) == 0);
      CHECK(g.degree(g.node({1, 1})) == 0);
      CHECK(g.find_edge(g.node({0, 0}), g.node({1, 0})) >= 0);
      CHECK(g.find_edge(g.node({0, 0}), g.node({1, 1})) == -1);  // blocked target
      CHECK(g.find_edge(g.node({0, 0}), g.node({3, 0})) == -1);  // too far
      CHECK(g.find_edge(g.node({4, 0}), g.node({3, 0})) == -1);  // blocked source
      const aco::EdgeId e = g.find_edge(g.node({0, 0}), g.node({0, 1}));
      REQUIRE(e >= 0);
      CHECK(g.targets[e] == g.node({0, 1}));
      CHECK(g.cell(g.node({5, 3})) == aco::Cell{5, 3});
      CHECK(g.node({5, 3}) == 3 * 8 + 5);
    }
  }
}

TEST_CASE("subgraph keeps the edges between open nodes, and edges_in and per_edge map them back", "[graph]") {
  std::mt19937 rng(23);
  for (int trial = 0; trial < 100; ++trial) {
    const aco::OccupancyGrid map =
        test::random_grid(rng, 3 + static_cast<int>(rng() % 10), 3 + static_cast<int>(rng() % 10));
    const auto n = trial % 3 == 0 ? aco::Neighbourhood::four : aco::Neighbourhood::eight;
    const aco::Graph g = build(map, n, trial % 2 == 0);
    std::vector<std::uint8_t> closed(g.num_nodes(), 0);
    for (auto& c : closed) c = rng() % 3 == 0;
    const aco::Graph part = aco::subgraph(g, closed);
    INFO("trial " << trial);
    REQUIRE(part.num_nodes() == g.num_nodes());
    check_invariants(part);
    std::vector<double> values(static_cast<std::size_t>(part.num_edges()));
    for (std::size_t e = 0; e < values.size(); ++e) values[e] = 1.0 + static_cast<double>(e);
    const std::vector<double> whole = aco::per_edge(g, aco::edges_in(g, part), values);
    REQUIRE(whole.size() == static_cast<std::size_t>(g.num_edges()));
    int kept = 0;
    for (aco::NodeId a = 0; a < g.num_nodes(); ++a)
      for (aco::EdgeId e = g.edges_begin(a); e < g.edges_end(a); ++e) {
        const aco::NodeId b = g.targets[e];
        const aco::EdgeId in_part = part.find_edge(a, b);
        if (closed[a] || closed[b]) {
          CHECK(in_part == -1);
          CHECK(whole[e] == 0.0);
          continue;
        }
        ++kept;
        REQUIRE(in_part >= 0);
        CHECK(part.cost(in_part) == g.cost(e));
        CHECK(whole[e] == values[in_part]);
      }
    CHECK(part.num_edges() == kept);
  }
}

TEST_CASE("build_graph with closed nodes is the subgraph of the whole graph, in 2D and in voxel worlds", "[graph]") {
  std::mt19937 rng(29);
  const auto same = [](const aco::Graph& a, const aco::Graph& b) {
    CHECK(a.offsets == b.offsets);
    CHECK(a.targets == b.targets);
    CHECK(a.edge_moves == b.edge_moves);
    CHECK(a.move_mask == b.move_mask);
  };
  for (int trial = 0; trial < 60; ++trial) {
    INFO("trial " << trial);
    std::unique_ptr<aco::Map> map;
    aco::GraphOptions options{aco::Neighbourhood::eight, trial % 2 == 0};
    if (trial % 3 == 0) {
      auto world = std::make_unique<aco::VoxelMap>(3 + static_cast<int>(rng() % 6), 3 + static_cast<int>(rng() % 6),
                                                   2 + static_cast<int>(rng() % 5), "world");
      for (int z = 0; z < world->depth(); ++z)
        for (int y = 0; y < world->height(); ++y)
          for (int x = 0; x < world->width(); ++x) world->set_blocked({x, y, z}, rng() % 4 == 0);
      map = std::move(world);
      options.neighbourhood = trial % 2 ? aco::Neighbourhood::twenty_six : aco::Neighbourhood::eighteen;
    } else {
      map = std::make_unique<aco::OccupancyGrid>(
          test::random_grid(rng, 3 + static_cast<int>(rng() % 10), 3 + static_cast<int>(rng() % 10)));
    }
    const aco::Graph whole = aco::build_graph(*map, options);
    std::vector<std::uint8_t> closed(static_cast<std::size_t>(whole.num_nodes()), 0);
    for (auto& c : closed) c = rng() % 3 == 0;
    const aco::Graph part = aco::build_graph(*map, options, closed);
    if (!map->volumetric()) check_invariants(part);
    same(part, aco::subgraph(whole, closed));
    same(aco::build_graph(*map, options, {}), whole);
  }
  const auto map = test::grid({"...", "..."});
  CHECK_THROWS_WITH(aco::build_graph(map, {aco::Neighbourhood::four, false}, std::vector<std::uint8_t>(5, 0)),
                    Catch::Contains("5 entries for 6 nodes"));
}

TEST_CASE("reachable across a wall", "[graph]") {
  SECTION("closed wall") {
    const auto map = test::grid({"..#..", "..#..", "..#.."});
    for (auto n : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen}) {
      for (bool cc : {false, true}) {
        const auto g = build(map, n, cc);
        CHECK_FALSE(aco::reachable(g, g.node({0, 0}), g.node({4, 2})));
        CHECK(aco::reachable(g, g.node({0, 0}), g.node({1, 2})));
        CHECK(aco::reachable(g, g.node({3, 0}), g.node({4, 2})));
        CHECK(aco::reachable(g, g.node({0, 0}), g.node({0, 0})));
      }
    }
  }
  SECTION("wall with a gap") {
    const auto map = test::grid({"..#..", "..#..", "....."});
    const auto g = build(map, aco::Neighbourhood::four, false);
    CHECK(aco::reachable(g, g.node({0, 0}), g.node({4, 0})));
  }
  SECTION("diagonal gap: only with corner cutting") {
    const auto map = test::grid({"..#..", "..#..", ".#..."});
    CHECK_FALSE(aco::reachable(build(map, aco::Neighbourhood::eight, false), 0, 14));
    CHECK(aco::reachable(build(map, aco::Neighbourhood::eight, true), 0, 14));
  }
}

TEST_CASE("BreadthFirstSearch: fewest steps round blocked and avoided nodes, within a node limit", "[graph]") {
  // The only way from the left half to the right half is the gap at (2, 2).
  const auto map = test::grid({"..#..", "..#..", "....."});
  const auto g = build(map, aco::Neighbourhood::four, false);
  const aco::NodeId from = g.node({0, 0}), to = g.node({4, 0}), gap = g.node({2, 2});
  aco::BreadthFirstSearch search;
  REQUIRE(search.find(g, from, to));
  const auto& path = search.path();
  CHECK(path.front() == from);
  CHECK(path.back() == to);
  CHECK(path.size() == 9);  // 8 steps: down 2, across 4, up 2
  CHECK(std::find(path.begin(), path.end(), gap) != path.end());
  CHECK(aco::path_length(g, path) == Approx(8.0));

  CHECK_FALSE(search.find(g, from, to, {}, gap));  // avoiding the gap cuts the map in two
  std::vector<std::uint8_t> blocked(g.num_nodes(), 0);
  blocked[gap] = 1;
  CHECK_FALSE(search.find(g, from, to, blocked));
  blocked[gap] = 0;
  blocked[g.node({0, 1})] = 1;  // the way down column 1 stays open, as short
  REQUIRE(search.find(g, from, to, blocked));
  CHECK(search.path().size() == 9);
  CHECK(std::find(search.path().begin(), search.path().end(), g.node({0, 1})) == search.path().end());

  // The left half holds 6 nodes and the goal is 8 steps away: 6 nodes taken from the queue
  // cannot reach it, the whole map can.
  CHECK_FALSE(search.find(g, from, to, {}, -1, 6));
  CHECK(search.find(g, from, to, {}, -1, g.num_nodes()));
  // Many searches with one object (stamps) answer as fresh ones do.
  for (int i = 0; i < 300; ++i) REQUIRE(search.find(g, to, from) == aco::reachable(g, to, from));
}

TEST_CASE("path_length sums step costs and rejects non-neighbours", "[graph]") {
  const auto map = test::grid(open_grid(5, 5));
  const auto g = build(map, aco::Neighbourhood::sixteen);
  auto nodes = [&](std::initializer_list<aco::Cell> cells) {
    std::vector<aco::NodeId> v;
    for (const auto& c : cells) v.push_back(g.node(c));
    return v;
  };
  const auto path = nodes({{0, 0}, {1, 1}, {2, 1}, {4, 2}, {4, 3}});
  CHECK(aco::path_length(g, path) == Approx(std::sqrt(2.0) + 1.0 + std::sqrt(5.0) + 1.0));
  CHECK(aco::path_length(g, nodes({{2, 2}})) == 0.0);
  CHECK(aco::path_length(g, std::vector<aco::NodeId>{}) == 0.0);
  const auto jump = nodes({{0, 0}, {1, 0}, {3, 0}});
  REQUIRE_THROWS_AS(aco::path_length(g, jump), aco::Error);
  REQUIRE_THROWS_WITH(aco::path_length(g, jump), Catch::Contains("(1,0) -> (3,0)") && Catch::Contains("not an edge"));
  // A knight step is not an edge of the 8-neighbourhood.
  const auto g8 = build(map, aco::Neighbourhood::eight);
  REQUIRE_THROWS_WITH(aco::path_length(g8, nodes({{0, 0}, {2, 1}})), Catch::Contains("(0,0) -> (2,1)"));
  // Into a blocked cell.
  const auto walled = test::grid({"...", ".#.", "..."});
  const auto gw = build(walled, aco::Neighbourhood::eight);
  REQUIRE_THROWS_AS(aco::path_length(gw, std::vector<aco::NodeId>{0, 4}), aco::Error);
}

TEST_CASE("polyline_length and to_waypoints", "[graph]") {
  CHECK(aco::polyline_length(aco::Waypoints{}) == 0.0);
  CHECK(aco::polyline_length(aco::Waypoints{p(1, 1)}) == 0.0);
  CHECK(aco::polyline_length(aco::Waypoints{p(0, 0), p(3, 4)}) == Approx(5.0));
  CHECK(aco::polyline_length(aco::Waypoints{p(0, 0), p(1, 0), p(1, 1), p(0, 0)}) == Approx(2.0 + std::sqrt(2.0)));
  CHECK(aco::polyline_length(aco::Waypoints{{0, 0, 0}, {0, 0, 2}}) == Approx(2.0));

  const auto map = test::grid(open_grid(4, 3));
  const auto g = build(map, aco::Neighbourhood::eight);
  const std::vector<aco::NodeId> path{g.node({0, 0}), g.node({1, 1}), g.node({2, 1}), g.node({3, 2})};
  const auto points = aco::to_waypoints(g, path);
  REQUIRE(points.size() == 4);
  CHECK(points[1].isApprox(p(1, 1)));
  CHECK(points[3].isApprox(p(3, 2)));
  CHECK(aco::polyline_length(points) == Approx(aco::path_length(g, path)));
}

TEST_CASE("count_turns on hand-made waypoint lists", "[graph]") {
  using W = aco::Waypoints;
  CHECK(aco::count_turns(W{}) == 0);
  CHECK(aco::count_turns(W{p(0, 0)}) == 0);
  CHECK(aco::count_turns(W{p(0, 0), p(5, 5)}) == 0);
  // Straight lines, also with uneven spacing and diagonally.
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(2, 0), p(3, 0)}) == 0);
  CHECK(aco::count_turns(W{p(0, 0), p(1, 1), p(3, 3), p(4, 4)}) == 0);
  CHECK(aco::count_turns(W{p(0, 0), p(1, 2), p(3, 6)}) == 0);
  // An L.
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(2, 0), p(2, 1), p(2, 2)}) == 1);
  // Straight then diagonal then straight: two heading changes.
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(2, 1), p(3, 1)}) == 2);
  // Collinear repeated points are not turns.
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(1, 0), p(2, 0)}) == 0);
  CHECK(aco::count_turns(W{p(0, 0), p(0, 0), p(1, 0), p(2, 0), p(2, 0)}) == 0);
  // A U-turn reverses the heading.
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(0, 0)}) == 1);
  CHECK(aco::count_turns(W{p(0, 0), p(2, 0), p(2, 1), p(0, 1)}) == 2);
  // Zig-zag.
  CHECK(aco::count_turns(W{p(0, 0), p(1, 1), p(2, 0), p(3, 1), p(4, 0)}) == 3);
}

TEST_CASE("count_turns: a repeated waypoint at a corner still is one turn", "[graph]") {
  // The heading changes from +x to +y at (1,0); repeating that waypoint must not hide the turn.
  using W = aco::Waypoints;
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(1, 0), p(1, 1)}) == 1);
  CHECK(aco::count_turns(W{p(0, 0), p(1, 0), p(1, 0), p(0, 0)}) == 1);  // U-turn with a repeat
}

// ---------------------------------------------------------------------------------------------
// line_of_sight
//
// test::reference_segment_clear (support.hpp) is an independent statement of the segment rule.

TEST_CASE("edge_by_move and find_edge agree with a scan of the edge list", "[graph]") {
  aco::Rng rng(5);
  for (int round = 0; round < 20; ++round) {
    std::vector<std::string> rows(9, std::string(11, '.'));
    for (auto& row : rows)
      for (char& c : row) c = rng.uniform() < 0.25 ? '#' : '.';
    const auto map = test::grid(rows);
    for (auto hood : {aco::Neighbourhood::four, aco::Neighbourhood::eight, aco::Neighbourhood::sixteen})
      for (bool cc : {false, true}) {
        const aco::Graph g = aco::build_graph(map, {hood, cc});
        for (aco::NodeId a = 0; a < g.num_nodes(); ++a)
          for (int dy = -3; dy <= 3; ++dy)
            for (int dx = -3; dx <= 3; ++dx) {
              const aco::Cell from = g.cell(a), to{from.x + dx, from.y + dy};
              aco::EdgeId scanned = -1;
              for (aco::EdgeId e = g.edges_begin(a); e < g.edges_end(a); ++e)
                if (map.contains(to) && g.targets[e] == g.node(to)) scanned = e;
              REQUIRE(g.edge_by_move(a, dx, dy) == scanned);
              if (map.contains(to)) REQUIRE(g.find_edge(a, g.node(to)) == scanned);
            }
      }
  }
}

TEST_CASE("A step rule that allows a step but not its reverse is refused by name", "[graph]") {
  // A map plugin's step rule (Map::step_allowed()) need not be symmetric; the engine needs every
  // edge's reverse. Plain grids skip the check: their moves are symmetric by construction.
  class OneWay final : public aco::Map {
   public:
    int width() const override { return 3; }
    int height() const override { return 1; }
    bool passable(aco::Cell c) const override { return contains(c); }
    bool step_allowed(aco::Cell from, aco::Cell to) const override { return !(from.x == 1 && to.x == 0); }
    std::string name() const override { return "one-way"; }
  } map;
  CHECK_THROWS_WITH(aco::build_graph(map, {aco::Neighbourhood::four, false}),
                    "one-way: the step (0,0) -> (1,0) is allowed but its reverse is not");
}
