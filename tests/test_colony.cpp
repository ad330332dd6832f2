#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <set>

#include "aco/engine/colony.hpp"
#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/rng.hpp"
#include "support.hpp"

using Catch::Contains;

using test::Baseline;
using test::RecordingUpdate;

TEST_CASE("random streams are reproducible and independent", "[rng]") {
  aco::Rng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const auto x = a.next();
    CHECK(x == b.next());
    CHECK(x != c.next());
  }
  auto s1 = aco::Rng::stream(7, 3, 5), s2 = aco::Rng::stream(7, 3, 5), s3 = aco::Rng::stream(7, 5, 3);
  CHECK(s1.next() == s2.next());
  CHECK(s1.next() != s3.next());
  aco::Rng r(1);
  double sum = 0;
  for (int i = 0; i < 10000; ++i) {
    const double u = r.uniform();
    REQUIRE(u >= 0.0);
    REQUIRE(u < 1.0);
    sum += u;
    REQUIRE(r.below(7) < 7);
  }
  CHECK(sum / 10000 == Approx(0.5).margin(0.02));
}

TEST_CASE("results are bit-identical for any thread count", "[colony][determinism]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {});
  aco::ColonySettings settings;
  settings.ants = 40;
  settings.iterations = 30;
  settings.seed = 11;
  std::vector<aco::ColonyResult> results;
  // Allow more threads than cores, so 4 really means 4 on a small machine.
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (int threads : {1, 2, 4}) {
    Baseline b;
    tbb::task_arena arena(threads);
    arena.execute([&] {
      results.push_back(aco::run_colony(graph, graph.node({3, 3}), graph.node({44, 40}), b.pipeline(), settings));
    });
  }
  for (std::size_t i = 1; i < results.size(); ++i) test::check_same_run(results[i], results[0]);
  REQUIRE(results[0].solved);
}

TEST_CASE("another seed gives another run", "[colony][determinism]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  Baseline b;
  aco::ColonySettings s;
  s.iterations = 20;
  const auto first = aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), s);
  s.seed = 2;
  Baseline c;
  const auto second = aco::run_colony(graph, 0, graph.node({19, 19}), c.pipeline(), s);
  CHECK(first.ant_steps != second.ant_steps);
}

TEST_CASE("every ant walks a loop-free chain of edges from the start", "[colony]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {});
  Baseline b;
  RecordingUpdate recorder(*b.update);
  aco::ColonyStrategies p = b.pipeline();
  p.update = &recorder;
  aco::ColonySettings s;
  s.ants = 30;
  s.iterations = 10;
  const aco::NodeId start = 0, goal = graph.node({19, 19});
  const auto result = aco::run_colony(graph, start, goal, p, s);
  REQUIRE(recorder.ants.size() == 10);
  int arrived = 0;
  for (const auto& iteration : recorder.ants) {
    REQUIRE(iteration.size() == 30);
    for (const aco::Ant& ant : iteration) {
      REQUIRE(test::walk_problem(graph, ant, start, goal) == "");
      if (ant.arrived) ++arrived;
    }
  }
  CHECK(arrived > 0);
  // The reported best is the shortest arrived ant, and best_iteration the first iteration reaching it.
  double shortest = INFINITY;
  int first = 0;
  for (std::size_t it = 0; it < recorder.ants.size(); ++it)
    for (const aco::Ant& ant : recorder.ants[it])
      if (ant.arrived && ant.length < shortest) shortest = ant.length, first = int(it) + 1;
  CHECK(result.length == shortest);
  CHECK(result.best_iteration == first);
  for (std::size_t i = 1; i < result.best_so_far.size(); ++i) CHECK(result.best_so_far[i] <= result.best_so_far[i - 1]);
}

