// The colony and corridors (aco/engine/colony.hpp, issue 52): the corridors its walks took, restarts that
// settle a corridor, islands that keep distinct corridors, and per-node memory of the way to the goal.
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <catch2/catch.hpp>

#include "aco/astar.hpp"
#include "aco/engine/colony.hpp"
#include "aco/corridor.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/run_spec.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

// One run of the keys' colony and pipeline (fresh plugins, as acoplan makes them) on `threads`.
aco::ColonyResult run(const aco::Graph& graph, aco::Cell start, aco::Cell goal, const aco::Keys& keys,
                      int threads = 1) {
  aco::PluginRegistry& registry = test::plugins();
  const aco::RunSpec spec = aco::resolve_run(keys, registry);
  const aco::PipelinePlugins plugins = aco::instantiate(registry, spec.pipeline);
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  tbb::task_arena arena(threads);
  aco::ColonyResult result;
  arena.execute([&] {
    result =
        aco::run_pipeline(registry, spec.pipeline, plugins, graph, graph.node(start), graph.node(goal), spec.colony);
  });
  return result;
}

// The same run on 1, 2 and 4 threads, checked bit for bit; the first.
aco::ColonyResult run_on_thread_counts(const aco::Graph& graph, aco::Cell start, aco::Cell goal,
                                       const aco::Keys& keys) {
  const aco::ColonyResult first = run(graph, start, goal, keys, 1);
  for (int threads : {2, 4}) test::check_same_run(run(graph, start, goal, keys, threads), first);
  return first;
}

// A block in the middle of an open room: two corridors, the one below the block shorter.
const std::vector<std::string> kBlock = {
    "............", "............", ".....##.....", ".....##.....", ".....##.....", "............", "............",
};

}  // namespace

TEST_CASE("the colony reports each corridor its arrived walks took, once", "[colony][corridor]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {});
  const aco::ColonyResult r =
      run_on_thread_counts(graph, {3, 3}, {44, 40}, {{"ants", "20"}, {"iterations", "10"}, {"seed", "3"}});
  REQUIRE(r.solved);
  REQUIRE_FALSE(r.corridors.empty());
  CHECK(std::is_sorted(r.corridors.begin(), r.corridors.end()));
  CHECK(std::adjacent_find(r.corridors.begin(), r.corridors.end()) == r.corridors.end());
  const aco::CorridorKeys keys(*map);
  CHECK(std::binary_search(r.corridors.begin(), r.corridors.end(), keys.key(graph, r.path)));
  SECTION("a room with nothing inside to go round is one corridor") {
    const auto open = test::grid({"........", "........", "........", "........"});
    const aco::Graph open_graph = aco::build_graph(open, {});
    CHECK(run(open_graph, {0, 0}, {7, 3}, {{"ants", "10"}, {"iterations", "5"}}).corridors.size() == 1);
  }
}

TEST_CASE("restarts settle the epoch's corridor and keep the run's best path", "[colony][corridor]") {
  const auto map = test::grid(kBlock);
  const aco::Graph graph = aco::build_graph(map, {});
  const aco::Cell start{0, 3}, goal{11, 4};
  const double optimum = aco::astar(graph, graph.node(start), graph.node(goal))->length;
  const aco::Keys keys{{"ants", "10"}, {"iterations", "40"}, {"restart-after", "3"}, {"corridor-derate", "0.5"}};
  const aco::ColonyResult r = run_on_thread_counts(graph, start, goal, keys);
  REQUIRE(r.solved);
  CHECK(r.restarts > 0);
  CHECK(r.corridors.size() == 2);  // both sides of the block
  // Every epoch's walks count: the result is the shortest walk of the run, whichever epoch found it.
  CHECK(*std::min_element(r.iteration_best.begin(), r.iteration_best.end()) == r.length);
  CHECK(aco::path_length(graph, r.path) == Approx(r.length));
  CHECK(r.length >= optimum - 1e-9);
  SECTION("without restart-after the run is the one it always was") {
    aco::Keys plain = keys;
    plain.erase("restart-after");
    plain.erase("corridor-derate");
    const aco::ColonyResult once = run(graph, start, goal, plain);
    CHECK(once.restarts == 0);
    aco::Keys zero = plain;
    zero["restart-after"] = std::string("0");
    test::check_same_run(run(graph, start, goal, zero), once);
  }
}

