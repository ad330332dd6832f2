// Solution quality on the classic map and Moving AI arena. Runs are deterministic for their
// seeds, so these are regression tests of the algorithms, not statistical gambles.
#include <catch2/catch.hpp>
#include <fstream>

#include "aco/astar.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/engine/pipeline.hpp"
#include "support.hpp"

namespace {

struct Problem {
  aco::OccupancyGrid map;
  aco::Graph graph;
  Problem(aco::OccupancyGrid m, aco::GraphOptions options) : map(std::move(m)), graph(aco::build_graph(map, options)) {}
};

// acs runs with its q0 of 0.7 (a colony setting).
aco::ColonyResult plan(const Problem& p, aco::Cell start, aco::Cell goal, const std::string& update,
                       std::map<std::string, std::string> params, std::uint64_t seed) {
  aco::Keys keys{{"update", update}};
  for (const auto& [name, value] : params) keys["update." + name] = value;
  const auto pipeline = aco::instantiate(test::plugins(), test::pipeline(keys));
  aco::ColonySettings s;  // 50 ants, 100 iterations, alpha 1, beta 7
  s.seed = seed;
  if (update == "acs") s.q0 = 0.7;
  return aco::run_colony(p.graph, p.graph.node(start), p.graph.node(goal), pipeline.strategies(), s);
}

constexpr double kMap1CornerCutting = 34.3848;

}  // namespace

TEST_CASE("ant_system on classic map1 ends within 3 % of the optimum on average", "[quality]") {
  const Problem p(test::classic_map(1), {aco::Neighbourhood::eight, true});
  double sum = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto r = plan(p, {0, 0}, {19, 19}, "ant_system", {{"rho", "0.3"}, {"q", "1"}}, seed);
    REQUIRE(r.solved);
    sum += r.length;
  }
  const double mean = sum / 20;
  INFO("mean best length " << mean);
  CHECK(mean <= kMap1CornerCutting * 1.03);
  CHECK(mean >= kMap1CornerCutting - 1e-4);
}

TEST_CASE("max_min and acs reach the optimum of classic map1 in at least 18 of 20 seeds", "[quality]") {
  const Problem p(test::classic_map(1), {aco::Neighbourhood::eight, true});
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> variants{
      {"max_min", {}}, {"acs", {{"rho", "0.3"}, {"q", "1"}}}};
  for (const auto& [update, params] : variants) {
    int optimal = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed)
      optimal += plan(p, {0, 0}, {19, 19}, update, params, seed).length < kMap1CornerCutting + 1e-4;
    INFO(update << " reached the optimum in " << optimal << " of 20 seeds");
    CHECK(optimal >= 18);
  }
}

TEST_CASE("default settings solve sampled arena scenarios within 5 % of the optimum on average", "[quality]") {
  const auto scenarios = aco::load_scenarios(test::data_dir() / "maps/movingai/arena.map.scen");
  std::ifstream in(test::data_dir() / "maps/movingai/arena.map");
  const Problem p(aco::read_movingai_map(in, "arena"), {});
  double gap = 0;
  int sampled = 0;
  for (std::size_t i = 0; i < scenarios.size(); i += 8, ++sampled) {
    const auto& s = scenarios[i];
    const auto r = plan(p, s.start, s.goal, "ant_system", {}, 1);
    INFO("scenario " << i);
    REQUIRE(r.solved);
    CHECK(r.length >= s.optimal_length * (1 - 1e-3));
    gap += (r.length - s.optimal_length) / s.optimal_length;
  }
  INFO("mean gap " << 100 * gap / sampled << " % over " << sampled << " scenarios");
  CHECK(gap / sampled <= 0.05);
}
