// The engine options for large maps: dead-end filling, local search on the ants' walks and the
// walk limit (aco/engine/dead_ends.hpp, aco/engine/local_search.hpp, ColonySettings).
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <functional>
#include <map>
#include <random>

#include "aco/engine/dead_ends.hpp"
#include "aco/engine/local_search.hpp"
#include "aco/engine/map_io.hpp"
#include "support.hpp"

namespace {

// Which cells are dead ends, as the rows of a map: 'x' dead, '.' free and on some simple path.
std::vector<std::string> picture(const aco::Graph& graph, const std::vector<std::uint8_t>& dead) {
  std::vector<std::string> rows(graph.height, std::string(graph.width, '#'));
  for (aco::NodeId n = 0; n < graph.num_nodes(); ++n)
    if (graph.passable(n)) rows[graph.cell(n).y][graph.cell(n).x] = dead[n] ? 'x' : '.';
  return rows;
}

// Brute force: the nodes on at least one simple start-goal path, by enumerating them all.
std::vector<std::uint8_t> on_some_simple_path(const aco::Graph& graph, aco::NodeId start, aco::NodeId goal) {
  std::vector<std::uint8_t> on(graph.num_nodes(), 0), in_walk(graph.num_nodes(), 0);
  std::vector<aco::NodeId> walk{start};
  in_walk[start] = 1;
  std::function<void(aco::NodeId)> extend = [&](aco::NodeId at) {
    if (at == goal) {
      for (aco::NodeId n : walk) on[n] = 1;
      return;
    }
    for (aco::EdgeId e = graph.edges_begin(at); e < graph.edges_end(at); ++e) {
      const aco::NodeId next = graph.targets[e];
      if (in_walk[next]) continue;
      in_walk[next] = 1;
      walk.push_back(next);
      extend(next);
      walk.pop_back();
      in_walk[next] = 0;
    }
  };
  extend(start);
  return on;
}

}  // namespace

TEST_CASE("dead ends: pockets, a room behind one door and the rest of the component are filled", "[large][dead_ends]") {
  const auto map = test::grid({
      "S.....#....",
      "####..#.##.",
      "#..#.......",
      "#..#.####.#",
      "#.......#G#",
      "#####.###.#",
      "#####.....#",
  });
  const aco::Graph graph = aco::build_graph(map, {});
  const auto dead = aco::dead_ends(graph, graph.node({0, 0}), graph.node({9, 4}));
  // The room at the left hangs on one door, (4,4); the stub (6,4)-(7,4) leads nowhere. The loop
  // at the top right and the corridor along the bottom, which reaches the goal from below, are
  // both ways to the goal, so they stay.
  CHECK(picture(graph, dead) == std::vector<std::string>{
                                    "......#....",
                                    "####..#.##.",
                                    "#xx#.......",
                                    "#xx#.####.#",
                                    "#xxx..xx#.#",
                                    "#####.###.#",
                                    "#####.....#",
                                });
}

TEST_CASE("dead ends: in a tree-shaped maze only the solution path is left", "[large][dead_ends]") {
  const auto map = test::grid({
      ".....#...",
      "####.#.#.",
      "...#...#.",
      ".#.#####.",
      ".#.......",
      "########.",
      ".........",
  });
  const aco::Graph graph = aco::build_graph(map, {});
  const aco::NodeId start = graph.node({0, 0}), goal = graph.node({0, 2});
  const auto dead = aco::dead_ends(graph, start, goal);
  // Without corner cutting no diagonal fits: the maze is a tree and its one start-goal path has
  // 27 cells; the corridor along the bottom and the stub (0,3)-(0,4) below the goal are filled.
  int left = 0;
  for (aco::NodeId n = 0; n < graph.num_nodes(); ++n) left += graph.passable(n) && !dead[n];
  CHECK(left == 27);
  CHECK(dead[graph.node({0, 6})] == 1);
  CHECK(dead[graph.node({0, 4})] == 1);
  CHECK(dead[graph.node({2, 3})] == 0);
}

