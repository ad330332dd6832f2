// acosim: scenario files, the simulation loop (local planner, sensing, replanning), bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <csignal>
#include <fstream>

#include "aco/simulation/batch.hpp"
#include "aco/simulation/simulation.hpp"
#include "aco/thread_limit.hpp"
#include "aco/error.hpp"
#include "aco/drawing/svg.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

// A scenario file beside two maps: open (12 x 5, empty) and two (10 x 5, a block with a
// corridor above and one below it).
std::filesystem::path scenario(const std::string& yaml) {
  const auto file = test::temp_file("scenario.yaml", yaml);
  std::ofstream open(file.parent_path() / "open.txt");
  for (int y = 0; y < 5; ++y) open << "0 0 0 0 0 0 0 0 0 0 0 0\n";
  std::ofstream(file.parent_path() / "two.txt") << "0 0 0 0 0 0 0 0 0 0\n0 1 1 1 1 1 1 1 1 0\n0 1 1 1 1 1 1 1 1 0\n"
                                                   "0 1 1 1 1 1 1 1 1 0\n0 0 0 0 0 0 0 0 0 0\n";
  return file;
}

// The scenario of `file`, driven with `changes` over its run keys.
aco::simulation::SimulationResult simulate(const std::filesystem::path& file, const aco::Keys& changes = {}) {
  aco::simulation::Scenario s = aco::simulation::load_scenario(file, test::plugins());
  if (!changes.empty()) s = aco::simulation::with_run_keys(s, {changes, {}}, test::plugins());
  return aco::simulation::simulate(s, test::plugins());
}

}  // namespace

TEST_CASE("acosim: dwa passes an unknown cell on the straight path, blind tracking hits it", "[acosim]") {
  const auto file = scenario("run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa}\nunknown: [[6, 2]]\n");
  const auto dwa = simulate(file);
  CHECK(dwa.reached);
  CHECK(dwa.collisions == 0);
  CHECK(dwa.min_clearance > 0.0);
  CHECK(dwa.sensed.size() == 1);
  CHECK(dwa.frames.size() == static_cast<std::size_t>(dwa.steps) + 1);
  const auto blind = simulate(file, {{"local", "track"}});
  CHECK_FALSE(blind.reached);
  CHECK(blind.outcome == "collision");
  CHECK(blind.collisions == 1);
  CHECK_THAT(blind.reason, Contains("the obstacle cell (6,2)"));

  // The same scenario gives the same run.
  const auto again = simulate(file);
  REQUIRE(again.frames.size() == dwa.frames.size());
  for (std::size_t i = 0; i < dwa.frames.size(); ++i) {
    CHECK(again.frames[i].robot.x == dwa.frames[i].robot.x);
    CHECK(again.frames[i].robot.y == dwa.frames[i].robot.y);
    CHECK(again.frames[i].robot.heading == dwa.frames[i].robot.heading);
  }
}

