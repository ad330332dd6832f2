// The colony's null models (docs/learning.md): what each twin keeps and drops, checked on runs; and
// explorer ants, the restart twin's kind of walk inside a learning colony.
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <catch2/catch.hpp>
#include <sqlite3.h>

#include "aco/engine/colony.hpp"
#include "aco/engine/map_io.hpp"
#include "acobench_support.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

// Counts the calls the engine makes to an update rule, then hands them on.
class CountingUpdate final : public aco::PheromoneUpdate {
 public:
  explicit CountingUpdate(aco::PheromoneUpdate& inner) : inner_(inner) {}
  void begin_run(const aco::Context& c) override {
    ++begun;
    inner_.begin_run(c);
  }
  void start(const aco::Context& c, std::span<double> tau) override {
    ++starts;
    inner_.start(c, tau);
  }
  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    ++updates;
    inner_.update(c, it, tau);
  }
  int begun = 0;
  int starts = 0;
  int updates = 0;

 private:
  aco::PheromoneUpdate& inner_;
};

// A pipeline of named plugins (defaults), kept alive with the test.
struct Strategies {
  Strategies(const std::string& init_name, const std::string& heuristic_name, const std::string& update_name,
             const std::string& deadlock_name)
      : init(test::make<aco::PheromoneInit>("init", init_name)),
        heuristic(test::make<aco::Heuristic>("heuristic", heuristic_name)),
        update(test::make<aco::PheromoneUpdate>("update", update_name)),
        deadlock(test::make<aco::DeadlockPolicy>("deadlock", deadlock_name)),
        counting(*update) {}
  aco::ColonyStrategies pipeline() { return {init.get(), heuristic.get(), &counting, deadlock.get()}; }
  std::unique_ptr<aco::PheromoneInit> init;
  std::unique_ptr<aco::Heuristic> heuristic;
  std::unique_ptr<aco::PheromoneUpdate> update;
  std::unique_ptr<aco::DeadlockPolicy> deadlock;
  CountingUpdate counting;
};

struct Arena {
  std::unique_ptr<aco::Map> map = aco::load_map(test::data_dir() / "maps/movingai/arena.map");
  aco::Graph graph = aco::build_graph(*map, {});
  aco::NodeId start = graph.node({3, 3});
  aco::NodeId goal = graph.node({44, 40});
};

aco::ColonySettings twin_settings(aco::NullModel model) {
  aco::ColonySettings s;
  s.ants = 8;
  s.iterations = 12;
  s.beta = 3;
  s.seed = 5;
  s.walk_limit = 4;
  s.local_search = aco::LocalSearch::straighten;
  s.null_model = model;
  return s;
}

// Two runs of the same plugins (uniform, progress, `update`, backtrack) that must walk the same
// walks, bit for bit, with q0 0 and 0.7: checked, and returned.
struct SameWalks {
  aco::ColonyResult first, second;
  int second_updates = 0;  // update() calls in the second run
};
std::vector<SameWalks> same_walks(aco::ColonySettings first, aco::ColonySettings second, const char* update) {
  Arena a;
  std::vector<SameWalks> runs;
  for (double q0 : {0.0, 0.7}) {
    first.q0 = second.q0 = q0;
    Strategies p("uniform", "progress", update, "backtrack"), q("uniform", "progress", update, "backtrack");
    SameWalks& r = runs.emplace_back();
    r.first = aco::run_colony(a.graph, a.start, a.goal, p.pipeline(), first);
    r.second = aco::run_colony(a.graph, a.start, a.goal, q.pipeline(), second);
    r.second_updates = q.counting.updates;
    CHECK(r.first.path == r.second.path);
    CHECK(r.first.best_so_far == r.second.best_so_far);
    CHECK(r.first.iteration_best == r.second.iteration_best);
    CHECK(r.first.ant_steps == r.second.ant_steps);
  }
  return runs;
}

}  // namespace

