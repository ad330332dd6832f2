// Voxel worlds: the 6-, 18- and 26-neighbourhoods, the 3D corner rule, 3D line of sight, exact
// optima, and the colony with the plugins that declare they plan in 3D.
#include <catch2/catch.hpp>

#include <cmath>
#include <queue>
#include <random>
#include <set>
#include <tuple>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "aco/astar.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/planning.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/voxel.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

aco::Graph build(const aco::Map& map, aco::Neighbourhood n, bool corner_cutting = false) {
  return aco::build_graph(map, {n, corner_cutting});
}

// A world with every voxel blocked with probability `density` (fixed seed).
aco::VoxelMap random_world(int w, int h, int d, double density, unsigned seed) {
  aco::VoxelMap map(w, h, d, "random");
  std::mt19937 rng(seed);
  std::bernoulli_distribution blocked(density);
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) map.set_blocked({x, y, z}, blocked(rng));
  return map;
}

}  // namespace

TEST_CASE("a voxel world's graph has the 6, 18 and 26 moves, with costs and reverse edges by move", "[voxel][graph]") {
  const aco::VoxelMap open(3, 3, 3, "open");
  for (auto [n, expected] : {std::pair{aco::Neighbourhood::six, 6}, std::pair{aco::Neighbourhood::eighteen, 18},
                             std::pair{aco::Neighbourhood::twenty_six, 26}}) {
    const aco::Graph g = build(open, n);
    INFO(aco::describe(g.options));
    CHECK(g.volumetric);
    CHECK(g.num_nodes() == 27);
    CHECK(g.terrain_costs.empty());  // the lean graph stores none
    CHECK(g.degree(g.node({1, 1, 1})) == expected);
    std::set<std::tuple<int, int, int>> seen;
    for (aco::NodeId a = 0; a < g.num_nodes(); ++a)
      for (aco::EdgeId e = g.edges_begin(a); e < g.edges_end(a); ++e) {
        const aco::NodeId b = g.targets[e];
        CHECK(g.cost(e) == Approx(g.distance(a, b)));
        CHECK(g.targets[g.reverse_edge(e)] == a);
        CHECK(g.source(e) == a);
        CHECK(g.find_edge(a, b) == e);
        const aco::Cell ca = g.cell(a), cb = g.cell(b);
        CHECK(g.node(ca) == a);
        seen.insert({cb.x - ca.x, cb.y - ca.y, cb.z - ca.z});
      }
    CHECK(static_cast<int>(seen.size()) == expected);
  }
}

TEST_CASE("without corner cutting a 3D move needs every voxel of its box free, as the voxel benchmarks say",
          "[voxel][graph]") {
  const aco::VoxelMap world = random_world(6, 5, 4, 0.3, 7);
  for (bool corner_cutting : {false, true}) {
    const aco::Graph g = build(world, aco::Neighbourhood::twenty_six, corner_cutting);
    for (int z = 0; z < 4; ++z)
      for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 6; ++x)
          for (const aco::Move& m : aco::moves(aco::Neighbourhood::twenty_six)) {
            const aco::Cell a{x, y, z};
            INFO(aco::to_string(a) << " + (" << m.dx << "," << m.dy << "," << m.dz << "), corner cutting "
                                   << corner_cutting);
            CHECK((g.edge_by_move(g.node(a), m.dx, m.dy, m.dz) >= 0) ==
                  test::reference_voxel_move(world, a, m.dx, m.dy, m.dz, corner_cutting));
          }
  }
}

TEST_CASE("a voxel world takes the 3D neighbourhoods and a 2D map the 2D ones", "[voxel][graph]") {
  const aco::VoxelMap world(4, 4, 4, "cube");
  CHECK_THROWS_WITH(build(world, aco::Neighbourhood::eight),
                    Contains("cube is a voxel world: it takes the 6-, 18- or 26-neighbourhood"));
  const auto grid = test::grid({"....", "...."});
  CHECK_THROWS_WITH(build(grid, aco::Neighbourhood::twenty_six), Contains("the 26-neighbourhood is for voxel worlds"));
  CHECK_THROWS_WITH(aco::VoxelMap(4, 0, 2, "flat"), Contains("flat: voxel world size 4x0x2 is empty"));
}