TEST_CASE("acosim: a blocked corridor makes the robot replan round the block", "[acosim]") {
  // From (0, 1) to (9, 1) the corridor above the block is the short way; an unknown cell closes it.
  const auto file = scenario("run: {map: two.txt, start: [0, 1], goal: [9, 1], local: dwa}\nunknown: [[5, 0]]\n");
  const auto r = simulate(file);
  CHECK(r.reached);
  CHECK(r.collisions == 0);
  CHECK(r.replans >= 1);
  REQUIRE(r.plans.size() == static_cast<std::size_t>(r.replans) + 1);
  // Whether a plan's polyline passes through the closed cell (5, 0).
  const auto through_closed_cell = [](const std::vector<Eigen::Vector2d>& plan) {
    const Eigen::Vector2d cell(5, 0);
    for (std::size_t i = 1; i < plan.size(); ++i) {
      const Eigen::Vector2d a = plan[i - 1], ab = plan[i] - plan[i - 1];
      const double t = std::clamp((cell - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      if ((a + t * ab - cell).norm() < 0.5) return true;
    }
    return false;
  };
  CHECK(through_closed_cell(r.plans.front()));
  CHECK_FALSE(through_closed_cell(r.plans.back()));
}

TEST_CASE("acosim: following the path (dwa follow) gets through a one-cell door the paper's heading term stalls at",
          "[acosim]") {
  // A wall at x = 5 with one free cell at its top; the path runs along the bottom, up to the door
  // and back down. Heading for the turning points, the robot arrives beside the door and stalls.
  const auto file = test::temp_file("door.yaml", "");
  std::ofstream map(file.parent_path() / "door.txt");
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 12; ++x) map << (x == 5 && y != 1 ? "1" : "0") << (x == 11 ? "\n" : " ");
  map.close();
  const auto run = [&](const std::string& follow) {
    std::ofstream(file) << "run: {map: door.txt, start: [0, 8], goal: [11, 8], corner-cutting: false, smoother: prune, "
                           "smoother.clearance: 0.4, local: dwa, local.follow: "
                        << follow << "}\n";
    return simulate(file);
  };
  const auto paper = run("0");
  CHECK_FALSE(paper.reached);
  CHECK(paper.outcome == "stuck");
  const auto follow = run("0.5");
  CHECK(follow.reached);
  CHECK(follow.collisions == 0);
  CHECK(follow.replans == 0);
}

TEST_CASE("acosim: a moving obstacle is sensed and passed", "[acosim]") {
  const auto file = scenario(
      "run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa}\n"
      "moving:\n  - {position: [11, 0.5], velocity: [-0.2, 0], radius: 0.3}\n");
  const auto r = simulate(file);
  CHECK(r.reached);
  CHECK(r.collisions == 0);
  REQUIRE(r.frames.back().moving.size() == 1);
  CHECK(r.frames.back().moving[0].x() == Approx(11 - 0.2 * r.time));
}

namespace {

// The number in `attribute="..."` of the first element of `svg` that holds `marker`.
double attribute_of(const std::string& svg, const std::string& marker, const std::string& attribute) {
  const auto at = svg.find(marker);
  REQUIRE(at != std::string::npos);
  const auto value = svg.find(attribute + "=\"", at);
  REQUIRE(value != std::string::npos);
  return std::stod(svg.substr(value + attribute.size() + 2));
}

}  // namespace

TEST_CASE("acosim's picture has start and goal marked and a legend beside the map for every line and mark",
          "[acosim][svg]") {
  const auto file = scenario(
      "run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa}\nunknown: [[6, 2]]\n"
      "moving:\n  - {position: [11, 0.5], velocity: [-0.2, 0], radius: 0.3}\n");
  const aco::simulation::Scenario s = aco::simulation::load_scenario(file, test::plugins());
  const aco::simulation::SimulationResult r = aco::simulation::simulate(s, test::plugins());
  const std::string svg = aco::simulation::render_svg(s, r);
  // Start and goal: a marker at the cell's centre (24 pixels per cell, 12 margin) and a word.
  CHECK(attribute_of(svg, "<g id=\"start\"", "cx") == 12 + 0.5 * 24);
  CHECK(attribute_of(svg, "<g id=\"start\"", "cy") == 12 + 2.5 * 24);
  CHECK(attribute_of(svg, "<g id=\"goal\"", "cx") == 12 + 11.5 * 24);
  CHECK_THAT(svg, Contains(">start</text></g>") && Contains(">goal</text></g>"));
  // The legend names what this run drew: one replan (the unknown cell blocks the straight
  // path), no collision.
  REQUIRE(r.plans.size() == 2);
  const std::string legend = svg.substr(svg.find("<g id=\"legend\""));
  for (const char* entry :
       {">start<", ">goal<", ">obstacle on the map<", ">obstacle the map did not show<", ">planned path<",
        ">replanned path (1)<", ">moving obstacle's track<", ">moving obstacle at the end<", ">driven trajectory<"})
    CHECK_THAT(legend, Contains(entry));
  CHECK_THAT(legend, !Contains("collision"));
  // Beside the map (12 wide), not over it, and inside the picture by the text width estimate.
  const double map_right = 12 + 12 * 24;
  const double legend_left = std::stod(legend.substr(legend.find("translate(") + 10));
  CHECK(legend_left > map_right);
  const double width = attribute_of(svg, "<svg", "width");
  CHECK(legend_left + 36 + aco::text_width("obstacle the map did not show", 13) <= width);
  CHECK_THAT(svg, Contains("viewBox=\"0 0 "));

  SECTION("a collision is marked where the robot stopped, and the legend says so") {
    const aco::simulation::Scenario blind =
        aco::simulation::with_run_keys(s, {{{"local", "track"}}, {}}, test::plugins());
    const aco::simulation::SimulationResult hit = aco::simulation::simulate(blind, test::plugins());
    REQUIRE(hit.collisions == 1);
    const std::string picture = aco::simulation::render_svg(blind, hit);
    CHECK_THAT(picture, Contains("<g id=\"collision\">") && Contains(">collision</text>"));
  }
}

TEST_CASE("acosim: bad scenarios are errors naming the file, the line and the key", "[acosim][bad-input]") {
  const auto error = [](const std::string& yaml) {
    try {
      aco::simulation::load_scenario(scenario(yaml), test::plugins());
    } catch (const aco::Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string run = "run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa}\n";
  CHECK_THAT(error("run: [unclosed\n"), Contains("scenario.yaml:") && Contains("malformed YAML"));
  CHECK_THAT(error(run + "unknown: [[0, 2]]\n"),
             Contains("scenario.yaml:2") && Contains("overlaps the robot at the start (0,2)"));
  CHECK_THAT(error(run + "unknown: [[40, 2]]\n"), Contains("outside the map"));
  CHECK_THAT(error(run + "moving:\n  - {position: [0.2, 2], radius: 0.3}\n"),
             Contains("scenario.yaml:3") && Contains("overlaps"));
  CHECK_THAT(error(run + "robot: {max-speed: 0}\n"), Contains("scenario.yaml:2") && Contains("max-speed"));
  CHECK_THAT(error(run + "robot: {max-accel: -1}\n"), Contains("max-accel"));
  CHECK_THAT(error(run + "robot: {max-sped: 1}\n"), Contains("max-speed"));  // the nearest key
  CHECK_THAT(error(run + "simulation: {period: 5}\n"), Contains("longer than the local planner's horizon 3 s"));
  CHECK_THAT(error("run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa, local.horizn: 2}\n"),
             Contains("scenario.yaml:1") && Contains("local.horizon"));
  CHECK_THAT(error("run: {map: open.txt, start: [0, 2]}\n"), Contains("'run' needs 'goal'"));
  CHECK_THAT(error(run + "obstacles: []\n"), Contains("unknown key 'obstacles'"));
  CHECK_THAT(error(run + "moving:\n  - {route: [[3, 3]], speed: 1}\n"), Contains("at least two points"));
  CHECK_THROWS_WITH(aco::simulation::load_scenario(std::filesystem::temp_directory_path(), test::plugins()),
                    Contains("is a directory, not a scenario file"));
  CHECK_THROWS_WITH(aco::simulation::load_scenario("/dev/zero", test::plugins()),
                    Contains("/dev/zero: not a regular file"));
}

// Boost.ProgramOptions' message for these never came back (aco/hosts/program_options_error.hpp).
TEST_CASE("acosim: '%' placeholders in its options are shown as typed", "[acosim][bad-input]") {
  const auto error = [](const std::vector<std::string>& args) {
    std::vector<std::string> argv{ACO_TEST_ACOSIM};
    argv.insert(argv.end(), args.begin(), args.end());
    const auto r = test::run(argv);
    CHECK(r.exit_code == 1);
    return r.err;
  };
  CHECK(error({"--batch", "%value%"}) == "acosim: error: the argument ('%value%') for option '--batch' is invalid\n");
  CHECK(error({"--thr=%value%x"}) == "acosim: error: the argument ('%value%x') for option '--threads' is invalid\n");
  // Other options are run keys, checked once the scenario is read.
  const std::string scenario = (test::data_dir() / "scenarios" / "paper003_static.yaml").string();
  CHECK_THAT(error({scenario, "--%canonical_option%"}),
             Contains("acosim: error: --%canonical_option%: unknown key '%canonical_option%'"));
}

TEST_CASE("acosim: every bundled scenario reaches the goal without a collision", "[acosim][slow]") {
  for (const char* name : {"paper003_static", "paper003_moving", "paper003_replan", "generated_room32",
                           "generated_random32", "generated_maze32"}) {
    INFO(name);
    const auto r = simulate(test::data_dir() / "scenarios" / (std::string(name) + ".yaml"));
    CHECK(r.reached);
    CHECK(r.collisions == 0);
    CHECK(r.min_clearance > 0.0);
  }
  // The replan scenario needs its replan; the moving one needs the prediction its file sets.
  CHECK(simulate(test::data_dir() / "scenarios/paper003_replan.yaml").replans >= 1);
  CHECK(simulate(test::data_dir() / "scenarios/paper003_moving.yaml", {{"local.predict", "false"}}).outcome ==
        "collision");
  // The DWA's defaults (follow 0.5, predict) get through a door where the paper's reading stops.
  CHECK(simulate(test::data_dir() / "scenarios/generated_room32.yaml",
                 {{"local.follow", "0"}, {"local.predict", "false"}})
            .outcome == "stuck");
}

TEST_CASE("acosim batch: variations depend on the seed only, results not on the thread count", "[acosim][slow]") {
  const auto file = scenario("run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa, local.predict: true}\n");
  const aco::simulation::Scenario base = aco::simulation::load_scenario(file, test::plugins());
  const auto a = aco::simulation::variations(base, 6, 5, test::plugins());
  const auto b = aco::simulation::variations(base, 6, 5, test::plugins());
  const auto other = aco::simulation::variations(base, 6, 6, test::plugins());
  REQUIRE(a.size() == 6);
  bool differs = false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CHECK(a[i].unknown == b[i].unknown);
    CHECK(!a[i].unknown.empty());
    CHECK(!a[i].moving.empty());
    differs = differs || a[i].unknown != other[i].unknown;
  }
  CHECK(differs);
  const auto run = [&](int threads) {
    const aco::ThreadLimit limit(threads);
    return aco::simulation::run_batch(a, test::plugins());
  };
  const auto one = run(1), two = run(2);
  CHECK(one.runs == 6);
  CHECK(one.reached == two.reached);
  CHECK(one.collisions == two.collisions);
  CHECK(one.replans == two.replans);
  CHECK(one.mean_time == two.mean_time);
  CHECK(one.mean_clearance == two.mean_clearance);
  CHECK(one.reached_with_collision == 0);
}

TEST_CASE("acosim batch: no variation seals the goal off", "[acosim]") {
  // A one-cell corridor: any unknown cell on it would leave no way to the goal.
  const auto file = scenario("run: {map: corridor.txt, start: [0, 1], goal: [11, 1], local: dwa}\n");
  std::ofstream(file.parent_path() / "corridor.txt") << "1 1 1 1 1 1 1 1 1 1 1 1\n0 0 0 0 0 0 0 0 0 0 0 0\n"
                                                        "1 1 1 1 1 1 1 1 1 1 1 1\n";
  const aco::simulation::Scenario base = aco::simulation::load_scenario(file, test::plugins());
  for (const auto& v : aco::simulation::variations(base, 10, 3, test::plugins())) {
    CHECK(v.unknown.empty());
    CHECK(!v.moving.empty());
  }
}

namespace {

// acosim with these arguments.
test::CommandResult acosim_run(const std::vector<std::string>& args) {
  std::vector<std::string> argv{ACO_TEST_ACOSIM};
  argv.insert(argv.end(), args.begin(), args.end());
  return test::run(argv);
}

}  // namespace

TEST_CASE("acosim --batch: worker processes give the in-process results, whatever the thread count",
          "[acosim][contain]") {
  const auto file = scenario("run: {map: two.txt, start: [0, 1], goal: [9, 1], local: dwa, local.predict: true}\n");
  const aco::simulation::Scenario base = aco::simulation::load_scenario(file, test::plugins());
  const auto in_process =
      aco::simulation::run_batch(aco::simulation::variations(base, 6, 5, test::plugins()), test::plugins());
  const std::vector<std::string> command{
      ACO_TEST_ACOSIM, "--variation-worker", file.string(), "--batch", "6", "--seed", "5"};
  for (const int lanes : {1, 2}) {
    INFO(lanes << " worker processes");
    const auto workers = aco::simulation::run_batch_in_workers(
        6, command, lanes, {},
        [](int k, const aco::simulation::SimulationResult& r) { FAIL("variation " << k << " failed: " << r.reason); });
    REQUIRE(workers.results.size() == in_process.results.size());
    for (std::size_t k = 0; k < workers.results.size(); ++k) {
      const auto &a = workers.results[k], &b = in_process.results[k];
      CHECK(a.reached == b.reached);
      CHECK(a.outcome == b.outcome);
      CHECK(a.reason == b.reason);
      CHECK(a.time == b.time);  // exact: doubles cross the processes bit for bit
      CHECK(a.distance == b.distance);
      CHECK(a.min_clearance == b.min_clearance);
      CHECK(a.collisions == b.collisions);
      CHECK(a.replans == b.replans);
      CHECK(a.steps == b.steps);
      CHECK(a.plans == b.plans);
      CHECK(a.sensed == b.sensed);
      CHECK(a.frames.empty());
    }
    CHECK(workers.outcomes == in_process.outcomes);
    CHECK(workers.mean_time == in_process.mean_time);
    CHECK(workers.mean_clearance == in_process.mean_clearance);
  }
  CHECK(in_process.replans > 0);  // the plans and sensed cells compared are more than the first

  // The command line: the same summary in worker processes on 1 or 2 lanes and in-process.
  const std::vector<std::string> batch{file.string(), "--batch", "6", "--seed", "5"};
  std::vector<std::string> outputs;
  for (const auto& more :
       std::vector<std::vector<std::string>>{{"--threads", "1"}, {"--threads", "2"}, {"--in-process"}}) {
    auto args = batch;
    args.insert(args.end(), more.begin(), more.end());
    const auto r = acosim_run(args);
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.empty());
    outputs.push_back(r.out);
  }
  CHECK_THAT(outputs[0], Contains("batch:      6 variations"));
  CHECK(outputs[1] == outputs[0]);
  CHECK(outputs[2] == outputs[0]);
}

TEST_CASE("acosim --batch: a variation whose plugin crashes or hangs costs only itself, and says which plugin hook",
          "[acosim][contain]") {
  const auto file = [](const std::string& update) {
    return scenario("run: {map: open.txt, start: [0, 2], goal: [11, 2], local: dwa, update: " + update + "}\n")
        .string();
  };
  const std::string hostile = ACO_TEST_HOSTILE_PLUGIN_DIR;
  // One lane: the worker that crashed is started again for the next variation.
  const auto crashed = acosim_run({file("crashing"), "--batch", "3", "--threads", "1", "--plugin-dir", hostile});
  INFO(crashed.out << crashed.err);
  CHECK(crashed.exit_code == 0);
  CHECK_THAT(crashed.out, Contains("outcomes:   crashed 3;"));
  CHECK_THAT(crashed.out, Contains("reached:    0 (0 %)"));
  const std::string where = " in update() in iteration 3 (0-based, as Context::iteration)";
  for (const char* k : {"0", "1", "2"}) {
    CHECK_THAT(crashed.out,
               Contains(std::string("variation ") + k + ": crashed (crashed: SIGSEGV in plugin update/crashing ("));
    CHECK_THAT(crashed.err,
               Contains(std::string("acosim: variation ") + k + ": crashed: SIGSEGV in plugin update/crashing ("));
  }
  CHECK_THAT(crashed.err, Contains("aco_update_crashing.so)" + where + "\n"));

  // abort(), as a failed assert does, on two lanes.
  const auto aborted =
      acosim_run({file("crashing, update.abort: true"), "--batch", "2", "--threads", "2", "--plugin-dir", hostile});
  CHECK(aborted.exit_code == 0);
  CHECK_THAT(aborted.out, Contains("outcomes:   crashed 2;"));
  CHECK_THAT(aborted.err, Contains("crashed: SIGABRT in plugin update/crashing (") && Contains(where));

  // An endless loop: stopped at the time limit, which says where the worker was. Its outcome is
  // the outcome table's "timeout", as a simulation over its own time limit has (not the worker's
  // "timed out", which no table of outcomes knows).
  const auto hung =
      acosim_run({file("hanging"), "--batch", "2", "--variation-timeout", "0.5", "--plugin-dir", hostile});
  CHECK(hung.exit_code == 0);
  CHECK_THAT(hung.out, Contains("outcomes:   timeout 2;"));
  CHECK_THAT(hung.out,
             Contains("variation 1: timeout (timed out after 0.5 s in plugin update/hanging (") && Contains(where));
  CHECK_THAT(hung.err, Contains("acosim: variation 0: timed out after 0.5 s in plugin update/hanging ("));

  // Filling memory: stopped at the limit.
  const auto hogged = acosim_run(
      {file("hogging, update.megabytes: 1024"), "--batch", "1", "--variation-memory", "128M", "--plugin-dir", hostile});
  CHECK(hogged.exit_code == 0);
  CHECK_THAT(hogged.out, Contains("outcomes:   out of memory 1;"));
  CHECK_THAT(hogged.err, Contains("acosim: variation 0: out of memory (over 128 MiB) in plugin update/hogging (") &&
                             Contains(where));

  // --in-process is the old way: the crash ends the batch (and is named).
  const auto in_process = acosim_run({file("crashing"), "--batch", "2", "--in-process", "--plugin-dir", hostile});
  CHECK(in_process.exit_code == 128 + SIGSEGV);
  CHECK(in_process.out.empty());
  CHECK_THAT(in_process.err,
             Contains("acosim: error: crashed: SIGSEGV in plugin update/crashing (") && Contains(where));

  // An error is still an error, in a worker process too.
  const auto walled = scenario("run: {map: walled.txt, start: [0, 0], goal: [2, 0], local: dwa}\n");
  std::ofstream(walled.parent_path() / "walled.txt") << "0 1 0\n0 1 0\n";
  for (const auto& more : std::vector<std::vector<std::string>>{{}, {"--in-process"}}) {
    std::vector<std::string> args{walled.string(), "--batch", "2"};
    args.insert(args.end(), more.begin(), more.end());
    const auto r = acosim_run(args);
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.err, Contains("acosim: error: batch: the scenario's map has no path from start to goal"));
  }
  const auto bad =
      acosim_run({file("crashing"), "--batch", "2", "--variation-timeout", "soon", "--plugin-dir", hostile});
  CHECK(bad.exit_code == 1);
  CHECK_THAT(bad.err, Contains("acosim: error: --variation-timeout: 'soon' is not a time in seconds"));
}
