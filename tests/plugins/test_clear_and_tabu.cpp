#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "aco/engine/pipeline.hpp"
#include "support.hpp"

TEST_CASE("clear_and_tabu: the dead ant's walk is cleared and its dead end forbidden", "[plugin][clear_and_tabu]") {
  const auto map = test::grid({
      "......",
      ".####.",
      ".#..#.",
      ".#.##.",
      "......",
  });
  const aco::Graph g = aco::build_graph(map, {});
  const auto c = test::context(g, {0, 0}, {5, 4});
  auto policy = test::make<aco::DeadlockPolicy>("deadlock", "clear_and_tabu");
  policy->begin_run(c);
  // A walk that ended in the pocket (2,2)-(3,2)-(2,3), whose only opening is (2,4) below.
  aco::Ant dead = test::ant(g, {{3, 2}, {2, 2}, {2, 3}});
  dead.arrived = false;
  aco::Ant alive = test::ant(g, {{0, 0}, {1, 0}, {2, 0}});
  std::vector<double> tau(g.num_edges(), 3.0);
  std::vector<std::uint8_t> forbidden(g.num_nodes(), 0);
  const std::vector<aco::Ant> ants{dead, alive};
  CHECK(policy->on_stuck(c, dead.nodes) == 0);
  aco::Trail tau_trail(tau);
  policy->after_iteration(c, {ants, nullptr, nullptr}, tau_trail, forbidden);
  for (aco::EdgeId e : dead.edges) CHECK(tau[e] == 0.0);
  for (aco::EdgeId e : alive.edges) CHECK(tau[e] == 3.0);
  CHECK(forbidden[g.node({2, 3})] == 1);
  int count = 0;
  for (auto f : forbidden) count += f;
  CHECK(count == 1);
}

TEST_CASE("clear_and_tabu never forbids a node the goal depends on", "[plugin][clear_and_tabu]") {
  // A one-cell corridor at (3,1): an ant stuck there (walled in by its own trail) must not close it.
  const auto map = test::grid({
      "...#...",
      ".......",
      "...#...",
  });
  const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::four, false});
  const auto c = test::context(g, {0, 1}, {6, 1});
  auto policy = test::make<aco::DeadlockPolicy>("deadlock", "clear_and_tabu", {{"keep", "0.5"}});
  policy->begin_run(c);
  aco::Ant dead = test::ant(g, {{0, 1}, {1, 1}, {2, 1}, {3, 1}});
  dead.arrived = false;
  std::vector<double> tau(g.num_edges(), 3.0);
  std::vector<std::uint8_t> forbidden(g.num_nodes(), 0);
  const std::vector<aco::Ant> ants{dead};
  aco::Trail tau_trail(tau);
  policy->after_iteration(c, {ants, nullptr, nullptr}, tau_trail, forbidden);
  CHECK(forbidden[g.node({3, 1})] == 0);
  for (aco::EdgeId e : dead.edges) CHECK(tau[e] == 1.5);  // keep = 0.5
}

namespace {
// Forwards to the plugin and records the forbidden set after every iteration.
class Watch final : public aco::DeadlockPolicy {
 public:
  explicit Watch(aco::DeadlockPolicy& inner) : inner_(inner) {}
  void begin_run(const aco::Context& c) override { inner_.begin_run(c); }
  int on_stuck(const aco::Context& c, std::span<const aco::NodeId> walk) const override {
    return inner_.on_stuck(c, walk);
  }
  void after_iteration(const aco::Context& c, const aco::Iteration& it, aco::Trail& trail,
                       std::vector<std::uint8_t>& forbidden) override {
    for (const aco::Ant& ant : it.ants)
      for (aco::NodeId n : ant.nodes) entered_after_forbidden += forbidden[n];
    inner_.after_iteration(c, it, trail, forbidden);
    forbidden_count = 0;
    for (auto f : forbidden) forbidden_count += f;
  }
  int entered_after_forbidden = 0;
  int forbidden_count = 0;

