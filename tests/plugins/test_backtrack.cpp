#include <catch2/catch.hpp>

#include "support.hpp"

namespace {

// A comb: a spine along the top, every tooth below it a dead end, the goal at the far end of the
// spine. A greedy ant that steps into a tooth can only get out by backing off.
aco::OccupancyGrid comb() {
  return test::grid({
      "...................",
      ".#.#.#.#.#.#.#.#.#.",
      ".#.#.#.#.#.#.#.#.#.",
      ".#.#.#.#.#.#.#.#.#.",
      "##################.",
  });
}

}  // namespace

TEST_CASE("backtrack: a stuck ant steps back the configured number of nodes", "[plugin][backtrack]") {
  const auto map = test::grid({"...", "..."});
  const aco::Graph graph = aco::build_graph(map, {});
  const auto context = test::context(graph, {0, 0}, {2, 1});
  const std::vector<aco::NodeId> walk{0, 1, 2};
  CHECK(test::make<aco::DeadlockPolicy>("deadlock", "backtrack")->on_stuck(context, walk) == 1);
  CHECK(test::make<aco::DeadlockPolicy>("deadlock", "backtrack", {{"steps", "4"}})->on_stuck(context, walk) == 4);
  CHECK_THROWS(test::make<aco::DeadlockPolicy>("deadlock", "backtrack", {{"steps", "0"}}));
}

TEST_CASE("backtrack: on a comb of dead ends every ant arrives on a loop-free path", "[plugin][backtrack]") {
  const auto map = comb();
  for (const bool corner_cutting : {false, true}) {
    const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, corner_cutting});
    const aco::NodeId start = graph.node({0, 3}), goal = graph.node({18, 3});
    test::Baseline b;
    auto backtrack = test::make<aco::DeadlockPolicy>("deadlock", "backtrack");
    auto progress = test::make<aco::Heuristic>("heuristic", "progress");
    test::RecordingUpdate recorder(*b.update);
    aco::ColonyStrategies p = b.pipeline();
    p.deadlock = backtrack.get();
    p.update = &recorder;
    aco::ColonySettings s;
    s.ants = 30;
    s.iterations = 20;
    const auto result = aco::run_colony(graph, start, goal, p, s);
    REQUIRE(result.solved);
    for (int arrived : result.arrived) CHECK(arrived == s.ants);
    int entered_a_tooth = 0;
    for (const auto& iteration : recorder.ants)
      for (const aco::Ant& ant : iteration) {
        REQUIRE(ant.arrived);
        REQUIRE(test::walk_problem(graph, ant, start, goal) == "");  // no node twice, edges chain
        for (aco::NodeId n : ant.nodes) entered_a_tooth += graph.cell(n).y == 3 && n != start && n != goal;
      }
    CHECK(entered_a_tooth == 0);  // the final walks hold no dead end: the ants backed out of them
    CHECK(result.ant_steps > std::uint64_t(s.ants * s.iterations) * result.path.size());  // they did walk into some
    // The same map with ants that die: most of them are lost in the teeth.
    test::Baseline dying;
    aco::ColonyStrategies q = dying.pipeline();
    q.heuristic = progress.get();
    p.heuristic = progress.get();
    const auto dropped = aco::run_colony(graph, start, goal, q, s);
    int arrived = 0;
    for (int a : dropped.arrived) arrived += a;
    CHECK(arrived < s.ants * s.iterations);
  }
}