TEST_CASE("3D A* finds the exact optimum of every neighbourhood", "[voxel][astar]") {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    aco::VoxelMap world = random_world(9, 8, 7, 0.25, seed);
    const aco::Cell start{0, 0, 0}, goal{8, 7, 6};
    world.set_blocked(start, false);
    world.set_blocked(goal, false);
    for (int n : {6, 18, 26}) {
      const aco::Graph g = build(world, static_cast<aco::Neighbourhood>(n));
      const auto expected = test::reference_voxel_distance(world, start, goal, n);
      const auto found = aco::astar(g, g.node(start), g.node(goal));
      INFO("seed " << seed << ", " << n << "-neighbourhood");
      REQUIRE(found.has_value() == expected.has_value());
      if (found) {
        CHECK(found->length == Approx(*expected).epsilon(1e-12));
        CHECK(aco::path_length(g, found->nodes) == Approx(found->length));
      }
    }
  }
}

TEST_CASE("3D line of sight enters no blocked voxel and obeys the box rule where it passes an edge or a corner",
          "[voxel][graph]") {
  aco::VoxelMap world(5, 5, 5, "sight");
  CHECK(aco::line_of_sight(world, {0, 0, 0}, {4, 3, 2}, false));
  world.set_blocked({2, 2, 2}, true);
  CHECK_FALSE(aco::line_of_sight(world, {0, 0, 0}, {4, 4, 4}, false));  // through the blocked centre
  CHECK_FALSE(aco::line_of_sight(world, {2, 2, 0}, {2, 2, 4}, true));
  CHECK(aco::line_of_sight(world, {0, 0, 0}, {4, 0, 0}, false));
  // Through the edge between (2,2,1) and (3,3,1): the box's other voxels must be free.
  aco::VoxelMap edge(5, 5, 3, "edge");
  edge.set_blocked({3, 2, 1}, true);
  CHECK_FALSE(aco::line_of_sight(edge, {1, 1, 1}, {4, 4, 1}, false));
  CHECK(aco::line_of_sight(edge, {1, 1, 1}, {4, 4, 1}, true));  // one side free: corner cutting grazes
  edge.set_blocked({2, 3, 1}, true);
  CHECK_FALSE(aco::line_of_sight(edge, {1, 1, 1}, {4, 4, 1}, true));  // both sides: no squeezing through
  // Sampled check on random worlds: a segment said clear has every sample in a free voxel.
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const aco::VoxelMap w = random_world(7, 7, 7, 0.15, seed);
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> coord(0, 6);
    for (int k = 0; k < 300; ++k) {
      const aco::Cell a{coord(rng), coord(rng), coord(rng)}, b{coord(rng), coord(rng), coord(rng)};
      if (!aco::line_of_sight(w, a, b, false)) continue;
      for (int s = 0; s <= 1000; ++s) {
        const double t = s / 1000.0;
        const double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y), z = a.z + t * (b.z - a.z);
        const aco::Cell c{int(std::lround(x)), int(std::lround(y)), int(std::lround(z))};
        INFO(aco::to_string(a) << " -> " << aco::to_string(b) << " at t = " << t);
        REQUIRE(w.passable(c));
      }
    }
  }
}

TEST_CASE("the colony plans in a voxel world with every plugin that says it can", "[voxel][colony]") {
  aco::VoxelMap world(12, 10, 8, "pillars");
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 10; ++y)
      if (y != 4) world.set_blocked({6, y, z}, true);  // a wall with a slot and open above
  const aco::Cell start{1, 1, 0}, goal{10, 8, 1};
  const aco::Graph g = build(world, aco::Neighbourhood::twenty_six);
  const double optimum = aco::astar(g, g.node(start), g.node(goal))->length;
  const std::vector<std::vector<std::pair<std::string, std::string>>> pipelines{
      {{"init", "uniform"}, {"heuristic", "distance"}, {"update", "ant_system"}, {"deadlock", "discard"}},
      {{"init", "potential_field"}, {"heuristic", "potential_field"}, {"update", "elite"}, {"deadlock", "backtrack"}},
      {{"init", "obstacle_density"},
       {"heuristic", "direction"},
       {"update", "gaussian"},
       {"deadlock", "clear_and_tabu"}},
      {{"init", "uniform"}, {"heuristic", "adaptive"}, {"update", "wolf_pack"}, {"deadlock", "backtrack_penalty"}},
      {{"init", "uniform"}, {"heuristic", "progress"}, {"update", "max_min"}, {"deadlock", "backtrack"}},
      {{"init", "uniform"}, {"heuristic", "distance"}, {"update", "acs"}, {"deadlock", "backtrack"}},
      {{"init", "uniform"}, {"heuristic", "distance"}, {"update", "population"}, {"deadlock", "backtrack"}},
  };
  for (const auto& choice : pipelines) {
    aco::Keys keys(choice.begin(), choice.end());
    keys["smoother"] = "prune";
    const auto spec = test::pipeline(keys);
    const auto p = aco::instantiate(test::plugins(), spec);
    aco::ColonySettings s;
    s.ants = 20;
    s.iterations = 15;
    for (bool bidirectional : {false, true}) {
      s.bidirectional = bidirectional;
      const auto r = aco::run_pipeline(test::plugins(), spec, p, g, g.node(start), g.node(goal), s);
      INFO(choice[0].second << " " << choice[1].second << " " << choice[2].second << " " << choice[3].second
                            << (bidirectional ? ", bidirectional" : ""));
      REQUIRE(r.solved);
      CHECK(aco::path_length(g, r.path) == Approx(r.length));
      CHECK(r.length >= optimum - 1e-9);
      auto context = test::context(g, start, goal);
      const aco::Waypoints smoothed = p.smoother->smooth(context, r.path);
      CHECK(aco::waypoint_problem(g, g.node(start), g.node(goal), smoothed).empty());
      CHECK(aco::polyline_length(smoothed) <= r.length + 1e-9);
      for (std::size_t i = 1; i < smoothed.size(); ++i) {
        const auto cell = [](const Eigen::Vector3d& v) { return aco::Cell{int(v.x()), int(v.y()), int(v.z())}; };
        CHECK(aco::line_of_sight(world, cell(smoothed[i - 1]), cell(smoothed[i]), false));
      }
    }
  }
}

