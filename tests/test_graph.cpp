// The CSR graph: neighbourhoods, corner rule, knight moves, reverse edges, path measures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/rng.hpp"
#include "support.hpp"

namespace {

aco::Graph build(const aco::Map& map, aco::Neighbourhood n, bool corner_cutting = false) {
  aco::GraphOptions options;
  options.neighbourhood = n;
  options.corner_cutting = corner_cutting;
  return aco::build_graph(map, options);
}

bool has_edge(const aco::Graph& g, aco::Cell a, aco::Cell b) { return g.find_edge(g.node(a), g.node(b)) >= 0; }

std::vector<std::string> open_grid(int w, int h) { return std::vector<std::string>(h, std::string(w, '.')); }

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

#include <random>

namespace {

using CellSet = std::set<std::pair<int, int>>;

aco::OccupancyGrid blocked_at(int w, int h, std::initializer_list<aco::Cell> blocked) {
  auto rows = open_grid(w, h);
  for (const auto& c : blocked) rows[c.y][c.x] = '#';
  return test::grid(rows);
}

}  // namespace

TEST_CASE("line_of_sight: the reference sampler agrees with hand-computed crossings", "[graph][line_of_sight]") {
  CHECK(test::reference_cells_entered({0, 0}, {4, 1}) == CellSet{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {3, 1}, {4, 1}});
  CHECK(test::reference_cells_entered({0, 0}, {2, 1}) == CellSet{{0, 0}, {1, 0}, {1, 1}, {2, 1}});
  CHECK(test::reference_cells_entered({0, 0}, {3, 0}) == CellSet{{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  CHECK(test::reference_cells_entered({2, 2}, {2, 2}) == CellSet{{2, 2}});
  // A diagonal enters only the cells on it; (0,0)-(3,1) passes the vertex (1.5, 0.5).
  CHECK(test::reference_cells_entered({0, 0}, {2, 2}) == CellSet{{0, 0}, {1, 1}, {2, 2}});
  CHECK(test::reference_cells_entered({0, 0}, {3, 1}) == CellSet{{0, 0}, {1, 0}, {2, 1}, {3, 1}});
  CHECK(test::reference_cells_entered({3, 1}, {0, 0}) == test::reference_cells_entered({0, 0}, {3, 1}));
  const auto v = test::reference_vertex_sides({0, 0}, {3, 1});
  REQUIRE(v.size() == 1);
  CHECK(CellSet{{v[0].first.x, v[0].first.y}, {v[0].second.x, v[0].second.y}} == CellSet{{2, 0}, {1, 1}});
  CHECK(test::reference_vertex_sides({0, 0}, {2, 2}).size() == 2);
  CHECK(test::reference_vertex_sides({0, 0}, {4, 1}).empty());
  CHECK(test::reference_vertex_sides({0, 0}, {0, 5}).empty());
  // Along a diagonal of the other orientation the side cells are the anti-diagonal pair.
  const auto w = test::reference_vertex_sides({1, 0}, {0, 1});
  REQUIRE(w.size() == 1);
  CHECK(CellSet{{w[0].first.x, w[0].first.y}, {w[0].second.x, w[0].second.y}} == CellSet{{0, 0}, {1, 1}});
}

TEST_CASE("line_of_sight: rows and columns", "[graph][line_of_sight]") {
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    const auto open = test::grid(open_grid(7, 5));
    CHECK(aco::line_of_sight(open, {0, 2}, {6, 2}, cc));
    CHECK(aco::line_of_sight(open, {6, 2}, {0, 2}, cc));
    CHECK(aco::line_of_sight(open, {3, 0}, {3, 4}, cc));
    CHECK(aco::line_of_sight(open, {3, 4}, {3, 0}, cc));
    CHECK(aco::line_of_sight(open, {0, 0}, {1, 0}, cc));
    const auto wall = blocked_at(7, 5, {{3, 2}});
    CHECK_FALSE(aco::line_of_sight(wall, {0, 2}, {6, 2}, cc));
    CHECK_FALSE(aco::line_of_sight(wall, {6, 2}, {0, 2}, cc));
    CHECK_FALSE(aco::line_of_sight(wall, {3, 0}, {3, 4}, cc));
    CHECK_FALSE(aco::line_of_sight(wall, {3, 4}, {3, 0}, cc));
    CHECK_FALSE(aco::line_of_sight(wall, {3, 2}, {5, 2}, cc));  // blocked end
    CHECK_FALSE(aco::line_of_sight(wall, {1, 2}, {3, 2}, cc));
    // The neighbouring rows and columns pass right beside the blocked cell.
    CHECK(aco::line_of_sight(wall, {0, 1}, {6, 1}, cc));
    CHECK(aco::line_of_sight(wall, {0, 3}, {6, 3}, cc));
    CHECK(aco::line_of_sight(wall, {2, 0}, {2, 4}, cc));
    CHECK(aco::line_of_sight(wall, {4, 4}, {4, 0}, cc));
  }
}

TEST_CASE("line_of_sight: diagonals through vertices and the corner rule", "[graph][line_of_sight]") {
  // (0,0) -> (2,2) passes the vertices (0.5,0.5) [sides (1,0), (0,1)] and (1.5,1.5) [sides (2,1), (1,2)].
  struct Case {
    std::vector<aco::Cell> blocked;
    bool strict, cutting;
  };
  const Case cases[] = {
      {{}, true, true},
      {{{1, 0}}, false, true},  // one side cell blocked
      {{{0, 1}}, false, true},
      {{{1, 2}}, false, true},  // at the second vertex
      {{{1, 0}, {0, 1}}, false, false},  // squeezing between two
      {{{2, 1}, {1, 2}}, false, false},
      {{{1, 0}, {1, 2}}, false, true},  // one side at each vertex
      {{{1, 1}}, false, false},  // a cell on the diagonal
      {{{2, 0}, {0, 2}}, true, true},  // cells the segment does not touch
  };
  for (const Case& c : cases) {
    auto rows3 = open_grid(3, 3);
    for (const auto& b : c.blocked) rows3[b.y][b.x] = '#';
    const auto map = test::grid(rows3);
    std::string text;
    for (const auto& b : c.blocked) text += aco::to_string(b);
    INFO("blocked " << text);
    CHECK(aco::line_of_sight(map, {0, 0}, {2, 2}, false) == c.strict);
    CHECK(aco::line_of_sight(map, {2, 2}, {0, 0}, false) == c.strict);
    CHECK(aco::line_of_sight(map, {0, 0}, {2, 2}, true) == c.cutting);
    CHECK(aco::line_of_sight(map, {2, 2}, {0, 0}, true) == c.cutting);
    // The same map mirrored left-right: the anti-diagonal (2,0) -> (0,2).
    auto rows = open_grid(3, 3);
    for (const auto& b : c.blocked) rows[b.y][2 - b.x] = '#';
    const auto m = test::grid(rows);
    CHECK(aco::line_of_sight(m, {2, 0}, {0, 2}, false) == c.strict);
    CHECK(aco::line_of_sight(m, {0, 2}, {2, 0}, true) == c.cutting);
  }
  {  // A single diagonal step squeezing between two blocked cells is refused even with corner cutting.
    const auto map = test::grid({".#", "#."});
    CHECK_FALSE(aco::line_of_sight(map, {0, 0}, {1, 1}, true));
    CHECK_FALSE(aco::line_of_sight(map, {0, 0}, {1, 1}, false));
    // ... although the graph with corner cutting has that edge: the segment rule is stricter.
    CHECK(has_edge(build(map, aco::Neighbourhood::eight, true), {0, 0}, {1, 1}));
  }
}

TEST_CASE("line_of_sight: knight-like and arbitrary slopes", "[graph][line_of_sight]") {
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    // (0,0) -> (2,1) crosses (1,0) and (1,1) through the middle of their shared edge.
    CHECK(aco::line_of_sight(blocked_at(3, 2, {}), {0, 0}, {2, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(blocked_at(3, 2, {{1, 0}}), {0, 0}, {2, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(blocked_at(3, 2, {{1, 1}}), {2, 1}, {0, 0}, cc));
    CHECK(aco::line_of_sight(blocked_at(3, 2, {{0, 1}, {2, 0}}), {0, 0}, {2, 1}, cc));
    // (0,0) -> (4,1): enters (1,0), (2,0), (2,1), (3,1); passes close to (1,1) and (3,0) without touching.
    for (aco::Cell entered : {aco::Cell{1, 0}, aco::Cell{2, 0}, aco::Cell{2, 1}, aco::Cell{3, 1}}) {
      INFO("blocked " << aco::to_string(entered));
      CHECK_FALSE(aco::line_of_sight(blocked_at(5, 2, {entered}), {0, 0}, {4, 1}, cc));
      CHECK_FALSE(aco::line_of_sight(blocked_at(5, 2, {entered}), {4, 1}, {0, 0}, cc));
    }
    CHECK(aco::line_of_sight(blocked_at(5, 2, {{1, 1}, {3, 0}, {0, 1}, {4, 0}}), {0, 0}, {4, 1}, cc));
    CHECK(aco::line_of_sight(blocked_at(5, 2, {{1, 1}, {3, 0}}), {4, 1}, {0, 0}, cc));
    // (0,0) -> (3,1) passes exactly through the vertex (1.5, 0.5): side cells (2,0) and (1,1).
    CHECK(aco::line_of_sight(blocked_at(4, 2, {}), {0, 0}, {3, 1}, cc));
    CHECK(aco::line_of_sight(blocked_at(4, 2, {{2, 0}}), {0, 0}, {3, 1}, cc) == cc);
    CHECK(aco::line_of_sight(blocked_at(4, 2, {{1, 1}}), {3, 1}, {0, 0}, cc) == cc);
    CHECK_FALSE(aco::line_of_sight(blocked_at(4, 2, {{2, 0}, {1, 1}}), {0, 0}, {3, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(blocked_at(4, 2, {{1, 0}}), {0, 0}, {3, 1}, cc));
    CHECK(aco::line_of_sight(blocked_at(4, 2, {{0, 1}, {3, 0}}), {0, 0}, {3, 1}, cc));
    // A long shallow segment, (0,0) -> (9,2), in both directions: blocking any cell it enters
    // (as the reference finds them) refuses it, blocking any other cell of the box does not,
    // unless that cell is a side cell at a vertex (here there is none: gcd(9,2) = 1 and 9, 2 not both odd).
    const auto entered = test::reference_cells_entered({0, 0}, {9, 2});
    REQUIRE(test::reference_vertex_sides({0, 0}, {9, 2}).empty());
    for (int y = 0; y < 3; ++y) {
      for (int x = 0; x < 10; ++x) {
        const auto map = blocked_at(10, 3, {{x, y}});
        INFO("blocked " << x << "," << y);
        CHECK(aco::line_of_sight(map, {0, 0}, {9, 2}, cc) == (entered.count({x, y}) == 0));
        CHECK(aco::line_of_sight(map, {9, 2}, {0, 0}, cc) == (entered.count({x, y}) == 0));
      }
    }
  }
}

TEST_CASE("line_of_sight: ends outside the map, a == b", "[graph][line_of_sight]") {
  const auto map = blocked_at(4, 3, {{2, 1}});
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    CHECK(aco::line_of_sight(map, {1, 1}, {1, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {2, 1}, {2, 1}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {-1, 0}, {-1, 0}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {0, 0}, {-1, 0}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {-1, 0}, {0, 0}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {0, 0}, {4, 0}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {3, 2}, {3, 3}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {-2, -1}, {5, 4}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {0, 3}, {3, 3}, cc));  // a row just below the map
    // Along the map border, inside: fine; a diagonal from a corner cell leaves through the corner vertex.
    CHECK(aco::line_of_sight(map, {0, 0}, {3, 0}, cc));
    CHECK(aco::line_of_sight(map, {0, 2}, {3, 2}, cc));
    CHECK_FALSE(aco::line_of_sight(map, {0, 0}, {-1, -1}, cc));
  }
  // Between two cells of the map, every cell and side cell the segment meets lies in the
  // bounding box of its ends, so inside the map.
  CHECK(aco::line_of_sight(test::grid({"..", ".."}), {0, 0}, {1, 1}, false));
  CHECK(aco::line_of_sight(test::grid({"..", ".."}), {0, 1}, {1, 0}, false));
}

TEST_CASE("line_of_sight agrees with the graph's moves", "[graph][line_of_sight]") {
  // For every king and knight move, a segment is free exactly when the graph has the edge,
  // except that with corner cutting a diagonal edge may squeeze between two blocked cells.
  std::mt19937 rng(7);
  std::bernoulli_distribution blocked(0.3);
  int edges = 0, squeezes = 0;
  for (int trial = 0; trial < 30; ++trial) {
    aco::OccupancyGrid map(9, 7, "random");
    for (int y = 0; y < 7; ++y)
      for (int x = 0; x < 9; ++x) map.set_blocked({x, y}, blocked(rng));
    for (bool cc : {false, true}) {
      const auto g = build(map, aco::Neighbourhood::sixteen, cc);
      for (aco::NodeId n = 0; n < g.num_nodes(); ++n) {
        const aco::Cell a = g.cell(n);
        for (int dy = -2; dy <= 2; ++dy) {
          for (int dx = -2; dx <= 2; ++dx) {
            if ((dx == 0 && dy == 0) || std::abs(dx) + std::abs(dy) == 4 || (std::abs(dx) == 2 && dy == 0) ||
                (dx == 0 && std::abs(dy) == 2))
              continue;
            const aco::Cell b{a.x + dx, a.y + dy};
            const bool edge = map.contains(b) && has_edge(g, a, b);
            const bool los = aco::line_of_sight(map, a, b, cc);
            const bool squeeze = cc && std::abs(dx) == 1 && std::abs(dy) == 1 && !map.passable({a.x + dx, a.y}) &&
                                 !map.passable({a.x, a.y + dy});
            INFO(aco::to_string(a) << " -> " << aco::to_string(b) << ", corner cutting " << cc);
            if (squeeze) {
              CHECK_FALSE(los);
              squeezes += edge;
            } else {
              CHECK(los == edge);
            }
            edges += edge;
          }
        }
      }
    }
  }
  CHECK(edges > 1000);
  CHECK(squeezes > 10);
}

TEST_CASE("line_of_sight on random maps: symmetric, equal to the reference and to segment_free",
          "[graph][line_of_sight][segment_free]") {
  std::mt19937 rng(2024);
  int free = 0, refused = 0, vertex_cases = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::uniform_int_distribution<int> size(3, 16);
    const int w = size(rng), h = size(rng);
    const aco::OccupancyGrid map = test::random_grid(rng, w, h);
    // Ends inside, one in ten up to two cells outside the map.
    std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1), ox(-2, w + 1), oy(-2, h + 1);
    std::bernoulli_distribution outside(0.1);
    auto end = [&] { return outside(rng) ? aco::Cell{ox(rng), oy(rng)} : aco::Cell{px(rng), py(rng)}; };
    for (int pair = 0; pair < 60; ++pair) {
      const aco::Cell a = end(), b = end();
      vertex_cases += !test::reference_vertex_sides(a, b).empty();
      for (bool cc : {false, true}) {
        const bool los = aco::line_of_sight(map, a, b, cc);
        INFO(w << "x" << h << " map, " << aco::to_string(a) << " -> " << aco::to_string(b) << ", corner cutting "
               << cc);
        // One CHECK per comparison would be 24000 assertions; count failures instead.
        const bool ok = los == aco::line_of_sight(map, b, a, cc) &&
                        los == test::reference_segment_clear(map, a, b, cc) &&
                        test::reference_segment_clear(map, b, a, cc) == los;
        if (!ok) CHECK(los == test::reference_segment_clear(map, a, b, cc));
        if (!ok) CHECK(los == aco::line_of_sight(map, b, a, cc));
        // segment_free between the cells' centres is line_of_sight.
        const Eigen::Vector2d pa(a.x, a.y), pb(b.x, b.y);
        if (aco::segment_free(map, pa, pb, cc) != los || aco::segment_free(map, pb, pa, cc) != los) {
          CHECK(aco::segment_free(map, pa, pb, cc) == los);
          CHECK(aco::segment_free(map, pb, pa, cc) == los);
        }
        (los ? free : refused) += 1;
        // Corner cutting only ever allows more.
        if (!cc && los) CHECK(aco::line_of_sight(map, a, b, true));
      }
    }
  }
  INFO(free << " free, " << refused << " refused, " << vertex_cases << " through a vertex");
  CHECK(free > 6000);
  CHECK(refused > 10000);
  CHECK(vertex_cases > 2000);
}

TEST_CASE("line_of_sight on long segments", "[graph][line_of_sight]") {
  aco::OccupancyGrid map(600, 450, "large");
  const aco::Cell a{3, 5}, b{597, 446};
  CHECK(aco::line_of_sight(map, a, b, false));
  const auto entered = test::reference_cells_entered(a, b);
  // Block one entered cell in the middle, then a cell right beside the segment.
  auto it = entered.begin();
  std::advance(it, entered.size() / 2);
  map.set_blocked({it->first, it->second}, true);
  CHECK_FALSE(aco::line_of_sight(map, a, b, false));
  CHECK_FALSE(aco::line_of_sight(map, b, a, true));
  map.set_blocked({it->first, it->second}, false);
  for (int dy = -1; dy <= 1; ++dy) {
    const aco::Cell beside{it->first, it->second + dy};
    if (entered.count({beside.x, beside.y})) continue;
    map.set_blocked(beside, true);
    const bool expected = test::reference_segment_clear(map, a, b, false);
    CHECK(aco::line_of_sight(map, a, b, false) == expected);
    map.set_blocked(beside, false);
  }
  // (594, 441) = 9 * (66, 49): with an even component the segment meets no vertex, so it enters
  // one cell per column and row boundary it crosses.
  CHECK(test::reference_vertex_sides(a, b).empty());
  CHECK(entered.size() == 1 + 594 + 441);
}

// ---------------------------------------------------------------------------------------------
// segment_free: line_of_sight between any two points

namespace {

bool segment_free(const aco::Map& map, double ax, double ay, double bx, double by, bool cc) {
  return aco::segment_free(map, {ax, ay}, {bx, by}, cc);
}

}  // namespace

TEST_CASE("segment_free: grazing a corner, squeezing between two cells, exactly and just beside",
          "[graph][segment_free]") {
  // (-0.25, 0.875) -> (1.25, 0.125) passes exactly through the vertex (0.5, 0.5), from cell (0,1)
  // into cell (1,0); the side cells are (0,0) and (1,1).
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    CHECK(segment_free(test::grid({"...", "...", "..."}), -0.25, 0.875, 1.25, 0.125, cc));
    CHECK(segment_free(test::grid({"...", ".#.", "..."}), -0.25, 0.875, 1.25, 0.125, cc) == cc);  // grazing (1,1)
    CHECK(segment_free(test::grid({"#..", "...", "..."}), 1.25, 0.125, -0.25, 0.875, cc) == cc);  // grazing (0,0)
    CHECK_FALSE(segment_free(test::grid({"#..", ".#.", "..."}), -0.25, 0.875, 1.25, 0.125, cc));  // squeezing
    CHECK(segment_free(test::grid({"..#", "...", "..."}), -0.25, 0.875, 1.25, 0.125, cc));  // not touched
    // A hair above the vertex the segment crosses the corner of (1,1); a hair below, of (0,0).
    const double hair = 1e-12;
    const auto center_blocked = test::grid({"...", ".#.", "..."});
    CHECK_FALSE(segment_free(center_blocked, -0.25, 0.875 + hair, 1.25, 0.125 + hair, cc));
    CHECK(segment_free(center_blocked, -0.25, 0.875 - hair, 1.25, 0.125 - hair, cc));
    const auto corner_blocked = test::grid({"#..", "...", "..."});
    CHECK(segment_free(corner_blocked, -0.25, 0.875 + hair, 1.25, 0.125 + hair, cc));
    CHECK_FALSE(segment_free(corner_blocked, -0.25, 0.875 - hair, 1.25, 0.125 - hair, cc));
    // The smallest step off the vertex decides too: the vertex lies 1 ulp off the line.
    const double up = std::nextafter(0.125, 1.0);
    CHECK_FALSE(segment_free(center_blocked, -0.25, 0.875, 1.25, up, cc));
    CHECK(segment_free(corner_blocked, -0.25, 0.875, 1.25, up, cc));
  }
}

TEST_CASE("segment_free: along grid lines, ends on borders, points", "[graph][segment_free]") {
  for (bool cc : {false, true}) {
    INFO("corner cutting " << cc);
    // y = 0.5, between rows 0 and 1, from x = 0 to x = 3.
    CHECK(segment_free(test::grid({"....", "....", "...."}), 0, 0.5, 3, 0.5, cc));
    CHECK(segment_free(test::grid({".#..", "....", "...."}), 0, 0.5, 3, 0.5, cc) == cc);  // along one wall
    CHECK(segment_free(test::grid({"....", "..#.", "...."}), 3, 0.5, 0, 0.5, cc) == cc);
    CHECK_FALSE(segment_free(test::grid({".#..", ".#..", "...."}), 0, 0.5, 3, 0.5, cc));  // between two
    // Through the vertex (1.5, 0.5) between the blocked (1,0) and (2,1): squeezing.
    CHECK_FALSE(segment_free(test::grid({".#..", "..#.", "...."}), 0, 0.5, 3, 0.5, cc));
    // ... but ending at that vertex is only touching.
    CHECK(segment_free(test::grid({".#..", "..#.", "...."}), 0, 1, 1.5, 0.5, cc) == cc);
    // The same along a column: x = 1.5 between columns 1 and 2.
    CHECK(segment_free(test::grid({"....", "..#.", "...."}), 1.5, 0, 1.5, 2, cc) == cc);
    CHECK_FALSE(segment_free(test::grid({"....", ".##.", "...."}), 1.5, 2, 1.5, 0, cc));
    CHECK(segment_free(test::grid({"....", ".##.", "...."}), 1.5, 2, 1.5, 1.5, cc) == cc);  // stops at the wall
    // Along the map's own border: the outside is blocked.
    CHECK(segment_free(test::grid({"...", "..."}), -0.5, 0, -0.5, 1, cc) == cc);
    CHECK(segment_free(test::grid({"...", "..."}), 0, 1.5, 2, 1.5, cc) == cc);
    CHECK_FALSE(segment_free(test::grid({"...", "..."}), -0.5001, 0, 1, 0, cc));
    CHECK_FALSE(segment_free(test::grid({"...", "..."}), 0, 0, 0, 1.6, cc));
    // An end on a cell's edge touches the cell behind it.
    CHECK(segment_free(test::grid({"#..", "..."}), 0.5, 0, 2, 0.25, cc) == cc);
    CHECK_FALSE(segment_free(test::grid({"#..", "..."}), 0.25, 0, 2, 0.25, cc));
    // Points: inside a cell, on an edge, on a vertex.
    const auto map = test::grid({"#..", "...", "..#"});
    CHECK(segment_free(map, 1, 1, 1, 1, cc));
    CHECK_FALSE(segment_free(map, 0, 0, 0, 0, cc));
    CHECK(segment_free(map, 0.5, 0, 0.5, 0, cc) == cc);
    CHECK(segment_free(map, 0.5, 0.5, 0.5, 0.5, cc) == cc);
    CHECK(segment_free(map, 1.5, 1.5, 1.5, 1.5, cc) == cc);
    CHECK(segment_free(map, 1, 0.5, 1, 0.5, cc));
    // Not finite.
    CHECK_FALSE(segment_free(map, std::nan(""), 1, 1, 1, cc));
    CHECK_FALSE(segment_free(map, 1, 1, 1, INFINITY, cc));
  }
}

TEST_CASE("segment_free on random points: symmetric, and no sample on it in a blocked cell", "[graph][segment_free]") {
  // The reference here is one-sided: a point of the segment strictly inside a blocked cell refuses
  // it; without corner cutting a free segment has every sample on a passable cell.
  std::mt19937 rng(7);
  int free = 0, refused = 0, failures = 0;
  for (int trial = 0; trial < 100; ++trial) {
    std::uniform_int_distribution<int> size(2, 12);
    const int w = size(rng), h = size(rng);
    const aco::OccupancyGrid map = test::random_grid(rng, w, h);
    std::uniform_real_distribution<double> px(-0.5, w - 0.5), py(-0.5, h - 0.5);
    for (int pair = 0; pair < 50; ++pair) {
      const Eigen::Vector2d a(px(rng), py(rng)), b(px(rng), py(rng));
      const bool strict = aco::segment_free(map, a, b, false), cutting = aco::segment_free(map, a, b, true);
      bool sample_blocked = false;
      for (int k = 0; k <= 400; ++k) {
        const Eigen::Vector2d p = a + (b - a) * (k / 400.0);
        const aco::Cell c{static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
        const bool on_border =
            std::abs(std::abs(p.x() - c.x) - 0.5) < 1e-9 || std::abs(std::abs(p.y() - c.y) - 0.5) < 1e-9;
        if (!on_border && !map.passable(c)) sample_blocked = true;
      }
      const bool ok = strict == aco::segment_free(map, b, a, false) && cutting == aco::segment_free(map, b, a, true) &&
                      (!strict || cutting) && !(sample_blocked && cutting);
      if (!ok) {
        INFO(w << "x" << h << " map, (" << a.x() << ", " << a.y() << ") -> (" << b.x() << ", " << b.y() << ")");
        CHECK(ok);
        ++failures;
      }
      (cutting ? free : refused) += 1;
    }
  }
  CHECK(failures == 0);
  CHECK(free > 500);
  CHECK(refused > 1000);
}

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
