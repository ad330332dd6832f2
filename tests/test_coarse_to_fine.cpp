// Coarse to fine (ColonySettings::coarse_to_fine) and the closed nodes it hands the colony on the
// map itself (ColonySettings::closed, dead_ends() and reachable() within them).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdlib>
#include <memory>
#include <random>

#include "aco/engine/coarse_to_fine.hpp"
#include "aco/engine/dead_ends.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/plan_request.hpp"
#include "aco/planning/presets.hpp"
#include "aco/voxel.hpp"
#include "support.hpp"

namespace {

// A map of rooms, `side` cells a side: walls every 32 cells, 4 cells thick, each wall segment
// between two crossings with a door of 8 cells at a random place, and random pillars (2x2) in the
// rooms; the corners (4,4) and (side - 5, side - 5) are free.
aco::OccupancyGrid rooms(int side, std::uint32_t seed) {
  std::mt19937 rng(seed);
  aco::OccupancyGrid map(side, side, "rooms");
  const auto block = [&](int x0, int y0, int w, int h) {
    for (int y = y0; y < std::min(side, y0 + h); ++y)
      for (int x = x0; x < std::min(side, x0 + w); ++x) map.set_blocked({x, y}, true);
  };
  for (int wall = 32; wall < side; wall += 32) {
    block(wall, 0, 4, side);
    block(0, wall, side, 4);
  }
  for (int wall = 32; wall < side; wall += 32)
    for (int from = 0; from < side; from += 32) {
      const int door = from + 4 + static_cast<int>(rng() % 20);
      for (int y = door; y < std::min(side, door + 8); ++y)
        for (int x = wall; x < wall + 4; ++x) map.set_blocked({x, y}, false), map.set_blocked({y, x}, false);
    }
  for (int pillar = 0; pillar < side * side / 400; ++pillar)
    block(static_cast<int>(rng() % side), static_cast<int>(rng() % side), 2, 2);
  for (const aco::Cell corner : {aco::Cell{4, 4}, aco::Cell{side - 5, side - 5}})
    for (int y = corner.y - 2; y <= corner.y + 2; ++y)
      for (int x = corner.x - 2; x <= corner.x + 2; ++x) map.set_blocked({x, y}, false);
  return map;
}

aco::ColonySettings settings(int coarse_to_fine) {
  aco::ColonySettings s;
  s.ants = 20;
  s.iterations = 10;
  s.beta = 3;
  s.q0 = 0.7;
  s.seed = 5;
  s.fill_dead_ends = true;
  s.local_search = aco::LocalSearch::straighten;
  s.walk_limit = 4;
  s.coarse_to_fine = coarse_to_fine;
  return s;
}

aco::ColonyResult plan(const aco::Graph& graph, aco::Cell start, aco::Cell goal, const aco::ColonySettings& s) {
  const aco::PipelineSpec spec =
      test::pipeline({{"heuristic", "progress"}, {"update", "max_min"}, {"deadlock", "backtrack"}});
  const auto pipeline = aco::instantiate(test::plugins(), spec);
  return aco::run_pipeline(test::plugins(), spec, pipeline, graph, graph.node(start), graph.node(goal), s);
}

}  // namespace

TEST_CASE("dead ends and reachability within closed nodes are those of the graph without them",
          "[coarse_to_fine][dead_ends]") {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 200; ++trial) {
    const auto problem = test::random_problem(rng, 4, 12);
    const aco::Graph graph = aco::build_graph(problem.map, {});
    const aco::NodeId start = graph.node(problem.start), goal = graph.node(problem.goal);
    std::vector<std::uint8_t> closed(graph.num_nodes(), 0);
    for (auto& c : closed) c = rng() % 4 == 0;
    closed[start] = closed[goal] = 0;
    const aco::Graph narrowed = aco::subgraph(graph, closed);
    INFO("trial " << trial);
    CHECK(aco::reachable(graph, start, goal, closed) == aco::reachable(narrowed, start, goal));
    CHECK(aco::dead_ends(graph, start, goal, closed) == aco::dead_ends(narrowed, start, goal));
  }
}

