#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "pso/pso.hpp"
#include "support.hpp"

namespace {

aco::PsoSettings defaults() { return aco::pso_settings(aco::resolve(aco::pso_parameters(), {}, "pso.")); }

std::vector<aco::Cell> cells(const aco::Graph& g, const std::vector<aco::NodeId>& nodes) {
  std::vector<aco::Cell> result;
  for (aco::NodeId n : nodes) result.push_back(g.cell(n));
  return result;
}

}  // namespace

TEST_CASE("pso: a valid graph path from start to goal on an empty, a classic and an obstacle map", "[pso]") {
  const auto empty = test::grid(std::vector<std::string>(12, std::string(15, '.')));
  const auto classic = test::classic_map(1);
  const auto walls = test::grid({
      "..........",
      "..######..",
      "..#.......",
      "..#.#####.",
      "....#.....",
      "#####..#..",
      ".......#..",
      "..######..",
      "..........",
  });
  struct Case {
    const aco::Map* map;
    aco::GraphOptions options;
    aco::Cell start, goal;
  };
  for (const Case& c : {Case{&empty, {aco::Neighbourhood::eight, false}, {0, 11}, {14, 0}},
                        Case{&classic, {aco::Neighbourhood::eight, true}, {0, 0}, {19, 19}},
                        Case{&classic, {aco::Neighbourhood::four, false}, {0, 0}, {19, 19}},
                        Case{&walls, {aco::Neighbourhood::eight, false}, {0, 0}, {9, 8}},
                        Case{&walls, {aco::Neighbourhood::eight, true}, {0, 8}, {9, 0}},
                        Case{&classic, {aco::Neighbourhood::sixteen, false}, {0, 0}, {19, 19}}}) {
    const aco::Graph g = aco::build_graph(*c.map, c.options);
    INFO(c.map->name() << ", " << aco::describe(c.options));
    const auto r = aco::run_pso(g, g.node(c.start), g.node(c.goal), defaults());
    REQUIRE(r.solved);
    CHECK(r.path.front() == g.node(c.start));
    CHECK(r.path.back() == g.node(c.goal));
    for (std::size_t i = 1; i < r.path.size(); ++i) CHECK(g.find_edge(r.path[i - 1], r.path[i]) >= 0);
    CHECK(r.length == aco::path_length(g, r.path));
    CHECK(r.length >= aco::astar(g, g.node(c.start), g.node(c.goal))->length - 1e-9);
    REQUIRE(r.best_so_far.size() == 100u);
    CHECK(r.best_so_far.back() == r.length);
    CHECK(r.best_so_far[r.best_iteration - 1] == r.length);
    CHECK(r.evaluations == 50u * 101u);
    // The walks are the evaluations: the initial swarm counts towards iteration 1.
    test::check_anytime_curves(r, r.evaluations);
    for (std::size_t i = 0; i < r.walks.size(); ++i) CHECK(r.walks[i] == 50u * (i + 2));
  }
  // On an empty map the straight line is a walk of every swarm: the optimum.
  const aco::Graph g = aco::build_graph(empty, {aco::Neighbourhood::eight, false});
  CHECK(aco::run_pso(g, g.node({0, 11}), g.node({14, 0}), defaults()).length ==
        Approx(aco::astar(g, g.node({0, 11}), g.node({14, 0}))->length));
}

TEST_CASE("pso: same seed, same result on 1, 2 and 4 threads", "[pso][determinism]") {
  const auto map = test::classic_map(3);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  aco::PsoSettings s = defaults();
  s.seed = 9;
  std::vector<aco::PlannerResult> results;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (int threads : {1, 2, 4}) {
    tbb::task_arena arena(threads);
    arena.execute([&] { results.push_back(aco::run_pso(g, g.node({0, 0}), g.node({19, 19}), s)); });
  }
  REQUIRE(results[0].solved);
  for (const auto& r : results) {
    CHECK(r.path == results[0].path);
    CHECK(r.length == results[0].length);
    CHECK(r.best_so_far == results[0].best_so_far);
    CHECK(r.walks == results[0].walks);
  }
}