TEST_CASE("the stagnation rule stops a run after that many iterations without improvement, and its curves with it",
          "[colony]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  Baseline b;
  aco::ColonySettings s;
  s.iterations = 1000;
  s.stagnation = 5;
  const auto result = aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), s);
  REQUIRE(result.solved);
  CHECK(result.iterations < 1000);
  CHECK(result.iterations - result.best_iteration == 5);
  CHECK(result.best_so_far.size() == std::size_t(result.iterations));
  // The anytime curves: a time per iteration run, never decreasing, and one walk per ant.
  const auto ants = static_cast<std::uint64_t>(s.ants);
  test::check_anytime_curves(result, ants * static_cast<std::uint64_t>(result.iterations));
  for (std::size_t i = 0; i < result.walks.size(); ++i) CHECK(result.walks[i] == ants * (i + 1));
  // start == goal: no search, no iteration, no curve.
  const auto trivial = aco::run_colony(graph, 0, 0, b.pipeline(), s);
  CHECK(trivial.elapsed_s.empty());
  CHECK(trivial.walks.empty());
}

TEST_CASE("a time limit stops the run inside an iteration, its walks cut short", "[colony]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  Baseline b;
  aco::ColonySettings s;
  s.iterations = 50;
  // Any colony's setup outlasts a nanosecond: every ant sees the limit passed at its first look at
  // the clock, before its first move, whatever the machine. The first iteration is the last.
  s.time_limit = 1e-9;
  const auto limited = aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), s);
  CHECK(limited.stopped_by == aco::StopReason::time);
  CHECK(limited.iterations == 1);
  CHECK(limited.ant_steps == 0);
  CHECK(limited.best_so_far.size() == 1);
  CHECK_FALSE(limited.solved);
  // The same in the bidirectional search and the islands.
  aco::ColonySettings two = s;
  two.bidirectional = true;
  Baseline other;
  const aco::ColonyStrategies backward = other.pipeline();
  const auto both_ways = aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), two, &backward);
  CHECK((both_ways.stopped_by == aco::StopReason::time && both_ways.ant_steps == 0 && both_ways.iterations == 1));
  two.bidirectional = false;
  two.colonies = 2;
  const std::vector<aco::ColonyStrategies> more{backward};
  const auto islands = aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), two, nullptr, more);
  CHECK((islands.stopped_by == aco::StopReason::time && islands.ant_steps == 0 && islands.iterations == 1));
  // A limit that is never reached, and the budget's last iteration past the limit, are the
  // iteration budget's stop.
  s.time_limit = 1e6;
  CHECK(aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), s).stopped_by == aco::StopReason::iterations);
  s.iterations = 1;
  s.time_limit = 1e-9;
  CHECK(aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), s).stopped_by == aco::StopReason::iterations);
  for (const double bad : {-1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    s.time_limit = bad;
    CHECK_THROWS_WITH(aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), s),
                      Catch::Contains("time-limit must be finite and >= 0"));
  }
}

TEST_CASE("a host's between-iterations call may abandon a run, and leaves a run it lets finish unchanged", "[colony]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  aco::ColonySettings s;
  s.iterations = 20;
  Baseline plain;
  const auto without = aco::run_colony(graph, 0, graph.node({19, 19}), plain.pipeline(), s);
  int calls = 0;
  s.between_iterations = [&calls] { ++calls; };
  Baseline counted;
  test::check_same_run(aco::run_colony(graph, 0, graph.node({19, 19}), counted.pipeline(), s), without);
  CHECK(calls == s.iterations - 1);  // not after the last: the run is over
  struct Stop {};
  calls = 0;
  s.between_iterations = [&calls] {
    if (++calls == 3) throw Stop{};
  };
  Baseline stopped;
  CHECK_THROWS_AS(aco::run_colony(graph, 0, graph.node({19, 19}), stopped.pipeline(), s), Stop);
  CHECK(calls == 3);
}

namespace {
// Steps back one node whenever an ant is stuck.
class BacktrackOne final : public aco::DeadlockPolicy {
 public:
  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override { return 1; }
};
class ForbidNode final : public aco::DeadlockPolicy {
 public:
  explicit ForbidNode(aco::NodeId n) : node(n) {}
  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override { return 0; }
  void after_iteration(const aco::Context&, const aco::Iteration&, aco::Trail&,
                       std::vector<std::uint8_t>& forbidden) override {
    forbidden[node] = 1;
  }
  aco::NodeId node;
};
}  // namespace

