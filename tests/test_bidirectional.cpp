// Paper 000's bidirectional search: two colonies, joined where a forward and a backward walk meet.
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>

#include "aco/engine/colony.hpp"
#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "support.hpp"

using Catch::Contains;
using test::Baseline;
using test::RecordingUpdate;

namespace {

aco::ColonySettings bidirectional(int ants, int iterations, std::uint64_t seed = 1) {
  aco::ColonySettings s;
  s.ants = ants;
  s.iterations = iterations;
  s.seed = seed;
  s.bidirectional = true;
  return s;
}

// Both colonies' ants of every iteration, recorded.
struct TwoColonies {
  Baseline forward, backward;
  RecordingUpdate forward_ants{*forward.update}, backward_ants{*backward.update};
  aco::ColonyStrategies forward_pipeline() {
    aco::ColonyStrategies p = forward.pipeline();
    p.update = &forward_ants;
    return p;
  }
  aco::ColonyStrategies backward_pipeline() {
    aco::ColonyStrategies p = backward.pipeline();
    p.update = &backward_ants;
    return p;
  }
};

}  // namespace

TEST_CASE("every joined bidirectional path is a valid start-to-goal path", "[bidirectional]") {
  std::mt19937 rng(2026);
  int maps = 0, joined = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const aco::OccupancyGrid map = test::random_grid(rng, 6 + trial % 15, 5 + trial % 11);
    const aco::Graph graph = aco::build_graph(
        map, {trial % 3 == 0 ? aco::Neighbourhood::sixteen : aco::Neighbourhood::eight, trial % 2 == 0});
    std::vector<aco::NodeId> free;
    for (aco::NodeId n = 0; n < graph.num_nodes(); ++n)
      if (graph.passable(n)) free.push_back(n);
    if (free.size() < 2) continue;
    const aco::NodeId start = free.front(), goal = free.back();
    if (!aco::reachable(graph, start, goal)) continue;
    ++maps;
    TwoColonies c;
    // Backtracking on odd trials, so walks also shrink while the other ant looks for them.
    std::unique_ptr<aco::DeadlockPolicy> f_back, b_back;
    if (trial % 2) {
      f_back = test::make<aco::DeadlockPolicy>("deadlock", "backtrack_penalty");
      b_back = test::make<aco::DeadlockPolicy>("deadlock", "backtrack_penalty");
    }
    aco::ColonyStrategies fp = c.forward_pipeline(), bp = c.backward_pipeline();
    if (f_back) fp.deadlock = f_back.get(), bp.deadlock = b_back.get();
    const auto result = aco::run_colony(graph, start, goal, fp, bidirectional(12, 8, trial), &bp);
    REQUIRE(c.forward_ants.ants.size() == c.backward_ants.ants.size());
    for (std::size_t it = 0; it < c.forward_ants.ants.size(); ++it) {
      for (std::size_t k = 0; k < c.forward_ants.ants[it].size(); ++k) {
        const aco::Ant& f = c.forward_ants.ants[it][k];
        const aco::Ant& b = c.backward_ants.ants[it][k];
        INFO("trial " << trial << ", iteration " << it << ", ant " << k);
        REQUIRE(test::walk_problem(graph, f, start, goal) == "");
        REQUIRE(test::walk_problem(graph, b, goal, start) == "");
        REQUIRE(f.arrived == b.arrived);
        if (f.arrived) {
          ++joined;
          // The backward ant carries the same path, walked the other way.
          REQUIRE(std::equal(f.nodes.begin(), f.nodes.end(), b.nodes.rbegin(), b.nodes.rend()));
          REQUIRE(f.length == Approx(b.length));
        }
      }
    }
    if (result.solved) {
      REQUIRE(result.path.front() == start);
      REQUIRE(result.path.back() == goal);
      REQUIRE(result.length == Approx(aco::path_length(graph, result.path)));
    }
  }
  CHECK(maps >= 20);
  CHECK(joined > 1000);
}

TEST_CASE("the bidirectional search is bit-identical for any thread count", "[bidirectional][determinism]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {aco::Neighbourhood::sixteen, false});
  std::vector<aco::ColonyResult> results;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (int threads : {1, 2, 4}) {
    Baseline forward, backward;
    const aco::ColonyStrategies bp = backward.pipeline();
    tbb::task_arena arena(threads);
    arena.execute([&] {
      results.push_back(aco::run_colony(graph, graph.node({3, 3}), graph.node({44, 40}), forward.pipeline(),
                                        bidirectional(30, 20, 5), &bp));
    });
  }
  REQUIRE(results[0].solved);
  for (std::size_t i = 1; i < results.size(); ++i) test::check_same_run(results[i], results[0]);
}

TEST_CASE("the bidirectional search finds the classic map's paths and composes with other plugins", "[bidirectional]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  const double optimum = 34.3848;  // A*, see test_quality
  for (const char* update : {"ant_system", "acs", "max_min", "gaussian"}) {
    INFO(update);
    auto make_pipeline = [&](Baseline& b) {
      b.update = test::make<aco::PheromoneUpdate>("update", update);
      b.init = test::make<aco::PheromoneInit>("init", "obstacle_density");
      return b.pipeline();
    };
    Baseline forward, backward;
    const aco::ColonyStrategies fp = make_pipeline(forward), bp = make_pipeline(backward);
    aco::ColonySettings s = bidirectional(50, 60);
    if (std::string(update) == "acs") s.q0 = 0.7;
    const auto result = aco::run_colony(graph, 0, graph.node({19, 19}), fp, s, &bp);
    REQUIRE(result.solved);
    CHECK(result.length < optimum * 1.10);
    CHECK(result.path.front() == 0);
    CHECK(result.path.back() == graph.node({19, 19}));
  }
}

TEST_CASE("the bidirectional search counts both ants of a pair as walks", "[bidirectional]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  Baseline forward, backward;
  const aco::ColonyStrategies bp = backward.pipeline();
  const auto result = aco::run_colony(graph, 0, graph.node({19, 19}), forward.pipeline(), bidirectional(9, 12), &bp);
  REQUIRE(result.iterations == 12);
  test::check_anytime_curves(result, 2u * 9u * 12u);
  for (std::size_t i = 0; i < result.walks.size(); ++i) CHECK(result.walks[i] == 2u * 9u * (i + 1));
}

TEST_CASE("the bidirectional search refuses a missing or shared backward pipeline", "[bidirectional]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {});
  Baseline b;
  const aco::ColonyStrategies p = b.pipeline();
  CHECK_THROWS_WITH(aco::run_colony(graph, 0, graph.node({19, 19}), p, bidirectional(5, 2)),
                    Contains("second, complete set of strategy objects"));
  CHECK_THROWS_WITH(aco::run_colony(graph, 0, graph.node({19, 19}), p, bidirectional(5, 2), &p),
                    Contains("must not share strategy objects"));
}

TEST_CASE("acoplan --search bidirectional plans and reports the joined path", "[bidirectional][acoplan]") {
  const auto r = test::acoplan({"--search", "bidirectional", "--json", "--seed", "3"});
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Contains("\"solved\":true"));
  CHECK_THAT(r.out, Contains("\"search\":\"bidirectional\""));
}