TEST_CASE("pso walks: moves along each leg, sliding along walls, infeasible only when stuck", "[pso]") {
  const auto open = test::grid(std::vector<std::string>(5, std::string(8, '.')));
  const aco::Graph g = aco::build_graph(open, {aco::Neighbourhood::eight, false});
  const std::vector<aco::Cell> legs{{0, 0}, {4, 2}, {4, 4}};
  const auto w = aco::walk_waypoints(g, legs);
  // (0,0) -> (4,2): the cells closest to the line y = x / 2 (ties to the cell nearer the leg's
  // end); then straight down.
  CHECK(cells(g, w.nodes) == std::vector<aco::Cell>{{0, 0}, {1, 1}, {2, 1}, {3, 2}, {4, 2}, {4, 3}, {4, 4}});
  CHECK(w.infeasible == 0);
  CHECK(w.length == Approx(4 + 2 * std::sqrt(2.0)));

  const auto wall = test::grid({
      "....#...",
      "....#...",
      "....#...",
  });
  const aco::Graph gw = aco::build_graph(wall, {aco::Neighbourhood::eight, false});
  const std::vector<aco::Cell> across{{0, 1}, {7, 1}};
  const auto blocked = aco::walk_waypoints(gw, across);
  CHECK(blocked.infeasible == 2);  // into the wall and out of it; the other steps are edges
  CHECK(cells(gw, blocked.nodes).back() == aco::Cell{7, 1});
  CHECK_THROWS_AS(aco::path_length(gw, blocked.nodes), aco::Error);
}

TEST_CASE("pso: no feasible particle is unsolved, bad settings are errors", "[pso]") {
  const auto map = test::grid({"..#..", "..#..", "..#.."});
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::PsoSettings s = defaults();
  s.iterations = 5;
  const auto r = aco::run_pso(g, g.node({0, 0}), g.node({4, 2}), s);
  CHECK_FALSE(r.solved);
  CHECK(r.path.empty());
  CHECK(r.best_iteration == 0);

  const auto table = aco::pso_parameters();
  aco::check_table(table, "pso");
  CHECK_THROWS_WITH(aco::resolve(table, {{"particles", "0"}}, "--pso."), Catch::Contains("--pso.particles"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"c1", "-1"}}, "--pso."), Catch::Contains("--pso.c1"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"wayponts", "3"}}, "--pso."), Catch::Contains("waypoints"));
  s.max_velocity = 0.0;
  CHECK_THROWS_AS(aco::run_pso(g, g.node({0, 0}), g.node({1, 1}), s), aco::Error);
  CHECK_THROWS_WITH(aco::run_pso(g, g.node({2, 0}), g.node({1, 1}), defaults()), Catch::Contains("blocked"));
}

TEST_CASE("acoplan --planner pso on the paper004 map", "[pso][acoplan]") {
  const std::string scen = (test::data_dir() / "terrain/paper004.map.scen").string();
  const auto r = test::acoplan({"--scen", scen, "--planner", "pso", "--pso.iterations", "30", "--seed", "2", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("config").at("planner") == "pso");
  CHECK(j.at("solved").get<bool>());
  CHECK(j.at("iterations") == 30);
  CHECK(j.at("convergence").size() == 30u);
  CHECK(j.at("evaluations") == 50 * 31);
  CHECK(j.at("config").at("pso.particles") == 50);
  CHECK(j.at("grid_length").get<double>() >= j.at("optimal_length").get<double>() - 1e-9);

  const auto summary = test::acoplan({"--scen", scen, "--planner", "pso", "--pso.iterations", "30", "--seed", "2"});
  CHECK_THAT(summary.out, Catch::Contains("planner:  pso") && Catch::Contains("evaluations"));
  const auto bad = test::acoplan({"--scen", scen, "--planner", "pso", "--pso.inertia", "nan"});
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.err, Catch::Contains("--pso.inertia"));
}