TEST_CASE("dead ends agree with enumerating every simple path on small random maps", "[large][dead_ends]") {
  std::mt19937 rng(5);
  int checked = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const auto map = test::random_grid(rng, 4, 3 + trial % 2);
    for (const bool corner_cutting : {false, true}) {
      const aco::Graph graph = aco::build_graph(map, {aco::Neighbourhood::eight, corner_cutting});
      std::vector<aco::NodeId> free;
      for (aco::NodeId n = 0; n < graph.num_nodes(); ++n)
        if (graph.passable(n)) free.push_back(n);
      if (free.size() < 2) continue;
      const aco::NodeId start = free[rng() % free.size()], goal = free[rng() % free.size()];
      if (start == goal) continue;
      auto expected = on_some_simple_path(graph, start, goal);
      const auto dead = aco::dead_ends(graph, start, goal);
      for (aco::NodeId n = 0; n < graph.num_nodes(); ++n) {
        INFO("trial " << trial << " node " << aco::to_string(graph.cell(n)));
        if (n == start || n == goal)
          CHECK(dead[n] == 0);
        else
          CHECK(dead[n] == !expected[n]);
      }
      ++checked;
    }
  }
  CHECK(checked > 400);
}

TEST_CASE("local search: loops are cut and a corner becomes a diagonal", "[large][local_search]") {
  const auto map = test::grid({".....", ".....", ".....", ".....", "....."});
  const aco::Graph graph = aco::build_graph(map, {});
  const std::vector<std::uint8_t> forbidden(graph.num_nodes(), 0);
  aco::WalkScratch scratch;
  const aco::WalkShortener loops_only(graph, forbidden, 0), straighten(graph, forbidden, 64);
  // A staircase, right, up, right, up...: cutting loops (a later walk node next to an earlier
  // one) already turns every corner into a diagonal.
  aco::Ant stairs = test::ant(graph, {{0, 4}, {1, 4}, {1, 3}, {2, 3}, {2, 2}, {3, 2}, {3, 1}, {4, 1}, {4, 0}});
  loops_only.shorten(stairs, scratch);
  CHECK(stairs.length == Approx(4 * std::sqrt(2.0)));
  // Right, right, up, up: loop cutting gives right, diagonal, up (2 + sqrt 2); straightening the
  // diagonal (0,4) -> (2,2) is shorter still.
  const aco::Ant corner = test::ant(graph, {{0, 4}, {1, 4}, {2, 4}, {2, 3}, {2, 2}});
  aco::Ant cut = corner, straight = corner;
  loops_only.shorten(cut, scratch);
  CHECK(cut.length == Approx(2 + std::sqrt(2.0)));
  straighten.shorten(straight, scratch);
  CHECK(straight.length == Approx(2 * std::sqrt(2.0)));
  CHECK(test::walk_problem(graph, straight, graph.node({0, 4}), graph.node({2, 2})) == "");
  // A detour: down, right, right, up back to the first row, becomes the straight row.
  aco::Ant detour = test::ant(graph, {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {2, 2}, {2, 1}, {2, 0}});
  straighten.shorten(detour, scratch);
  CHECK(detour.length == Approx(2.0));
}