TEST_CASE("restarts in the bidirectional search: each colony restarts on its own", "[colony][corridor]") {
  const auto map = test::grid(kBlock);
  const aco::Graph graph = aco::build_graph(map, {});
  const aco::ColonyResult r = run_on_thread_counts(graph, {0, 3}, {11, 4},
                                                   {{"ants", "10"},
                                                    {"iterations", "30"},
                                                    {"search", "bidirectional"},
                                                    {"restart-after", "3"},
                                                    {"corridor-derate", "0.5"}});
  REQUIRE(r.solved);
  CHECK(r.restarts > 0);
  CHECK(aco::path_length(graph, r.path) == Approx(r.length));
}

TEST_CASE("islands: colonies of their own share the ants and keep distinct corridors", "[colony][corridor]") {
  SECTION("the same run on any thread count, the best of every colony") {
    const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
    const aco::Graph graph = aco::build_graph(*map, {});
    const aco::ColonyResult r = run_on_thread_counts(
        graph, {3, 3}, {44, 40},
        {{"ants", "21"}, {"iterations", "12"}, {"colonies", "4"}, {"exchange-every", "2"}, {"corridor-derate", "0.1"}});
    REQUIRE(r.solved);
    CHECK(r.walks.back() == 21u * 12u);  // the ants are shared, not multiplied
    CHECK(aco::path_length(graph, r.path) == Approx(r.length));
  }
  SECTION("two colonies settled on the same side: the worse starts afresh") {
    const auto map = test::grid(kBlock);
    const aco::Graph graph = aco::build_graph(map, {});
    const aco::ColonyResult r = run_on_thread_counts(
        graph, {0, 3}, {11, 4}, {{"ants", "10"}, {"iterations", "30"}, {"colonies", "2"}, {"exchange-every", "1"}});
    REQUIRE(r.solved);
    CHECK(r.restarts > 0);
  }
}

TEST_CASE("goal memory raises the edge a walk went on shorter from, and stays deterministic", "[colony][corridor]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {});
  const aco::Keys keys{{"ants", "20"}, {"iterations", "10"}, {"seed", "5"}};
  aco::Keys remembering = keys;
  remembering["goal-memory"] = "true";
  const aco::ColonyResult with = run_on_thread_counts(graph, {3, 3}, {44, 40}, remembering);
  const aco::ColonyResult without = run(graph, {3, 3}, {44, 40}, keys);
  REQUIRE(with.solved);
  CHECK(with.pheromone != without.pheromone);
}

TEST_CASE("restarts and islands refuse settings they cannot honour, saying why", "[colony][corridor][bad-input]") {
  const auto map = test::grid(kBlock);
  const aco::Graph graph = aco::build_graph(map, {});
  const auto error = [&](const aco::Keys& keys) {
    try {
      run(graph, {0, 3}, {11, 4}, keys);
    } catch (const aco::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(error({{"ants", "3"}, {"colonies", "4"}}),
             Contains("colonies must be between 1 and the number of ants (3)"));
  CHECK_THAT(error({{"colonies", "2"}, {"search", "bidirectional"}}), Contains("single search only"));
  CHECK_THAT(error({{"colonies", "2"}, {"same-path-stop", "true"}}), Contains("same-path-stop works with one colony"));
  CHECK_THAT(error({{"colonies", "9"}}), Contains("colonies"));  // beyond its range
  SECTION("a direct caller must give every further colony its own objects") {
    test::Baseline a;
    aco::ColonySettings settings;
    settings.colonies = 2;
    CHECK_THROWS_WITH(aco::run_colony(graph, graph.node({0, 3}), graph.node({11, 4}), a.pipeline(), settings),
                      Contains("needs 1 more sets of strategy objects"));
    const aco::ColonyStrategies same[] = {a.pipeline()};
    CHECK_THROWS_WITH(
        aco::run_colony(graph, graph.node({0, 3}), graph.node({11, 4}), a.pipeline(), settings, nullptr, same),
        Contains("must not share strategy objects"));
  }
}