TEST_CASE("plan() refuses a planner or plugin that does not plan in 3D, naming it", "[voxel][planning]") {
  aco::VoxelMap world(6, 6, 4, "box.3dmap");
  const aco::Graph g = build(world, aco::Neighbourhood::twenty_six);
  aco::Keys keys{{"smoother", "taut"}};
  auto run = aco::resolve_run(keys, test::plugins());
  CHECK_THROWS_WITH(aco::plan(test::plugins(), g, g.node({0, 0, 0}), g.node({5, 5, 3}), run),
                    Contains("smoother/taut") && Contains("does not plan in 3D; box.3dmap is a voxel world"));
  run = aco::resolve_run({{"planner", "pso"}}, test::plugins());
  CHECK_THROWS_WITH(aco::plan(test::plugins(), g, g.node({0, 0, 0}), g.node({5, 5, 3}), run),
                    Contains("planner 'pso' plans on 2D maps only; box.3dmap is a voxel world"));
  run = aco::resolve_run({{"planner", "astar"}}, test::plugins());
  const auto outcome = aco::plan(test::plugins(), g, g.node({0, 0, 0}), g.node({5, 5, 3}), run);
  CHECK(outcome.solved());
  CHECK(outcome.length == Approx(std::sqrt(3.0) * 3 + std::sqrt(2.0) * 2));
}

TEST_CASE("cells parse as X,Y or X,Y,Z and name their layer in a voxel world", "[voxel][keys]") {
  CHECK(aco::parse_cell("3,4,5", "start") == aco::Cell{3, 4, 5});
  CHECK(aco::parse_cell("3,4", "start") == aco::Cell{3, 4, 0});
  CHECK_THROWS_WITH(aco::parse_cell("3,4,5,6", "goal"), Contains("expected X,Y such as 3,7 (X,Y,Z in a voxel world)"));
  CHECK_THROWS_WITH(aco::parse_cell("3,,5", "goal"), Contains("is not a cell"));
  const aco::VoxelMap world(4, 4, 4, "w");
  CHECK(world.describe({1, 2, 0}) == "(1,2,0)");
  CHECK(aco::to_string(aco::Cell{1, 2, 3}) == "(1,2,3)");
  CHECK(aco::to_string(aco::Cell{1, 2}) == "(1,2)");
}

namespace {

// A small voxel world on disk: a 12x10x8 block with a wall that has a slot and is open above.
std::filesystem::path wall_world_file() {
  aco::VoxelMap world(12, 10, 8, "wall");
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 10; ++y)
      if (y != 4) world.set_blocked({6, y, z}, true);
  std::ostringstream text;
  aco::write_movingai_voxels(world, text);
  return test::temp_file("wall.3dmap", text.str());
}

}  // namespace