TEST_CASE("coarse to fine: the ants walk within one block of the coarse colony's path", "[coarse_to_fine]") {
  const aco::OccupancyGrid map = rooms(1024, 3);
  const aco::Graph graph = aco::build_graph(map, {});
  const aco::Cell start{4, 4}, goal{1019, 1019};
  const aco::ColonyResult run = plan(graph, start, goal, settings(4));
  REQUIRE(run.solved);
  REQUIRE(run.coarse);
  REQUIRE(run.coarse->solved);
  // The ants walked the corridor's graph, whose edges the pheromone is per edge of.
  REQUIRE(run.walked_coarse_corridor);
  // The coarse map is 256x256 blocks: too small to be coarsened again, so its path is in its cells.
  const int coarse_side = 256;
  for (const aco::NodeId n : run.coarse->path) CHECK(n < coarse_side * coarse_side);
  const auto in_corridor = [&](aco::NodeId n) {
    const aco::Cell c = graph.cell(n);
    return std::any_of(run.coarse->path.begin(), run.coarse->path.end(), [&](aco::NodeId b) {
      return std::abs(b % coarse_side - c.x / 4) <= 1 && std::abs(b / coarse_side - c.y / 4) <= 1;
    });
  };
  for (const aco::NodeId n : run.path) {
    INFO("cell " << aco::to_string(graph.cell(n)));
    CHECK(in_corridor(n));
  }
  // The pheromone is the corridor's edges' only, each named by its edge in the map's graph.
  CHECK(run.pheromone.size() * 10 < static_cast<std::size_t>(graph.num_edges()));
  REQUIRE(run.pheromone_edges.size() == run.pheromone.size());
  for (std::size_t i = 0; i < run.pheromone_edges.size(); ++i) {
    const aco::EdgeId e = run.pheromone_edges[i];
    REQUIRE(e >= 0);
    REQUIRE(e < graph.num_edges());
    if (i > 0) CHECK(e > run.pheromone_edges[i - 1]);
    if (i % 97 == 0) CHECK((in_corridor(graph.source(e)) && in_corridor(graph.targets[e])));
  }
  CHECK(run.path.front() == graph.node(start));
  CHECK(run.path.back() == graph.node(goal));
  for (std::size_t k = 1; k < run.path.size(); ++k) CHECK(graph.find_edge(run.path[k - 1], run.path[k]) >= 0);
}

TEST_CASE("coarse to fine gives bit-identical runs for any thread count", "[coarse_to_fine][determinism]") {
  const aco::OccupancyGrid map = rooms(1024, 4);
  const aco::Graph graph = aco::build_graph(map, {});
  aco::ColonySettings s = settings(4);
  s.iterations = 4;
  const aco::ColonyResult run = test::run_on_thread_counts(graph, graph.node({4, 4}), graph.node({1019, 1019}), s,
                                                           {"uniform", "progress", "max_min", "backtrack"});
  CHECK(run.solved);
  CHECK(run.walked_coarse_corridor);
}

TEST_CASE("coarse to fine leaves small maps to one level, bit for bit", "[coarse_to_fine]") {
  // 1020 cells a side in blocks of 4: 255 blocks, one short of a coarse level.
  const aco::OccupancyGrid map = rooms(1020, 5);
  const aco::Graph graph = aco::build_graph(map, {});
  aco::ColonySettings s = settings(4);
  s.iterations = 3;
  const aco::ColonyResult coarse = plan(graph, {4, 4}, {1015, 1015}, s);
  s.coarse_to_fine = 0;
  const aco::ColonyResult one_level = plan(graph, {4, 4}, {1015, 1015}, s);
  CHECK_FALSE(coarse.coarse);
  CHECK_FALSE(coarse.walked_coarse_corridor);
  test::check_same_run(coarse, one_level);
}

TEST_CASE("coarse to fine plans on the whole map where the blocks close the only door", "[coarse_to_fine]") {
  // A wall across the map with one door of a single cell: every block on the wall is closed.
  aco::OccupancyGrid map(1024, 1024, "one door");
  for (int y = 0; y < 1024; ++y)
    if (y != 700) map.set_blocked({512, y}, true);
  const aco::Graph graph = aco::build_graph(map, {});
  aco::ColonySettings s = settings(4);
  s.iterations = 3;
  const aco::ColonyResult run = plan(graph, {10, 10}, {1000, 1000}, s);
  CHECK(run.solved);
  CHECK_FALSE(run.coarse);
  CHECK_FALSE(run.walked_coarse_corridor);
}