TEST_CASE("local search never enters a blocked or forbidden cell and keeps the walk's ends", "[large][local_search]") {
  const auto map = test::grid({
      ".....",
      ".....",
      ".#...",
  });
  const aco::Graph graph = aco::build_graph(map, {});
  std::vector<std::uint8_t> forbidden(graph.num_nodes(), 0);
  aco::WalkScratch scratch;
  const aco::Ant over_the_top =
      test::ant(graph, {{0, 2}, {0, 1}, {0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {4, 1}, {4, 2}});
  const aco::WalkShortener shortener(graph, forbidden, 64);
  // Free: the optimum round the block, (0,2) (0,1) (1,1) (2,1) (3,2) (4,2), 4 + sqrt 2.
  aco::Ant free_run = over_the_top;
  shortener.shorten(free_run, scratch);
  CHECK(free_run.length == Approx(4 + std::sqrt(2.0)));
  // With (1,1) and (2,1) forbidden the shortcut must keep to the top row and (3,1).
  forbidden[graph.node({1, 1})] = forbidden[graph.node({2, 1})] = 1;
  aco::Ant kept = over_the_top;
  shortener.shorten(kept, scratch);
  for (aco::NodeId n : kept.nodes) {
    CHECK(graph.passable(n));
    CHECK(!forbidden[n]);
  }
  CHECK(kept.nodes.front() == graph.node({0, 2}));
  CHECK(kept.nodes.back() == graph.node({4, 2}));
  CHECK(kept.length < over_the_top.length);
  CHECK(test::walk_problem(graph, kept, graph.node({0, 2}), graph.node({4, 2})) == "");
}

TEST_CASE("local search: every shortened walk on random maps is valid and never longer", "[large][local_search]") {
  std::mt19937 rng(17);
  int shortened = 0, walks = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto map = test::random_grid(rng, 30, 30);
    const aco::Neighbourhood nbhd = trial % 3 == 0   ? aco::Neighbourhood::sixteen
                                    : trial % 3 == 1 ? aco::Neighbourhood::eight
                                                     : aco::Neighbourhood::four;
    const aco::Graph graph = aco::build_graph(map, {nbhd, trial % 2 == 0});
    std::vector<aco::NodeId> free;
    for (aco::NodeId n = 0; n < graph.num_nodes(); ++n)
      if (graph.degree(n) > 0) free.push_back(n);
    if (free.size() < 2) continue;
    const aco::NodeId start = free.front(), goal = free.back();
    if (!aco::reachable(graph, start, goal)) continue;
    // Raw walks: depth-first ants with the distance heuristic, which wander.
    test::Baseline b;
    auto backtrack = test::make<aco::DeadlockPolicy>("deadlock", "backtrack");
    test::RecordingUpdate recorder(*b.update);
    aco::ColonyStrategies p = b.pipeline();
    p.deadlock = backtrack.get();
    p.update = &recorder;
    aco::ColonySettings s;
    s.ants = 10;
    s.iterations = 2;
    s.beta = 1;
    aco::run_colony(graph, start, goal, p, s);
    std::vector<std::uint8_t> forbidden(graph.num_nodes(), 0);
    for (int k = 0; k < 20; ++k) forbidden[free[rng() % free.size()]] = 1;
    forbidden[start] = forbidden[goal] = 0;
    const aco::WalkShortener shortener(graph, forbidden, 2 + trial % 64);
    aco::WalkScratch scratch;
    for (const auto& iteration : recorder.ants)
      for (aco::Ant ant : iteration) {
        if (!ant.arrived) continue;
        const double before = ant.length;
        const std::vector<aco::NodeId> raw = ant.nodes;
        shortener.shorten(ant, scratch);
        REQUIRE(test::walk_problem(graph, ant, start, goal) == "");
        REQUIRE(ant.length <= before + 1e-9);
        // A forbidden cell may stay only where the raw walk had it; no new one is entered.
        for (aco::NodeId n : ant.nodes)
          if (forbidden[n]) REQUIRE(std::find(raw.begin(), raw.end(), n) != raw.end());
        shortened += ant.length < before - 1e-9;
        ++walks;
      }
  }
  CHECK(walks > 300);
  CHECK(shortened > walks / 2);  // wandering walks do get shorter
}

TEST_CASE("the walk limit bounds the moves of every ant once a path is known", "[large][walk_limit]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {});
  const aco::NodeId start = graph.node({3, 3}), goal = graph.node({44, 40});
  auto run = [&](int iterations, double limit) {
    test::Baseline b;
    auto backtrack = test::make<aco::DeadlockPolicy>("deadlock", "backtrack");
    aco::ColonyStrategies p = b.pipeline();
    p.deadlock = backtrack.get();
    aco::ColonySettings s;
    s.ants = 20;
    s.iterations = iterations;
    s.beta = 1;  // wandering ants
    s.walk_limit = limit;
    return aco::run_colony(graph, start, goal, p, s);
  };
  const auto first = run(1, 0.0);
  const auto unlimited = run(10, 0.0);
  const auto limited = run(10, 1.5);
  REQUIRE(first.solved);
  // Iteration 1 has no limit (no path known yet); after it, at most ceil(1.5 x the first best's
  // steps) moves per ant, and the best only gets shorter.
  const auto per_ant = static_cast<std::uint64_t>(std::ceil(1.5 * double(first.path.size() - 1)));
  CHECK(limited.ant_steps <= first.ant_steps + 9 * 20 * per_ant);
  CHECK(limited.ant_steps < unlimited.ant_steps);
  CHECK(limited.solved);
}

