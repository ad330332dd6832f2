// Plugins of different papers compose: every combination runs and gives a valid path.
#include <catch2/catch.hpp>
#include <fstream>

#include "aco/engine/map_io.hpp"
#include "aco/path.hpp"
#include "aco/engine/pipeline.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

struct Combination {
  const char* init;
  const char* heuristic;
  const char* update;
  const char* deadlock;
  const char* smoother;
};

// The final path runs from start to goal; each segment is an edge of the graph or a line of
// sight under the map's corner rule (by the tests' independent checker); smoothing never lengthens the grid path.
void check_result(const aco::Graph& g, aco::NodeId start, aco::NodeId goal, const aco::ColonyResult& r,
                  const aco::Waypoints& path) {
  REQUIRE(r.solved);
  REQUIRE(r.path.front() == start);
  REQUIRE(r.path.back() == goal);
  REQUIRE(aco::path_length(g, r.path) == Approx(r.length));
  REQUIRE(path.front() == g.position(start));
  REQUIRE(path.back() == g.position(goal));
  for (std::size_t i = 1; i < path.size(); ++i) {
    const aco::Cell a{int(path[i - 1].x()), int(path[i - 1].y())}, b{int(path[i].x()), int(path[i].y())};
    const bool edge = g.find_edge(g.node(a), g.node(b)) >= 0;
    INFO("segment " << aco::to_string(a) << " -> " << aco::to_string(b));
    REQUIRE((edge || test::reference_segment_clear(*g.map, a, b, g.options.corner_cutting)));
  }
  REQUIRE(aco::polyline_length(path) <= r.length + 1e-9);
}

}  // namespace

TEST_CASE("plugins of papers 001, 002 and 003 compose in any slot", "[composition]") {
  const std::vector<Combination> combinations{
      {"obstacle_density", "direction", "gaussian", "clear_and_tabu", "prune"},
      {"uniform", "adaptive", "wolf_pack", "backtrack_penalty", "prune"},
      {"obstacle_density", "direction", "max_min", "backtrack_penalty", "none"},
      {"obstacle_density", "adaptive", "acs", "clear_and_tabu", "prune"},
      {"uniform", "direction", "wolf_pack", "discard", "prune"},
      {"obstacle_density", "distance", "gaussian", "backtrack_penalty", "none"},
  };
  const auto classic = test::classic_map(2);
  std::ifstream in(test::data_dir() / "maps/movingai/arena.map");
  const auto arena = aco::read_movingai_map(in, "arena");
  struct Problem {
    const aco::Map* map;
    aco::GraphOptions options;
    aco::Cell start, goal;
  };
  const std::vector<Problem> problems{
      {&classic, {aco::Neighbourhood::eight, true}, {0, 0}, {19, 19}},
      {&classic, {aco::Neighbourhood::sixteen, false}, {0, 0}, {19, 19}},
      {&arena, {aco::Neighbourhood::eight, false}, {3, 3}, {44, 40}},
  };
  for (const auto& problem : problems) {
    const aco::Graph g = aco::build_graph(*problem.map, problem.options);
    for (const auto& combination : combinations) {
      const auto p = aco::instantiate(test::plugins(), test::pipeline({{"init", combination.init},
                                                                       {"heuristic", combination.heuristic},
                                                                       {"update", combination.update},
                                                                       {"deadlock", combination.deadlock},
                                                                       {"smoother", combination.smoother}}));
      aco::ColonySettings s;
      s.iterations = 40;
      const aco::NodeId start = g.node(problem.start), goal = g.node(problem.goal);
      const auto r = aco::run_colony(g, start, goal, p.strategies(), s);
      auto context = test::context(g, problem.start, problem.goal);
      INFO(combination.init << " " << combination.heuristic << " " << combination.update << " " << combination.deadlock
                            << " " << combination.smoother << " on " << problem.map->name() << ", "
                            << aco::describe(problem.options));
      check_result(g, start, goal, r, p.smoother->smooth(context, r.path));
    }
  }
}

TEST_CASE("acoplan runs a cross-paper pipeline from the command line", "[composition][acoplan]") {
  const auto r = test::acoplan({"--init", "obstacle_density", "--heuristic", "direction", "--heuristic.gamma", "3",
                                "--update", "gaussian", "--update.psi", "50", "--deadlock", "clear_and_tabu",
                                "--smoother", "prune", "--corner-cutting", "--same-path-stop", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out,
             Contains("\"solved\":true") && Contains("\"smoother\":\"prune\"") && Contains("\"heuristic.gamma\":3.0"));
}