TEST_CASE("the coarse colony is the colony with the same settings on the map in blocks, explorers its own",
          "[coarse_to_fine]") {
  const aco::OccupancyGrid map = rooms(1024, 6);
  const aco::Graph graph = aco::build_graph(map, {});
  const aco::Cell start{4, 4}, goal{1019, 1019};
  aco::ColonySettings s = settings(4);
  s.iterations = 4;
  s.coarse_explorers = 0.2;
  const aco::ColonyResult run = plan(graph, start, goal, s);
  REQUIRE(run.coarse);
  // The rule stated anew: a block is free where its 16 cells are, the start's and the goal's always.
  aco::OccupancyGrid blocks(256, 256, "blocks");
  for (int by = 0; by < 256; ++by)
    for (int bx = 0; bx < 256; ++bx)
      for (int k = 0; k < 16; ++k)
        if (!map.passable({4 * bx + k % 4, 4 * by + k / 4})) blocks.set_blocked({bx, by}, true);
  blocks.set_blocked({start.x / 4, start.y / 4}, false);
  blocks.set_blocked({goal.x / 4, goal.y / 4}, false);
  aco::ColonySettings level = s;
  level.coarse_to_fine = 0;
  level.explorers = 0.2;
  const aco::Graph coarse_graph = aco::build_graph(blocks, {});
  const aco::ColonyResult alone = plan(coarse_graph, {start.x / 4, start.y / 4}, {goal.x / 4, goal.y / 4}, level);
  CHECK(run.coarse->path == alone.path);
  CHECK(run.coarse->length == alone.length);
  CHECK(run.coarse->iteration_best == alone.iteration_best);
  CHECK(run.coarse->ant_steps == alone.ant_steps);
  // Without coarse explorers the coarse colony walks otherwise.
  s.coarse_explorers = 0.0;
  CHECK(plan(graph, start, goal, s).coarse->ant_steps != run.coarse->ant_steps);
}

namespace {

// A voxel world of 2^22 voxels (512x512x16), the least that is planned coarse to fine
// (aco::kCoarseWorldVoxels): a hall 64 voxels deep (y < 64), the rest solid, cut in two at x = 256
// by a wall with one door (y 20-27, z 4-11).
std::shared_ptr<aco::VoxelMap> hall_with_door(int depth = 16) {
  auto world = std::make_shared<aco::VoxelMap>(512, 512, depth, "hall");
  for (int z = 0; z < depth; ++z)
    for (int y = 0; y < 512; ++y)
      for (int x = 0; x < 512; ++x) {
        const bool door = y >= 20 && y < 28 && z >= 4 && z < 12;
        world->set_blocked({x, y, z}, y >= 64 || (x == 256 && !door));
      }
  return world;
}

aco::PlannedRuns plan_in(std::shared_ptr<const aco::Map> world, const aco::Keys& changes, int threads = 2) {
  const aco::KeySpelling spelling = "--";
  const auto source = aco::PipelineSource::choose("", "", aco::MapKind::voxel, spelling);
  aco::KeyedValues keys;
  keys.keys = {{"ants", "10"}, {"iterations", "5"}};
  for (const auto& [key, value] : changes) keys.keys.insert_or_assign(key, value);
  aco::PlanRequest request;
  request.run = aco::resolve_run(aco::over_pipeline_file(source.keys(), keys).keys, test::plugins(), spelling);
  request.run.problem.start = aco::Cell{10, 10, 2};
  request.run.problem.goal = aco::Cell{500, 50, 12};
  request.map = std::move(world);
  request.threads = threads;
  return aco::plan(request, test::plugins());
}

}  // namespace

TEST_CASE("a voxel world of millions of voxels is planned in the coarse colony's corridor", "[coarse_to_fine][voxel]") {
  const auto world = hall_with_door();
  const aco::PlannedRuns planned = plan_in(world, {});
  REQUIRE(planned.runs.size() == 1);
  const aco::PlanRun& run = planned.runs.front();
  REQUIRE(run.solved());
  CHECK(run.text("coarse.corridor") == "walked");
  CHECK(std::get<double>(run.properties.at("coarse.length")) > 0);
  // The graph is the corridor's: not the hall's 524288 voxels' edges, and A*'s optimum on it is not
  // the world's, so none is given.
  CHECK(planned.graph.num_edges() < 524288 * 26 / 4);
  CHECK_FALSE(run.optimal_length);
  // The path: free voxels, each step one of the 26 moves, through the door.
  const std::vector<aco::NodeId>& path = run.search.path;
  REQUIRE(path.size() >= 2);
  CHECK(path.front() == planned.graph.node({10, 10, 2}));
  CHECK(path.back() == planned.graph.node({500, 50, 12}));
  bool through_door = false;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const aco::Cell c = planned.graph.cell(path[i]);
    CHECK(world->passable(c));
    if (c.x == 256) through_door = c.y >= 20 && c.y < 28 && c.z >= 4 && c.z < 12;
    if (i == 0) continue;
    const aco::Cell b = planned.graph.cell(path[i - 1]);
    CHECK(std::max({std::abs(c.x - b.x), std::abs(c.y - b.y), std::abs(c.z - b.z)}) == 1);
  }
  CHECK(through_door);
  // The same run with one thread.
  CHECK(plan_in(world, {}, 1).runs.front().search.path == path);
}