TEST_CASE("the no-learning twin never changes the pheromone: no init, update or deadlock learning is used",
          "[colony][null-model]") {
  Arena a;
  const auto settings = twin_settings(aco::NullModel::no_learning);
  std::vector<aco::ColonyResult> runs;
  // Different init and update rules, and a deadlock policy that changes the pheromone and
  // forbids nodes after every iteration: the twin of each is the same run.
  for (const auto& [init, update, deadlock] :
       {std::tuple{"uniform", "ant_system", "backtrack"}, std::tuple{"potential_field", "max_min", "backtrack"},
        std::tuple{"obstacle_density", "acs", "backtrack_penalty"}, std::tuple{"uniform", "gaussian", "discard"},
        std::tuple{"fireworks", "wolf_pack", "clear_and_tabu"}}) {
    Strategies p(init, "progress", update, deadlock);
    runs.push_back(aco::run_colony(a.graph, a.start, a.goal, p.pipeline(), settings));
    CHECK(p.counting.begun == 0);
    CHECK(p.counting.starts == 0);
    CHECK(p.counting.updates == 0);
    const auto& tau = runs.back().pheromone;
    CHECK(std::all_of(tau.begin(), tau.end(), [](double t) { return t == 1.0; }));
  }
  REQUIRE(runs[0].solved);
  CHECK(runs[0].iterations == settings.iterations);
  // A stuck ant backs off (backtrack) or dies (backtrack_penalty, discard): beyond that, the
  // pipeline's learning plugins make no difference to the twin.
  test::check_same_run(runs[1], runs[0]);
  test::check_same_run(runs[3], runs[2]);
}

TEST_CASE("the no-learning twin walks as the colony with alpha 0 does when nothing else carries over",
          "[colony][null-model]") {
  // With alpha 0 the colony's choice ignores tau (tau^0 = 1); the backtrack policy learns
  // nothing between iterations. So the two runs walk the same walks, bit for bit: the twin is
  // the colony with the pheromone ignored, and nothing else changed (walk limit included).
  auto twin = twin_settings(aco::NullModel::no_learning);
  auto alpha_zero = twin_settings(aco::NullModel::none);
  alpha_zero.alpha = 0.0;
  for (const SameWalks& runs : same_walks(twin, alpha_zero, "acs")) {
    CHECK(runs.second_updates == alpha_zero.iterations);  // the colony did learn, and ignored it
    CHECK(runs.second.pheromone != runs.first.pheromone);
  }
}

TEST_CASE("the restart twin's walks are independent: the same result however they are split into iterations",
          "[colony][null-model]") {
  Arena a;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 4);
  for (bool bidirectional : {false, true}) {
    std::vector<aco::ColonyResult> runs;
    for (const auto& [ants, iterations, threads] :
         {std::tuple{6, 5, 1}, std::tuple{30, 1, 2}, std::tuple{1, 30, 1}, std::tuple{10, 3, 4}, std::tuple{6, 5, 2}}) {
      auto s = twin_settings(aco::NullModel::restarts);
      s.ants = ants;
      s.iterations = iterations;
      s.bidirectional = bidirectional;
      Strategies p("uniform", "progress", "acs", "backtrack"), back("uniform", "progress", "acs", "backtrack");
      const aco::ColonyStrategies backward = back.pipeline();
      tbb::task_arena arena(threads);
      arena.execute([&] { runs.push_back(aco::run_colony(a.graph, a.start, a.goal, p.pipeline(), s, &backward)); });
      CHECK(p.counting.updates == 0);
      CHECK(runs.back().ant_steps > 0);
    }
    REQUIRE(runs[0].solved);
    for (std::size_t i = 1; i < runs.size(); ++i) {
      CAPTURE(bidirectional, i);
      CHECK(runs[i].path == runs[0].path);
      CHECK(runs[i].length == runs[0].length);
      CHECK(runs[i].ant_steps == runs[0].ant_steps);
      CHECK(runs[i].best_so_far.back() == runs[0].best_so_far.back());
    }
    test::check_same_run(runs[4], runs[0]);  // same split, other thread count: everything equal
  }
}

TEST_CASE("the restart twin's walks see the initial pheromone, as the colony's first iteration does",
          "[colony][null-model]") {
  Arena a;
  auto colony = twin_settings(aco::NullModel::none);
  auto restarts = twin_settings(aco::NullModel::restarts);
  Strategies p("potential_field", "progress", "acs", "backtrack"), q("potential_field", "progress", "acs", "backtrack");
  const auto c = aco::run_colony(a.graph, a.start, a.goal, p.pipeline(), colony);
  const auto r = aco::run_colony(a.graph, a.start, a.goal, q.pipeline(), restarts);
  // The same first walks (same streams, no walk limit yet in the colony's first iteration)...
  CHECK(r.iteration_best.front() == c.iteration_best.front());
  CHECK(r.arrived.front() == c.arrived.front());
  // ... and the twin's field stays the one both started from: the init's, rescaled by ACS's start().
  Strategies fresh("potential_field", "progress", "acs", "backtrack");
  std::vector<double> initial(static_cast<std::size_t>(a.graph.num_edges()));
  aco::Context context = test::context(a.graph, {3, 3}, {44, 40}, 0, restarts.iterations);
  context.ants = restarts.ants;
  context.beta = restarts.beta;
  context.seed = restarts.seed;
  fresh.init->initialize(context, initial);
  fresh.update->start(context, initial);
  CHECK(r.pheromone == initial);
  CHECK(q.counting.begun == 1);
  CHECK(q.counting.starts == 1);
  CHECK(q.counting.updates == 0);
  CHECK(c.pheromone != initial);
}

