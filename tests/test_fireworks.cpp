#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <tuple>
#include <nlohmann/json.hpp>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "ifwa/fireworks.hpp"
#include "aco/engine/map_io.hpp"
#include "support.hpp"

namespace {

aco::FireworksSettings defaults() {
  return aco::fireworks_settings(aco::resolve(aco::fireworks_parameters(), {}, "ifwa."));
}

// Every step an edge, start to goal, length = the sum of the steps.
void check_path(const aco::Graph& g, const aco::PlannerResult& r, aco::Cell start, aco::Cell goal) {
  REQUIRE(r.solved);
  REQUIRE(r.path.size() >= 2);
  CHECK(r.path.front() == g.node(start));
  CHECK(r.path.back() == g.node(goal));
  CHECK(r.length == aco::path_length(g, r.path));  // throws if a step is not an edge
}

}  // namespace

TEST_CASE("fireworks defaults are paper 004's IFWA set-up", "[fireworks]") {
  const aco::FireworksSettings s = defaults();
  CHECK(s.iterations == 50);
  CHECK(s.fireworks == 15);
  CHECK(s.mutation_sparks == 10);
  CHECK(s.sparks == 5);
  CHECK(s.radius == 3.0);
  CHECK(s.a == 0.3);
  CHECK(s.b == 0.5);
  aco::check_table(aco::fireworks_parameters(), "fireworks");
}

TEST_CASE("fireworks finds a valid start-goal path and its curve tells when", "[fireworks]") {
  const auto map = test::classic_map(1);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::FireworksSettings s = defaults();
  s.iterations = 20;
  const auto r = aco::run_fireworks(g, g.node({0, 0}), g.node({19, 19}), s);
  check_path(g, r, {0, 0}, {19, 19});
  CHECK(r.length >= aco::astar(g, g.node({0, 0}), g.node({19, 19}))->length);
  REQUIRE(r.best_so_far.size() == 20u);
  CHECK(r.iterations == 20);
  for (std::size_t i = 1; i < r.best_so_far.size(); ++i) CHECK(r.best_so_far[i] <= r.best_so_far[i - 1]);
  CHECK(r.best_so_far.back() == r.length);
  REQUIRE(r.best_iteration >= 1);
  CHECK(r.best_so_far[r.best_iteration - 1] == r.length);
  if (r.best_iteration > 1) CHECK(r.best_so_far[r.best_iteration - 2] > r.length);
  // 15 initial fireworks, then per generation 2 or 3 explosion sparks per firework and 10 mutation sparks.
  CHECK(r.evaluations >= 15u + 20u * (15u * 2u + 10u));
  CHECK(r.evaluations <= 15u + 20u * (15u * 3u + 10u));
  // The walks are the evaluations, the initial fireworks counting towards generation 1.
  test::check_anytime_curves(r, r.evaluations);
  CHECK(r.walks[0] >= 15u + 15u * 2u + 10u);
  CHECK(r.walks[0] <= 15u + 15u * 3u + 10u);
  for (std::size_t i = 1; i < r.walks.size(); ++i) {
    CHECK(r.walks[i] - r.walks[i - 1] >= 15u * 2u + 10u);
    CHECK(r.walks[i] - r.walks[i - 1] <= 15u * 3u + 10u);
  }
}

TEST_CASE("fireworks: same seed, same result on 1, 2 and 4 threads, and another seed differs",
          "[fireworks][determinism]") {
  const auto map = test::classic_map(2);
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
  aco::FireworksSettings s = defaults();
  s.iterations = 15;
  s.seed = 5;
  std::vector<aco::PlannerResult> results;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (int threads : {1, 2, 4}) {
    tbb::task_arena arena(threads);
    arena.execute([&] { results.push_back(aco::run_fireworks(g, g.node({0, 0}), g.node({19, 19}), s)); });
  }
  for (const auto& r : results) {
    CHECK(r.path == results[0].path);
    CHECK(r.length == results[0].length);
    CHECK(r.best_so_far == results[0].best_so_far);
    CHECK(r.evaluations == results[0].evaluations);
  }
  check_path(g, results[0], {0, 0}, {19, 19});
  s.seed = 6;
  const auto other = aco::run_fireworks(g, g.node({0, 0}), g.node({19, 19}), s);
  CHECK((other.path != results[0].path || other.best_so_far != results[0].best_so_far));
}