TEST_CASE("a voxel world's coarse colony out of time leaves the run unsolved, with the reason",
          "[coarse_to_fine][voxel]") {
  const aco::PlannedRuns planned = plan_in(hall_with_door(), {{"time-limit", "0.000001"}});
  const aco::PlanRun& run = planned.runs.front();
  CHECK_FALSE(run.solved());
  CHECK_THAT(run.reason, Catch::Contains("ran out before the colony on the world in blocks of 2 voxels a side"));
  CHECK(run.text("coarse.corridor") == "not used");
}

TEST_CASE("a voxel world's coarse colony that finds no path with no time limit leaves the whole world",
          "[coarse_to_fine][voxel]") {
  // One ant that dies in its first dead end (no back-off), led by nothing: the coarse colony ends
  // without a path, and the world is planned on its whole graph, not refused for a time limit.
  const aco::PlannedRuns planned =
      plan_in(hall_with_door(),
              {{"deadlock", "discard"}, {"ants", "1"}, {"iterations", "1"}, {"heuristic", "distance"}, {"beta", "0"}});
  const aco::PlanRun& run = planned.runs.front();
  CHECK_FALSE(run.properties.count("coarse.corridor"));
  CHECK(run.optimal_length);  // A* on the whole graph
  CHECK_THAT(run.reason, !Catch::Contains("time limit"));
  CHECK(planned.graph.num_edges() > 524288 * 13);  // the hall's, not a corridor's
}

TEST_CASE("a smaller voxel world, or coarse-to-fine 0, is planned on its whole graph", "[coarse_to_fine][voxel]") {
  const auto check_whole = [](const aco::PlannedRuns& planned) {
    const aco::PlanRun& run = planned.runs.front();
    REQUIRE(run.solved());
    CHECK_FALSE(run.properties.count("coarse.corridor"));
    CHECK(run.optimal_length);
  };
  check_whole(plan_in(hall_with_door(15), {}));
  check_whole(plan_in(hall_with_door(), {{"coarse-to-fine", "0"}}));
}

TEST_CASE("a voxel world's coarse map: blocks of 2x2x2, free where all their voxels are", "[coarse_to_fine][voxel]") {
  aco::VoxelMap world(6, 4, 5, "w");
  world.set_blocked({3, 0, 0}, true);  // block (1,0,0)
  world.set_blocked({5, 3, 4}, true);  // block (2,1,2): the goal's, free whatever its voxels
  const auto coarse = aco::coarse_map(world, {0, 0, 0}, {4, 2, 4}, 2, 0);
  REQUIRE(coarse);
  REQUIRE(coarse->map->volumetric());
  CHECK(coarse->map->width() == 3);
  CHECK(coarse->map->height() == 2);
  CHECK(coarse->map->depth() == 3);
  CHECK(coarse->start == aco::Cell{0, 0, 0});
  CHECK(coarse->goal == aco::Cell{2, 1, 2});
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) CHECK(coarse->map->passable({x, y, z}) == (aco::Cell{x, y, z} != aco::Cell{1, 0, 0}));
  // Opened one deep around the start, the blocked block is free too.
  CHECK(aco::coarse_map(world, {0, 0, 0}, {4, 2, 4}, 2, 1)->map->passable({1, 0, 0}));
  // Start and goal in one block: no coarse level.
  CHECK_FALSE(aco::coarse_map(world, {0, 0, 0}, {1, 1, 1}, 2, 0));
  // The corridor: voxels within `radius` blocks of the path's blocks.
  const aco::Graph blocks = aco::build_graph(*coarse->map, {aco::Neighbourhood::twenty_six, false});
  const std::vector<aco::NodeId> path{blocks.node({0, 0, 0})};
  const auto near = aco::coarse_corridor(world, blocks, path, 2, 1);
  const auto wider = aco::coarse_corridor(world, blocks, path, 2, 2);
  for (int z = 0; z < 5; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 6; ++x) {
        const std::size_t voxel = (static_cast<std::size_t>(z) * 4 + y) * 6 + x;
        CHECK(near[voxel] == (x < 4 && z < 4 ? 0 : 1));
        CHECK(wider[voxel] == 0);
      }
}