TEST_CASE("both twins are bit-identical for any thread count", "[colony][null-model][determinism]") {
  Arena a;
  for (auto model : {aco::NullModel::no_learning, aco::NullModel::restarts})
    test::run_on_thread_counts(a.graph, a.start, a.goal, twin_settings(model),
                               {"uniform", "adaptive", "max_min", "backtrack"});
}

TEST_CASE("acoplan runs either twin with --null-model and records it", "[acoplan][null-model]") {
  const auto map = (test::data_dir() / "maps/classic20/map2.txt").string();
  for (const std::string model : {"no-learning", "restarts"}) {
    const auto r = test::acoplan(
        {"--map", map, "--start", "0,0", "--goal", "19,19", "--iterations", "5", "--null-model", model, "--json"});
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Contains("\"null-model\":\"" + model + "\""));
    CHECK_THAT(r.out, Contains("\"solved\":true"));
  }
  const auto bad = test::acoplan({"--map", map, "--start", "0,0", "--goal", "19,19", "--null-model", "restart"});
  CHECK(bad.exit_code != 0);
  CHECK_THAT(bad.err, Contains("null-model") && Contains("no-learning"));
}

TEST_CASE("an experiment's null-models key adds each named colony configuration's two twins",
          "[acobench][null-model]") {
  using test::acobench_helpers::kSmall;
  using test::acobench_helpers::load;
  const auto all = load(std::string(kSmall) + "null-models: true\n");
  REQUIRE(all.configurations.size() == 4 * 3);
  CHECK(all.configurations[4].name == "AS (no learning)");
  CHECK(all.configurations[5].name == "AS (restarts)");
  CHECK(all.configurations[11].name == "beta=7 (restarts)");
  CHECK(all.configurations[5].run->colony.null_model == aco::NullModel::restarts);
  CHECK(all.configurations[4].run->colony.null_model == aco::NullModel::no_learning);
  // A twin is its subject with one key more.
  auto keys = all.configurations[7].keys;
  CHECK(keys.at("null-model") == "restarts");
  keys.erase("null-model");
  CHECK(keys == all.configurations[1].keys);

  const auto named = load(std::string(kSmall) + "null-models: [ACS]\n");
  REQUIRE(named.configurations.size() == 4 + 2);
  CHECK(named.configurations[4].name == "ACS (no learning)");
  CHECK(load(std::string(kSmall) + "null-models: false\n").configurations.size() == 4);

  CHECK_THROWS_WITH(load(std::string(kSmall) + "null-models: [ACZ]\n"),
                    Contains("experiment.yaml:") && Contains("'ACZ' is not a configuration"));
  CHECK_THROWS_WITH(load(std::string(kSmall) + "null-models: maybe\n"), Contains("null-models"));
  CHECK_THROWS_WITH(load(std::string(kSmall) + "null-models: {ACS: 1}\n"), Contains("true, false or a list"));
  std::string with_astar = kSmall;
  with_astar.replace(with_astar.find("    q0: 0.7\n"), 12, "    q0: 0.7\n  - {name: exact, planner: astar}\n");
  CHECK(load(with_astar + "null-models: true\n").configurations.size() == 5 + 4 * 2);  // A* has no twins
  CHECK_THROWS_WITH(load(with_astar + "null-models: [exact]\n"), Contains("only a colony has twins"));
  std::string with_twin = kSmall;
  with_twin.replace(with_twin.find("    q0: 0.7\n"), 12, "    q0: 0.7\n  - {name: hand-made, null-model: restarts}\n");
  CHECK_THROWS_WITH(load(with_twin + "null-models: [hand-made]\n"), Contains("is itself a null model"));
  CHECK(load(with_twin + "null-models: true\n").configurations.size() == 5 + 4 * 2);  // the hand-made one has none
}

