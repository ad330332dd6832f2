// Line-of-sight walks (ColonySettings::walk_length): the colony ranks corridors by their taut length.
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "aco/any_angle.hpp"
#include "aco/engine/colony.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/engine/pipeline.hpp"
#include "support.hpp"

namespace {

// Two corridors about three cells wide from (1, 40) to (81, 40). North: one bend, at (41, 20),
// both legs at slope 1/2: taut 2 sqrt(40^2 + 20^2) = 89.4, but 2 (20 sqrt 2 + 20) = 96.6 on the
// grid, which pays 8% on that slope. South: diagonal, straight, diagonal (bends at (17, 56) and
// (65, 56)), 2 x 16 sqrt 2 + 48 = 93.3 either way, the grid's directions. Shorter on the grid
// the south one, taut the north one.
aco::OccupancyGrid two_corridors() {
  aco::OccupancyGrid map(83, 62, "two corridors");
  const auto near = [](double x, double y, Eigen::Vector2d a, Eigen::Vector2d b) {
    const Eigen::Vector2d p(x, y), ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm() <= 1.0;
  };
  const std::vector<std::vector<Eigen::Vector2d>> corridors = {{{1, 40}, {41, 20}, {81, 40}},
                                                               {{1, 40}, {17, 56}, {65, 56}, {81, 40}}};
  for (int y = 0; y < map.height(); ++y)
    for (int x = 0; x < map.width(); ++x) {
      bool free = false;
      for (const auto& c : corridors)
        for (std::size_t i = 0; i + 1 < c.size(); ++i) free |= near(x, y, c[i], c[i + 1]);
      map.set_blocked({x, y}, !free);
    }
  return map;
}

enum class Corridor { north, south, both };

Corridor corridor_of(const aco::Graph& graph, const std::vector<aco::NodeId>& path) {
  bool north = false, south = false;
  for (aco::NodeId n : path) {
    north |= graph.cell(n).y < 30;
    south |= graph.cell(n).y > 50;
  }
  return north && south ? Corridor::both : north ? Corridor::north : Corridor::south;
}

// The recommended pipeline (data/presets/robust.ini) with `walk_length`, on `threads` threads.
aco::ColonyResult run_robust(const aco::Graph& graph, aco::Cell start, aco::Cell goal, aco::WalkLength walk_length,
                             std::uint64_t seed, int threads, bool bidirectional = false) {
  const aco::RunSpec run =
      aco::resolve_run(aco::read_config_file((test::data_dir() / "presets/robust.ini").string()), test::plugins());
  aco::ColonySettings s = run.colony;
  s.ants = 20;
  s.iterations = 30;
  s.seed = seed;
  s.walk_length = walk_length;
  s.bidirectional = bidirectional;
  const auto pipeline = aco::instantiate(test::plugins(), run.pipeline);
  tbb::task_arena arena(threads);
  aco::ColonyResult result;
  arena.execute([&] {
    result = aco::run_pipeline(test::plugins(), run.pipeline, pipeline, graph, graph.node(start), graph.node(goal), s);
  });
  return result;
}

}  // namespace

TEST_CASE("line-of-sight walks choose the corridor that is shorter taut, grid walks the one shorter on the grid",
          "[colony][any_angle_walks]") {
  const aco::OccupancyGrid map = two_corridors();
  const aco::Graph graph = aco::build_graph(map, {});
  const aco::Cell start{1, 40}, goal{81, 40};
  // The premise, measured: the optimum is north, the octile optimum south.
  const auto taut = aco::any_angle_optimum(map, start, goal);
  REQUIRE(taut);
  CHECK(taut->length < 91.0);
  for (const auto& p : taut->waypoints) CHECK(p.y() < 41.0);
  const auto theta = aco::theta_star(graph, graph.node(start), graph.node(goal));
  REQUIRE(theta);
  CHECK(theta->length < 91.0);
  for (const std::uint64_t seed : {1, 2, 3}) {
    INFO("seed " << seed);
    const auto grid = run_robust(graph, start, goal, aco::WalkLength::grid, seed, 1);
    const auto sight = run_robust(graph, start, goal, aco::WalkLength::line_of_sight, seed, 1);
    REQUIRE(grid.solved);
    REQUIRE(sight.solved);
    CHECK(corridor_of(graph, grid.path) == Corridor::south);
    CHECK(corridor_of(graph, sight.path) == Corridor::north);
    // The grid run's length is its path's sum of steps; the other's is shorter than that sum.
    CHECK(grid.length == Approx(aco::path_length(graph, grid.path)));
    CHECK(sight.length < aco::path_length(graph, sight.path) - 5.0);
    CHECK(sight.length >= taut->length - 1e-9);
  }
}

TEST_CASE("line-of-sight walks give bit-identical results for any thread count", "[colony][any_angle_walks]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {aco::Neighbourhood::sixteen, false});
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (const bool bidirectional : {false, true}) {
    INFO("bidirectional " << bidirectional);
    const auto one = run_robust(graph, {1, 10}, {46, 30}, aco::WalkLength::line_of_sight, 5, 1, bidirectional);
    REQUIRE(one.solved);
    for (const int threads : {2, 4})
      test::check_same_run(
          run_robust(graph, {1, 10}, {46, 30}, aco::WalkLength::line_of_sight, 5, threads, bidirectional), one);
  }
}

TEST_CASE("a sight limit cuts the taut segments: never shorter than without it, never longer than the grid",
          "[colony][any_angle_walks]") {
  const aco::OccupancyGrid map = two_corridors();
  const aco::Graph graph = aco::build_graph(map, {});
  const auto run = [&](int limit) {
    const aco::RunSpec spec =
        aco::resolve_run(aco::read_config_file((test::data_dir() / "presets/robust.ini").string()), test::plugins());
    aco::ColonySettings s = spec.colony;
    s.ants = 1;
    s.iterations = 1;
    s.walk_length = aco::WalkLength::line_of_sight;
    s.sight_limit = limit;
    s.local_search = aco::LocalSearch::none;  // the same walks whatever the limit
    s.band_search = 0;
    const auto pipeline = aco::instantiate(test::plugins(), spec.pipeline);
    return aco::run_pipeline(test::plugins(), spec.pipeline, pipeline, graph, graph.node({1, 40}), graph.node({81, 40}),
                             s);
  };
  const auto unlimited = run(0), limited = run(4);
  REQUIRE(unlimited.solved);
  REQUIRE(limited.solved);
  REQUIRE(unlimited.path == limited.path);
  CHECK(limited.length > unlimited.length);
  CHECK(limited.length <= aco::path_length(graph, limited.path) + 1e-9);
}