TEST_CASE("explosion counts stay in [round(a m), round(b m)], the fittest firework gets the most", "[fireworks]") {
  const std::vector<double> fitness{40.0, 31.5, 55.2, 31.5, 90.0, 38.0, 47.3};
  for (const auto& [m, a, b] : {std::tuple{5, 0.3, 0.5}, std::tuple{20, 0.1, 0.6}, std::tuple{40, 0.04, 0.8}}) {
    const auto counts = aco::explosion_counts(fitness, m, a, b);
    REQUIRE(counts.size() == fitness.size());
    INFO("m " << m << ", a " << a << ", b " << b);
    for (int c : counts) {
      CHECK(c >= std::lround(a * m));
      CHECK(c <= std::lround(b * m));
    }
    for (std::size_t i = 0; i < fitness.size(); ++i)
      for (std::size_t j = 0; j < fitness.size(); ++j)
        if (fitness[i] < fitness[j]) CHECK(counts[i] >= counts[j]);
  }
  // Paper 004's m = 5, a = 0.3, b = 0.5: two or three sparks, the worst firework two.
  const auto counts = aco::explosion_counts(fitness, 5, 0.3, 0.5);
  CHECK(counts[4] == 2);
  // Unclamped (a = 0, b = 1): eq. 2 by hand for fitness {1, 2, 4}, m = 10: 10 * {3, 2, 0} / 5.
  CHECK(aco::explosion_counts(std::vector<double>{1, 2, 4}, 10, 0.0, 1.0) == std::vector<int>{6, 4, 0});
}

TEST_CASE("explosion amplitudes: the fittest firework barely moves, the worst the most", "[fireworks]") {
  const std::vector<double> fitness{30.0, 35.0, 45.0};
  const auto amplitudes = aco::explosion_amplitudes(fitness, 3.0);
  CHECK(amplitudes[0] == Approx(0.0).margin(1e-9));
  CHECK(amplitudes[1] == Approx(3.0 * 5.0 / 20.0));
  CHECK(amplitudes[2] == Approx(3.0 * 15.0 / 20.0));
}

TEST_CASE("the explosion radius cools geometrically from radius to radius x radius_end", "[fireworks]") {
  aco::FireworksSettings s = defaults();
  CHECK(aco::explosion_radius(s, 0) == Approx(3.0));
  CHECK(aco::explosion_radius(s, s.iterations) == Approx(0.3));
  CHECK(aco::explosion_radius(s, s.iterations / 2) == Approx(3.0 * std::sqrt(0.1)));
  s.radius_end = 1.0;
  CHECK(aco::explosion_radius(s, 17) == Approx(3.0));
}

TEST_CASE("fireworks: an unreachable goal is unsolved, not an error", "[fireworks]") {
  const auto map = test::grid({
      "..#..",
      "..#..",
      "..#..",
  });
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::FireworksSettings s = defaults();
  s.iterations = 3;
  const auto r = aco::run_fireworks(g, g.node({0, 0}), g.node({4, 2}), s);
  CHECK_FALSE(r.solved);
  CHECK(r.path.empty());
  CHECK(r.best_iteration == 0);
  REQUIRE(r.best_so_far.size() == 3u);
  for (double v : r.best_so_far) CHECK(std::isinf(v));
}

TEST_CASE("fireworks: bad settings and endpoints are errors", "[fireworks]") {
  const auto table = aco::fireworks_parameters();
  CHECK_THROWS_WITH(aco::resolve(table, {{"a", "1.5"}}, "--ifwa."), Catch::Contains("--ifwa.a"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"fireworks", "0"}}, "--ifwa."), Catch::Contains("--ifwa.fireworks"));
  CHECK_THROWS_WITH(aco::resolve(table, {{"radus", "2"}}, "--ifwa."), Catch::Contains("radius"));
  CHECK_THROWS_WITH(aco::fireworks_settings(aco::resolve(table, {{"a", "0.6"}}, "--ifwa.")),
                    Catch::Contains("a = 0.6"));
  CHECK_THROWS_WITH(aco::fireworks_settings(aco::resolve(table, {{"weight_min", "2"}}, "--ifwa.")),
                    Catch::Contains("weight_min"));
  const auto map = test::grid({"..#", "...", "..."});
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  CHECK_THROWS_WITH(aco::run_fireworks(g, g.node({2, 0}), g.node({0, 2}), defaults()), Catch::Contains("blocked"));
  aco::FireworksSettings s = defaults();
  s.b = 0.1;
  CHECK_THROWS_AS(aco::run_fireworks(g, g.node({0, 0}), g.node({2, 2}), s), aco::Error);
}