TEST_CASE("a backtracking deadlock policy lets ants out of dead ends", "[colony][deadlock]") {
  // A dead-end pocket right next to the start, towards the goal: greedy ants walk into it.
  const auto map = test::grid({
      "..........",
      ".######...",
      ".#....#...",
      ".#.##.#...",
      ".#..#.....",
      ".####.....",
      "..........",
  });
  const aco::Graph graph = aco::build_graph(map, {});
  aco::ColonySettings s;
  s.ants = 20;
  s.iterations = 5;
  const aco::NodeId start = graph.node({2, 2}), goal = graph.node({9, 6});
  Baseline discard;
  const auto dropped = aco::run_colony(graph, start, goal, discard.pipeline(), s);
  Baseline with_backtrack;
  BacktrackOne backtrack;
  aco::ColonyStrategies p = with_backtrack.pipeline();
  p.deadlock = &backtrack;
  RecordingUpdate recorder(*with_backtrack.update);
  p.update = &recorder;
  const auto rescued = aco::run_colony(graph, start, goal, p, s);
  int arrived_backtrack = 0, arrived_discard = 0;
  for (int a : rescued.arrived) arrived_backtrack += a;
  for (int a : dropped.arrived) arrived_discard += a;
  CHECK(arrived_backtrack == 100);  // backtracking never loses an ant when the goal is reachable
  CHECK(arrived_discard < arrived_backtrack);
  for (const auto& iteration : recorder.ants)
    for (const aco::Ant& ant : iteration) REQUIRE(aco::path_length(graph, ant.nodes) == Approx(ant.length));
}

TEST_CASE("nodes a deadlock policy forbids are never entered again", "[colony][deadlock]") {
  const auto map = test::grid({"......", "......", "......", "......"});
  const aco::Graph graph = aco::build_graph(map, {});
  Baseline b;
  const aco::NodeId banned = graph.node({2, 1});
  ForbidNode forbid(banned);
  RecordingUpdate recorder(*b.update);
  aco::ColonyStrategies p = b.pipeline();
  p.deadlock = &forbid;
  p.update = &recorder;
  aco::ColonySettings s;
  s.iterations = 10;
  aco::run_colony(graph, graph.node({0, 1}), graph.node({5, 1}), p, s);
  bool visited_before = false;
  for (const aco::Ant& ant : recorder.ants[0])
    visited_before |= std::count(ant.nodes.begin(), ant.nodes.end(), banned) > 0;
  CHECK(visited_before);  // the straight line runs through it, so the first iteration uses it
  for (std::size_t it = 1; it < recorder.ants.size(); ++it)
    for (const aco::Ant& ant : recorder.ants[it]) REQUIRE(std::count(ant.nodes.begin(), ant.nodes.end(), banned) == 0);
}

namespace {
class PoisonUpdate final : public aco::PheromoneUpdate {
 public:
  void update(const aco::Context&, const aco::Iteration&, std::span<double> tau) override { tau[3] = NAN; }
};
}  // namespace

TEST_CASE("bad inputs and bad strategy output are reported, not run", "[colony]") {
  const auto map = test::grid({"..#", "...", "..."});
  const aco::Graph graph = aco::build_graph(map, {});
  Baseline b;
  aco::ColonySettings s;
  REQUIRE_THROWS_WITH(aco::run_colony(graph, 0, graph.node({2, 0}), b.pipeline(), s),
                      Contains("goal (2,0) is a blocked cell"));
  REQUIRE_THROWS_WITH(aco::run_colony(graph, -1, 2, b.pipeline(), s), Contains("start node is outside the map"));
  s.ants = 0;
  REQUIRE_THROWS_WITH(aco::run_colony(graph, 0, 8, b.pipeline(), s), Contains("ants must be at least 1"));
  s.ants = 5;
  PoisonUpdate poison;
  aco::ColonyStrategies p = b.pipeline();
  p.update = &poison;
  REQUIRE_THROWS_WITH(aco::run_colony(graph, 0, 8, p, s),
                      Contains("the update plugin wrote nan to the pheromone of edge") &&
                          Contains("in update() in iteration 0 (0-based"));
  const auto trivial = aco::run_colony(graph, 4, 4, b.pipeline(), s);
  CHECK(trivial.solved);
  CHECK(trivial.length == 0.0);
  CHECK(trivial.path == std::vector<aco::NodeId>{4});
}

