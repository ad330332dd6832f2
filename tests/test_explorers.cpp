// Explorer ants (ColonySettings::explorers): a share of each iteration's ants that ignore the
// pheromone and the walk limit, inside a colony that learns from them.
#include <catch2/catch.hpp>

#include "aco/engine/colony.hpp"
#include "aco/engine/map_io.hpp"
#include "support.hpp"

namespace {

struct Strategies {
  explicit Strategies(const std::string& update_name)
      : init(test::make<aco::PheromoneInit>("init", "uniform")),
        heuristic(test::make<aco::Heuristic>("heuristic", "progress")),
        update(test::make<aco::PheromoneUpdate>("update", update_name)),
        deadlock(test::make<aco::DeadlockPolicy>("deadlock", "backtrack")) {}
  aco::ColonyStrategies pipeline() { return {init.get(), heuristic.get(), update.get(), deadlock.get()}; }
  std::unique_ptr<aco::PheromoneInit> init;
  std::unique_ptr<aco::Heuristic> heuristic;
  std::unique_ptr<aco::PheromoneUpdate> update;
  std::unique_ptr<aco::DeadlockPolicy> deadlock;
};

struct Rooms {
  std::unique_ptr<aco::Map> map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  aco::Graph graph = aco::build_graph(*map, {});
  aco::NodeId start = graph.node({3, 3});
  aco::NodeId goal = graph.node({44, 40});
};

aco::ColonySettings settings() {
  aco::ColonySettings s;
  s.ants = 8;
  s.iterations = 12;
  s.beta = 3;
  s.seed = 5;
  s.walk_limit = 4;
  s.band_search = 4;
  s.local_search = aco::LocalSearch::straighten;
  return s;
}

}  // namespace

TEST_CASE("a colony of explorers walks as the colony with alpha 0 and no walk limit does", "[colony][explorers]") {
  // An explorer's choice ignores tau, as tau^0 = 1 does, and no walk limit stops it; the backtrack
  // policy learns nothing between iterations. So the walks are the same, bit for bit.
  Rooms r;
  auto explorers = settings();
  explorers.explorers = 1.0;
  auto alpha_zero = settings();
  alpha_zero.alpha = 0.0;
  alpha_zero.walk_limit = 0.0;
  for (double q0 : {0.0, 0.7}) {
    explorers.q0 = alpha_zero.q0 = q0;
    Strategies p("max_min"), q("max_min");
    const auto e = aco::run_colony(r.graph, r.start, r.goal, p.pipeline(), explorers);
    const auto z = aco::run_colony(r.graph, r.start, r.goal, q.pipeline(), alpha_zero);
    REQUIRE(e.solved);
    CHECK(e.path == z.path);
    CHECK(e.best_so_far == z.best_so_far);
    CHECK(e.iteration_best == z.iteration_best);
    CHECK(e.ant_steps == z.ant_steps);
  }
}

TEST_CASE("explorers change the walks, and the run stays the same for any thread count",
          "[colony][explorers][determinism]") {
  Rooms r;
  auto mixed = settings();
  mixed.explorers = 0.25;  // the last 2 of 8 ants
  Strategies p("max_min"), q("max_min");
  const auto with = aco::run_colony(r.graph, r.start, r.goal, p.pipeline(), mixed);
  const auto without = aco::run_colony(r.graph, r.start, r.goal, q.pipeline(), settings());
  REQUIRE(with.solved);
  CHECK(with.ant_steps != without.ant_steps);
  test::run_on_thread_counts(r.graph, r.start, r.goal, mixed, {"uniform", "progress", "max_min", "backtrack"});
}

TEST_CASE("acoplan takes --explorers as a share of the ants and refuses one outside 0..1", "[acoplan][explorers]") {
  const auto map = (test::data_dir() / "maps/classic20/map2.txt").string();
  const auto ok = test::acoplan(
      {"--map", map, "--start", "0,0", "--goal", "19,19", "--explorers", "0.2", "--ants", "10", "--iterations", "5"});
  CHECK(ok.exit_code == 0);
  const auto bad = test::acoplan({"--map", map, "--start", "0,0", "--goal", "19,19", "--explorers", "1.5"});
  CHECK(bad.exit_code != 0);
  CHECK_THAT(bad.err, Catch::Contains("explorers") && Catch::Contains("[0, 1]"));
}