TEST_CASE("acoplan plans in a voxel world: the voxel preset, X,Y,Z cells, paths with z", "[voxel][acoplan]") {
  const auto file = wall_world_file();
  const auto r = test::acoplan(
      {"--map", file.string(), "--start", "1,1,0", "--goal", "10,8,1", "--ants", "20", "--iterations", "20", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["depth"] == 8);
  CHECK(j["start"] == nlohmann::json::array({1, 1, 0}));
  CHECK(j["goal"] == nlohmann::json::array({10, 8, 1}));
  CHECK(j["config"]["neighbourhood"] == "26");  // the voxel preset
  CHECK(j["config"]["smoother"] == "prune");
  REQUIRE(j["solved"] == true);
  CHECK(j["path"].front() == nlohmann::json::array({1.0, 1.0, 0.0}));
  CHECK(j["path"].back() == nlohmann::json::array({10.0, 8.0, 1.0}));
  for (const auto& cell : j["grid_path"]) CHECK(cell.size() == 3);
  CHECK(j["optimal_length"].get<double>() <= j["grid_length"].get<double>() + 1e-9);
  CHECK(j["any_angle_length"].is_null());  // the exact any-angle optimum is the plane's

  const auto summary =
      test::acoplan({"--map", file.string(), "--start", "1,1,0", "--goal", "10,8,1", "--iterations", "5"});
  CHECK_THAT(summary.out, Contains("(12x10x8 voxels), 26-neighbourhood") && Contains("the default for voxel worlds"));
}

TEST_CASE("acoplan refuses what does not fit a voxel world, with messages naming it", "[voxel][acoplan]") {
  const auto file = wall_world_file().string();
  const auto fails = [&](std::vector<std::string> extra) {
    std::vector<std::string> args{"--map", file, "--start", "1,1,0", "--goal", "10,8,1", "--iterations", "2"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = test::acoplan(args);
    CHECK(r.exit_code != 0);
    return r.err;
  };
  CHECK_THAT(fails({"--smoother", "taut"}), Contains("smoother/taut") && Contains("does not plan in 3D"));
  CHECK_THAT(fails({"--neighbourhood", "8"}), Contains("it takes the 6-, 18- or 26-neighbourhood"));
  CHECK_THAT(fails({"--planner", "ifwa"}), Contains("planner 'ifwa' plans on 2D maps only"));
  CHECK_THAT(test::acoplan({"--map", file, "--start", "1,1,9", "--goal", "10,8,1"}).err,
             Contains("start (1,1,9) is outside the 12x10x8 voxel world"));
  CHECK_THAT(test::acoplan({"--map", file, "--start", "6,0,0", "--goal", "10,8,1"}).err,
             Contains("start (6,0,0) is blocked"));
  const auto grid = test::acoplan({"--map", (test::data_dir() / "maps/classic20/map1.txt").string(), "--start", "0,0",
                                   "--goal", "19,19", "--iterations", "2", "--html", "/tmp/never.html"});
  CHECK_THAT(grid.err, Contains("--html draws voxel worlds in 3D"));
}

TEST_CASE("acoplan --html and --svg draw a voxel world's run", "[voxel][acoplan][drawing]") {
  const auto file = wall_world_file();
  const auto html = file.parent_path() / "run.html", svg = file.parent_path() / "run.svg";
  const auto r = test::acoplan({"--map", file.string(), "--start", "1,1,0", "--goal", "10,8,1", "--iterations", "10",
                                "--html", html.string(), "--svg", svg.string(), "--svg-pheromone"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::ifstream page(html), picture(svg);
  const std::string page_text((std::istreambuf_iterator<char>(page)), {}),
      svg_text((std::istreambuf_iterator<char>(picture)), {});
  CHECK_THAT(page_text, Contains("<!DOCTYPE html>") && Contains("wall.3dmap"));
  CHECK_THAT(page_text, !Contains("src=\"http") && !Contains("href=\"http"));  // offline: three.js is inside
  CHECK_THAT(svg_text, Contains("<svg") && Contains("polyline"));
}

TEST_CASE("acoplan plans a Moving AI voxel scenario and A* matches its optimal length", "[voxel][acoplan]") {
  const auto scen = test::data_dir() / "maps/voxel/warframe/Simple.3dmap.3dscen";
  const auto scenarios = aco::load_scenarios(scen);
  for (int index : {0, 9999}) {
    const auto r =
        test::acoplan({"--scen", scen.string(), "--scen-index", std::to_string(index), "--planner", "astar", "--json"});
    INFO("scenario " << index << ": " << r.err);
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["grid_length"].get<double>() == Approx(scenarios[index].optimal_length).epsilon(1e-7));
  }
}