TEST_CASE("the large-map options give bit-identical results for any thread count", "[large][determinism]") {
  const auto map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  const aco::Graph graph = aco::build_graph(*map, {});
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (const auto& [bidirectional, band_search] : {std::pair{false, 0}, {true, 0}, {false, 3}, {true, 3}}) {
    const aco::PipelineSpec spec =
        test::pipeline({{"heuristic", "progress"}, {"update", "acs"}, {"deadlock", "backtrack"}});
    aco::ColonySettings s;
    s.ants = 30;
    s.iterations = 15;
    s.beta = 3;
    s.seed = 3;
    s.fill_dead_ends = true;
    s.local_search = aco::LocalSearch::straighten;
    s.walk_limit = 2;
    s.bidirectional = bidirectional;
    s.band_search = band_search;  // aco::BandSearch
    std::vector<aco::ColonyResult> results;
    for (int threads : {1, 2, 4}) {
      const auto pipeline = aco::instantiate(test::plugins(), spec);
      tbb::task_arena arena(threads);
      arena.execute([&] {
        results.push_back(
            aco::run_pipeline(test::plugins(), spec, pipeline, graph, graph.node({1, 10}), graph.node({46, 30}), s));
      });
    }
    REQUIRE(results[0].solved);
    for (std::size_t i = 1; i < results.size(); ++i) test::check_same_run(results[i], results[0]);
  }
}

namespace {

// A heuristic as the engine saw it before updates by node: the whole table every iteration (or
// once, for one that does not vary).
class WholeTableEachIteration final : public aco::Heuristic {
 public:
  explicit WholeTableEachIteration(aco::Heuristic& inner) : inner_(inner) {}
  void compute(const aco::Context& c, std::span<double> eta) override { inner_.compute(c, eta); }
  void compute_powered(const aco::Context& c, std::span<double> eta_beta) override {
    inner_.compute_powered(c, eta_beta);
  }
  void begin_run(const aco::Context& c) override { inner_.begin_run(c); }
  aco::HeuristicSpecs specs() const override { return {.varies_by_iteration = inner_.specs().varies_by_iteration}; }

 private:
  aco::Heuristic& inner_;
};

}  // namespace

TEST_CASE("heuristics updated or computed node by node give the runs of a whole table, for any thread count",
          "[large][determinism][adaptive][potential_field][progress]") {
  const auto map = aco::load_map(test::data_dir() / "maps/generated/room64-8-s1.map");
  const aco::Graph graph = aco::build_graph(*map, {});
  const aco::NodeId start = graph.node({62, 1}), goal = graph.node({56, 20});
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> heuristics = {
      {"adaptive", {{"fade", "exponent"}}},
      {"adaptive", {{"fade", "factor"}}},
      {"potential_field", {}},
      {"progress", {}}};  // computed once per node, when an ant first stands on it
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 2);
  for (const auto& [name, params] : heuristics) {
    INFO(name << (params.empty() ? "" : " fade=" + params.begin()->second));
    auto run = [&](bool by_node, int threads) {
      test::Baseline b;
      auto heuristic = test::make<aco::Heuristic>("heuristic", name, params);
      REQUIRE(heuristic->specs().updates_by_node);
      WholeTableEachIteration whole(*heuristic);
      auto backtrack = test::make<aco::DeadlockPolicy>("deadlock", "backtrack");
      aco::ColonyStrategies p = b.pipeline();
      p.heuristic = by_node ? heuristic.get() : &whole;
      p.deadlock = backtrack.get();
      aco::ColonySettings s;
      s.ants = 10;
      s.iterations = 25;
      s.beta = 3.5;  // not a whole number: the pow() paths too
      aco::ColonyResult result;
      tbb::task_arena arena(threads);
      arena.execute([&] { result = aco::run_colony(graph, start, goal, p, s); });
      return result;
    };
    const auto reference = run(false, 1);
    REQUIRE(reference.solved);
    for (int threads : {1, 2}) {
      INFO(threads << " threads");
      test::check_same_run(run(true, threads), reference);
    }
  }
}