TEST_CASE("the same-path rule stops once that fraction of an iteration's ants share one path", "[colony]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  Baseline b;
  RecordingUpdate recorder(*b.update);
  aco::ColonyStrategies p = b.pipeline();
  p.update = &recorder;
  aco::ColonySettings s;
  s.iterations = 300;
  s.same_path_stop = true;
  s.same_path_fraction = 0.5;
  const auto result = aco::run_colony(graph, 0, graph.node({19, 19}), p, s);
  REQUIRE(result.stopped_by == aco::StopReason::same_path);
  REQUIRE(result.iterations < 300);
  // The last iteration met the rule and none before it did.
  auto largest = [](const std::vector<aco::Ant>& ants) {
    std::map<std::vector<aco::NodeId>, int> count;
    int most = 0;
    for (const auto& a : ants)
      if (a.arrived) most = std::max(most, ++count[a.nodes]);
    return most;
  };
  CHECK(largest(recorder.ants.back()) >= 25);
  for (std::size_t it = 0; it + 1 < recorder.ants.size(); ++it) CHECK(largest(recorder.ants[it]) < 25);
}

TEST_CASE("q0: with probability q0 an ant takes its best candidate (q0 = 1: every ant walks the greedy path)",
          "[colony][q0]") {
  const auto map = test::classic_map(1);
  const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, true});
  auto paths_of_first_iteration = [&](double q0) {
    Baseline b;
    RecordingUpdate recording(*b.update);
    aco::ColonyStrategies p = b.pipeline();
    p.update = &recording;
    aco::ColonySettings s;
    s.ants = 20;
    s.iterations = 1;
    s.q0 = q0;
    aco::run_colony(graph, 0, graph.node({19, 19}), p, s);
    std::set<std::vector<aco::NodeId>> paths;
    for (const aco::Ant& ant : recording.ants.at(0)) paths.insert(ant.nodes);
    return paths;
  };
  CHECK(paths_of_first_iteration(1.0).size() == 1);  // uniform pheromone: the heuristic's argmax every step
  CHECK(paths_of_first_iteration(0.0).size() > 10);
  aco::ColonySettings bad;
  bad.q0 = 1.5;
  Baseline b;
  CHECK_THROWS_WITH(aco::run_colony(graph, 0, graph.node({19, 19}), b.pipeline(), bad),
                    Contains("q0 must be in [0, 1]"));
}

TEST_CASE("strategy objects reused for runs on other maps give the runs fresh objects give", "[colony][lifecycle]") {
  // The bundled plugins that keep state from hook to hook within a run, which begin_run() must
  // reset (strategies.hpp, the lifecycle): direction's and potential_field's tables, max_min's
  // bounds and restarts, population's paths, clear_and_tabu's witness.
  const auto arena_map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph arena = aco::build_graph(*arena_map, {});
  const auto classic = test::classic_map(1);
  const aco::Graph other = aco::build_graph(classic, {aco::Neighbourhood::eight, true});
  aco::ColonySettings settings;
  settings.ants = 10;
  settings.iterations = 25;
  settings.seed = 3;
  const std::vector<aco::Keys> pipelines{{{"heuristic", "direction"},
                                          {"update", "max_min"},
                                          {"update.restart_after", "4"},
                                          {"deadlock", "clear_and_tabu"}},
                                         {{"init", "potential_field"},
                                          {"heuristic", "potential_field"},
                                          {"update", "population"},
                                          {"deadlock", "backtrack"}}};
  for (const aco::Keys& keys : pipelines) {
    INFO(keys.at("heuristic") << ", " << keys.at("update") << ", " << keys.at("deadlock"));
    const aco::PipelineSpec spec = test::pipeline(keys);
    const auto on_arena = [&](const aco::PipelinePlugins& p) {
      return aco::run_colony(arena, arena.node({3, 3}), arena.node({44, 40}), p.strategies(), settings);
    };
    const aco::PipelinePlugins reused = aco::instantiate(test::plugins(), spec);
    on_arena(reused);
    aco::run_colony(other, other.node({0, 0}), other.node({19, 19}), reused.strategies(), settings);
    const aco::ColonyResult again = on_arena(reused);
    REQUIRE(again.solved);
    test::check_same_run(again, on_arena(aco::instantiate(test::plugins(), spec)));
  }
}