TEST_CASE("acoplan --planner ifwa on the paper004 map", "[fireworks][acoplan]") {
  const std::string scen = (test::data_dir() / "terrain/paper004.map.scen").string();
  const auto r =
      test::acoplan({"--scen", scen, "--planner", "ifwa", "--ifwa.iterations", "10", "--seed", "4", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j.at("config").at("planner") == "ifwa");
  CHECK(j.at("solved").get<bool>());
  CHECK(j.at("iterations") == 10);
  CHECK(j.at("convergence").size() == 10u);
  CHECK(j.at("best_iteration").get<int>() >= 1);
  CHECK(j.at("config").at("ifwa.iterations") == 10);
  CHECK(j.at("config").at("ifwa.radius") == 3.0);
  CHECK(j.at("grid_length").get<double>() >= j.at("optimal_length").get<double>() - 1e-9);
  CHECK(j.at("grid_path").front() == nlohmann::json::array({0, 0}));
  CHECK(j.at("grid_path").back() == nlohmann::json::array({19, 19}));
  // The same run again: bit-identical.
  const auto again =
      test::acoplan({"--scen", scen, "--planner", "ifwa", "--ifwa.iterations", "10", "--seed", "4", "--json"});
  CHECK(nlohmann::json::parse(again.out).at("grid_path") == j.at("grid_path"));

  const auto bad = test::acoplan({"--scen", scen, "--planner", "ifwa", "--ifwa.sprks", "4"});
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.err, Catch::Contains("did you mean '--ifwa.sparks'"));
  const auto out_of_range = test::acoplan({"--scen", scen, "--planner", "ifwa", "--ifwa.b", "2"});
  CHECK(out_of_range.exit_code == 1);
  CHECK_THAT(out_of_range.err, Catch::Contains("--ifwa.b"));
}

TEST_CASE("fireworks on a large map: block weights and the walk limit, still deterministic",
          "[fireworks][large][slow]") {
  // The classic map with max_weights 16: cells share weights in 4 x 4 blocks of 5 x 5 cells.
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  const auto settings = [](const std::map<std::string, std::string>& given) {
    return aco::fireworks_settings(aco::resolve(aco::fireworks_parameters(), given, ""));
  };
  const auto blocks = settings({{"max_weights", "16"}, {"iterations", "10"}});
  const auto a = aco::run_fireworks(graph, 0, graph.node({19, 19}), blocks);
  const auto b = aco::run_fireworks(graph, 0, graph.node({19, 19}), blocks);
  REQUIRE(a.solved);
  CHECK(a.path == b.path);
  CHECK(a.best_so_far == b.best_so_far);
  CHECK(aco::path_length(graph, a.path) == Approx(a.length));
  const auto per_cell = aco::run_fireworks(graph, 0, graph.node({19, 19}), settings({{"iterations", "10"}}));
  CHECK(per_cell.best_so_far != a.best_so_far);
  // The walk limit never cuts a walk on a map of at most 4096 cells...
  const auto unlimited =
      aco::run_fireworks(graph, 0, graph.node({19, 19}), settings({{"iterations", "10"}, {"walk_limit", "0"}}));
  CHECK(unlimited.best_so_far == per_cell.best_so_far);
  // ...but does on a 193x194 map, where walks wander: the search then differs, still valid.
  const auto file = test::data_dir() / "maps/movingai/dao/lak304d.map";
  if (!std::filesystem::exists(file)) {
    WARN("skipped: no Moving AI data at " << file.string());
    return;
  }
  const auto large = aco::load_map(file);
  const aco::Graph big = aco::build_graph(*large, {});
  const aco::NodeId from = big.node({100, 166}), to = big.node({116, 42});
  REQUIRE(aco::reachable(big, from, to));
  const auto cut = aco::run_fireworks(big, from, to, settings({{"iterations", "5"}}));
  const auto uncut = aco::run_fireworks(big, from, to, settings({{"iterations", "5"}, {"walk_limit", "0"}}));
  REQUIRE(cut.solved);
  CHECK(cut.best_so_far != uncut.best_so_far);
  CHECK(aco::path_length(big, cut.path) == Approx(cut.length));
}