 private:
  aco::DeadlockPolicy& inner_;
};
}  // namespace

TEST_CASE("with clear_and_tabu no ant ever enters a tabu node", "[plugin][clear_and_tabu]") {
  // Traps on the way to the goal make ants die and nodes become tabu.
  const auto map = test::grid({
      "............",
      ".###..###...",
      ".#.#..#.#...",
      ".#....#.....",
      "............",
      "..###..###..",
      "..#.#..#.#..",
      "............",
  });
  const aco::Graph g = aco::build_graph(map, {});
  const aco::PipelineSpec spec = test::pipeline({{"deadlock", "clear_and_tabu"}});
  int tabu_total = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    auto p = aco::instantiate(test::plugins(), spec);
    Watch watch(*p.deadlock);
    aco::ColonyStrategies colony = p.strategies();
    colony.deadlock = &watch;
    aco::ColonySettings s;
    s.seed = seed;
    s.iterations = 40;
    s.beta = 3;  // weaker pull to the goal: more ants wander into traps
    const auto r = aco::run_colony(g, g.node({0, 0}), g.node({11, 7}), colony, s);
    CHECK(r.solved);
    CHECK(watch.entered_after_forbidden == 0);
    tabu_total += watch.forbidden_count;
  }
  CHECK(tabu_total > 0);  // the test exercised the tabu set
}

// The plugin decides reachability through a witness path instead of one search per dead ant;
// its decisions must be exactly those of the search: forbid a dead end iff the goal stays
// reachable from the start without it (and without everything forbidden before).
TEST_CASE("clear_and_tabu forbids exactly the nodes a search per dead ant would", "[plugin][clear_and_tabu]") {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 40; ++trial) {
    const auto map = test::random_grid(rng, 12, 9);
    const aco::Graph g = aco::build_graph(map, {aco::Neighbourhood::eight, false});
    std::vector<aco::NodeId> open;
    for (aco::NodeId n = 0; n < g.num_nodes(); ++n)
      if (g.passable(n)) open.push_back(n);
    if (open.size() < 3) continue;
    const aco::NodeId start = open.front(), goal = open.back();
    if (!aco::reachable(g, start, goal)) continue;
    const auto c = test::context(g, g.cell(start), g.cell(goal));
    auto policy = test::make<aco::DeadlockPolicy>("deadlock", "clear_and_tabu");
    policy->begin_run(c);
    std::vector<std::uint8_t> forbidden(g.num_nodes(), 0), expected(g.num_nodes(), 0);
    std::vector<double> tau(g.num_edges(), 1.0);
    for (int iteration = 0; iteration < 6; ++iteration) {
      std::vector<aco::Ant> ants(5);
      for (auto& a : ants) a.nodes = {start, open[rng() % open.size()]};
      aco::Trail tau_trail(tau);
      policy->after_iteration(c, {ants, nullptr, nullptr}, tau_trail, forbidden);
      for (const auto& a : ants) {
        const aco::NodeId n = a.nodes.back();
        if (n == start || expected[n]) continue;
        // Reference: a breadth-first search of the graph without the node and the tabu set
        // (not of a map with those cells blocked: a blocked cell would also remove the diagonal
        // moves beside it).
        std::vector<std::uint8_t> seen = expected;
        seen[n] = 1;
        std::vector<aco::NodeId> queue{start};
        seen[start] = 1;
        for (std::size_t head = 0; head < queue.size(); ++head)
          for (aco::EdgeId e = g.edges_begin(queue[head]); e < g.edges_end(queue[head]); ++e)
            if (!seen[g.targets[e]]) seen[g.targets[e]] = 1, queue.push_back(g.targets[e]);
        const bool goal_reached = std::find(queue.begin(), queue.end(), goal) != queue.end();
        if (goal_reached) expected[n] = 1;
      }
      REQUIRE(forbidden == expected);
    }
  }
}
