// aco::line_of_sight and aco::segment_free, the segment rules of the smoothers and the any-angle
// search, against independent reference samplers and the graph's moves.
#include <catch2/catch.hpp>

#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "support.hpp"

using test::build;
using test::has_edge;
using test::open_grid;

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