TEST_CASE("the report asks of every configuration with twins whether its pheromone matters",
          "[acobench][null-model][report]") {
  using namespace test::acobench_helpers;
  // ACS's twins from null-models, and the baseline's no-learning twin written by hand: the report
  // finds a twin by its settings, whoever wrote it.
  const auto file = experiment(R"(name: twins
seed: 3
repetitions: 4
problems:
  - map: {MAP1}
    start: [0, 0]
    goal: [19, 19]
  - {scen: {ARENA}, count: 2}
settings: {preset: ant-system, ants: 10, iterations: 10, beta: 3}
baseline: {name: AS}
configurations:
  - {name: ACS, update: acs, q0: 0.7}
  - {name: AS by hand, null-model: no-learning}
null-models: [ACS]
)");
  const auto db = file.parent_path() / "twins.db";
  const auto run = run_acobench({"run", file.string(), "--db", db.string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto out = file.parent_path() / "report";
  REQUIRE(run_acobench({"report", db.string(), "--out", out.string()}).exit_code == 0);
  const std::string md = file_bytes(out / "report.md");
  CHECK_THAT(md, Contains("## Does the pheromone matter?"));
  CHECK_THAT(md, Contains("| AS | no-learning | 12/12 vs 12/12 |"));
  CHECK_THAT(md, Contains("| ACS | no-learning | 12/12 vs 12/12 |"));
  CHECK_THAT(md, Contains("| ACS | restarts | 12/12 vs 12/12 |"));
  CHECK_THAT(md, !Contains("| AS | restarts |"));
  CHECK_THAT(file_bytes(out / "report.html"), Contains("Does the pheromone matter?"));

  // A study stopped part-way: the restart twin has not run map1 yet. Its comparison pools the
  // two arena problems only, on both sides.
  sqlite3* handle = nullptr;
  REQUIRE(sqlite3_open(db.string().c_str(), &handle) == SQLITE_OK);
  REQUIRE(
      sqlite3_exec(handle,
                   "DELETE FROM runs WHERE plannerid = (SELECT id FROM plannerConfigs WHERE name = 'ACS (restarts)') "
                   "AND experimentid = (SELECT id FROM experiments WHERE name = 'map1')",
                   nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(handle);
  const auto partial = file.parent_path() / "partial";
  REQUIRE(run_acobench({"report", db.string(), "--out", partial.string()}).exit_code == 0);
  const std::string partial_md = file_bytes(partial / "report.md");
  CHECK_THAT(partial_md, Contains("| ACS | restarts | 8/8 vs 8/8 |"));
  CHECK_THAT(partial_md, Contains("| ACS | no-learning | 12/12 vs 12/12 |"));
}

// Explorer ants (ColonySettings::explorers): the restart twin's kind of walk inside a colony that
// learns from them.
TEST_CASE("a colony of explorers walks as the colony with alpha 0 and no walk limit does", "[colony][explorers]") {
  // An explorer's choice ignores tau, as tau^0 = 1 does, and no walk limit stops it; the backtrack
  // policy learns nothing between iterations. So the walks are the same, bit for bit.
  auto explorers = twin_settings(aco::NullModel::none);
  explorers.explorers = 1.0;
  explorers.band_search = 4;
  auto alpha_zero = explorers;
  alpha_zero.explorers = 0.0;
  alpha_zero.alpha = 0.0;
  alpha_zero.walk_limit = 0.0;
  for (const SameWalks& runs : same_walks(explorers, alpha_zero, "max_min")) CHECK(runs.first.solved);
}

TEST_CASE("explorers change the walks, and the run stays the same for any thread count",
          "[colony][explorers][determinism]") {
  Arena a;
  auto mixed = twin_settings(aco::NullModel::none);
  mixed.band_search = 4;
  auto plain = mixed;
  mixed.explorers = 0.25;  // the last 2 of 8 ants
  Strategies p("uniform", "progress", "max_min", "backtrack"), q("uniform", "progress", "max_min", "backtrack");
  const auto with = aco::run_colony(a.graph, a.start, a.goal, p.pipeline(), mixed);
  const auto without = aco::run_colony(a.graph, a.start, a.goal, q.pipeline(), plain);
  REQUIRE(with.solved);
  CHECK(with.ant_steps != without.ant_steps);
  test::run_on_thread_counts(a.graph, a.start, a.goal, mixed, {"uniform", "progress", "max_min", "backtrack"});
}

TEST_CASE("acoplan takes --explorers as a share of the ants and refuses one outside 0..1", "[acoplan][explorers]") {
  const auto map = (test::data_dir() / "maps/classic20/map2.txt").string();
  const auto ok = test::acoplan(
      {"--map", map, "--start", "0,0", "--goal", "19,19", "--explorers", "0.2", "--ants", "10", "--iterations", "5"});
  CHECK(ok.exit_code == 0);
  const auto bad = test::acoplan({"--map", map, "--start", "0,0", "--goal", "19,19", "--explorers", "1.5"});
  CHECK(bad.exit_code != 0);
  CHECK_THAT(bad.err, Contains("explorers") && Contains("[0, 1]"));
}
