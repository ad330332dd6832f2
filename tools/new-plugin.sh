#!/usr/bin/env bash
# Scaffolds an out-of-tree plugin project that builds against an installed aco SDK; installed as
# <prefix>/bin/aco-new-plugin:
#   aco-new-plugin SLOT NAME DIR      (SLOT: init, heuristic, update, deadlock, smoother, local, map)
# then: cmake -S DIR -B DIR/build -DCMAKE_PREFIX_PATH=<aco prefix> && cmake --build DIR/build
#       ctest --test-dir DIR/build                  (the generated unit test: Catch2, aco/sdk/testing.hpp)
#       acoplan --plugin-dir DIR/build/plugins --SLOT NAME     (a map plugin: --map FILE.NAME)
# The generated class and its test compile and pass as they are; replace its one method with
# your idea and the test's example with what your idea must do.
set -euo pipefail
me=$(basename "$0")
usage="usage: $me SLOT NAME DIR
Writes an out-of-tree plugin project into DIR: NAME.cpp (a working SLOT plugin to replace with your
idea), test_NAME.cpp (its Catch2 unit test, with aco-plugin-check's checks), CMakeLists.txt and
README.md. SLOT: init, heuristic, update, deadlock, smoother, local; NAME: lower_case_with_underscores.
Then: cmake -S DIR -B DIR/build -DCMAKE_PREFIX_PATH=<aco prefix> && cmake --build DIR/build
      ctest --test-dir DIR/build && acoplan --plugin-dir DIR/build/plugins --SLOT NAME
Exit status: 0 written, 2 a wrong command line (nothing written)."
if [ "${1:-}" = "--help" ] || [ "${1:-}" = "-h" ]; then echo "$usage"; exit 0; fi
if [ $# -ne 3 ]; then echo "$usage" >&2; exit 2; fi
slot=$1 name=$2 dir=$3
[[ "$name" =~ ^[a-z][a-z0-9_]*$ ]] || { echo "$me: NAME must be lower_case_with_underscores" >&2; exit 2; }
case "$slot" in
  init) interface=PheromoneInit; method='  void initialize(const aco::Context&, std::span<double> tau) override {
    for (double& t : tau) t = p_.value;
  }'
  example="sets every edge to --init.value"
  test='  auto plugin = aco::testing::create<aco::PheromoneInit>(PLUGIN_FILE, {{"value", "2"}});
  std::vector<double> tau(problem.graph.num_edges());
  plugin->initialize(problem.context(), tau);
  aco::testing::check_values(tau, "tau", 0.0, true);  // every edge positive and finite
  CHECK(tau.front() == 2.0);' ;;
  heuristic) interface=Heuristic; method='  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) eta[e] = p_.value / (1.0 + g.distance(g.targets[e], c.goal));
  }'
  example="prefers steps towards the goal"
  test='  auto plugin = aco::testing::create<aco::Heuristic>(PLUGIN_FILE);
  std::vector<double> eta(problem.graph.num_edges());
  plugin->compute(problem.context(), eta);
  aco::testing::check_values(eta, "eta");
  // From the start (0,0), the diagonal step towards the goal (7,5) beats the step along the top.
  const aco::Graph& g = problem.graph;
  CHECK(eta[g.find_edge(problem.start, g.node({1, 1}))] > eta[g.find_edge(problem.start, g.node({1, 0}))]);' ;;
  update) interface=PheromoneUpdate; method='  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    aco::evaporate(tau, 0.1);
    if (it.best) aco::deposit(tau, *it.best, p_.value / it.best->length);
  }'
  example="reinforces the best path"
  test='  auto plugin = aco::testing::create<aco::PheromoneUpdate>(PLUGIN_FILE);
  const aco::testing::IterationCase ants = aco::testing::standard_iterations(problem).front();  // ants arrived
  std::vector<double> tau(problem.graph.num_edges(), 1.0);
  plugin->begin_run(problem.context());  // as every run begins
  plugin->start(problem.context(), tau);
  plugin->update(problem.context(), ants.view(), tau);
  aco::testing::check_values(tau, "tau");
  // The best ant'"'"'s first edge gains; the same step backwards, which no ant took, only evaporates.
  const aco::EdgeId first = ants.view().best->edges.front();
  CHECK(tau[first] > 1.0);
  CHECK(tau[problem.graph.reverse_edge(first)] < 1.0);' ;;
  deadlock) interface=DeadlockPolicy; method='  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override {
    return static_cast<int>(p_.value);  // nodes to step back; 0 lets the ant die
  }'
  example="steps back --deadlock.value nodes"
  test='  auto plugin = aco::testing::create<aco::DeadlockPolicy>(PLUGIN_FILE, {{"value", "2"}});
  CHECK(plugin->on_stuck(problem.context(), problem.shortest_path()) == 2);  // steps back 2 nodes' ;;
  smoother) interface=Smoother; method='  std::vector<Eigen::Vector3d> smooth(const aco::Context& c, std::span<const aco::NodeId> path) const override {
    return aco::to_waypoints(*c.graph, path);
  }'
  example="keeps the path's ends and never lengthens it"
  test='  auto plugin = aco::testing::create<aco::Smoother>(PLUGIN_FILE);
  const std::vector<aco::NodeId> path = problem.shortest_path();
  const auto points = plugin->smooth(problem.context(), path);
  REQUIRE(!points.empty());
  CHECK(points.front() == problem.graph.position(path.front()));
  CHECK(points.back() == problem.graph.position(path.back()));
  CHECK(aco::polyline_length(points) <= aco::path_length(problem.graph, path) + 1e-9);  // never longer' ;;
  local) interface=LocalPlanner; method='  aco::VelocityCommand command(const aco::LocalView& view) override {
    return aco::dynamic_window(view.robot, view.limits, view.period).clamp({p_.value, 0.0});  // straight ahead
  }'
  example="drives towards its goal"
  test='  auto plugin = aco::testing::create<aco::LocalPlanner>(PLUGIN_FILE);
  aco::LocalView view;  // a robot at rest at (0,0) facing +x, its goal straight ahead
  view.goal = {5.0, 0.0};
  const aco::VelocityCommand command = plugin->command(view);
  const aco::DynamicWindow window = aco::dynamic_window(view.robot, view.limits, view.period);
  CHECK(command.v >= window.v_low);
  CHECK(command.v <= window.v_high);
  CHECK(command.w >= window.w_low);
  CHECK(command.w <= window.w_high);
  CHECK(command.v > 0.0);  // it sets off' ;;
  map) interface=MapReader; method='  // Files ending in .'"${name}"': rows of . (free) and # (blocked), all of one length.
  std::vector<std::string> extensions() const override { return {".'"${name}"'"}; }
  std::string sample() const override { return "..#\n...\n"; }  // what aco-plugin-check reads
  std::unique_ptr<aco::Map> read(const std::filesystem::path& file, const aco::TerrainOptions&) const override {
    std::ifstream in(file);
    if (!in) throw aco::Error(file.string() + ": cannot open the map file");
    std::vector<std::string> rows;
    for (std::string row; std::getline(in, row);)
      if (!row.empty()) rows.push_back(row);
    if (rows.empty()) throw aco::Error(file.string() + ": no rows of . and #");
    auto grid = std::make_unique<aco::OccupancyGrid>(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), file.string());
    for (int y = 0; y < grid->height(); ++y) {
      if (rows[y].size() != rows.front().size()) throw aco::Error(file.string() + ": row " + std::to_string(y + 1) + " differs in length");
      for (int x = 0; x < grid->width(); ++x) grid->set_blocked({x, y}, rows[y][x] == '"'#'"');
    }
    return grid;
  }'
  example="reads a map written in its format"
  test='  // The open map written as rows of . and #, and read back.
  const auto file = std::filesystem::temp_directory_path() / "test_'"${name}.${name}"'";
  {
    std::ofstream out(file);
    for (int y = 0; y < problem.map->height(); ++y) {
      for (int x = 0; x < problem.map->width(); ++x) out << (problem.map->passable({x, y}) ? '"'.'"' : '"'#'"');
      out << '"'\\n'"';
    }
  }
  const auto map = aco::testing::create<aco::MapReader>(PLUGIN_FILE)->read(file, {});
  CHECK(map->width() == problem.map->width());
  CHECK(map->height() == problem.map->height());
  CHECK(map->passable({0, 0}));' ;;
  *) echo "$me: unknown SLOT '$slot' (init, heuristic, update, deadlock, smoother, local, map)" >&2; exit 2 ;;
esac
# Where a run's state goes (a map reader has no runs), and, for the slots a voxel world's run
# fills, how to plan there too.
lifecycle=""
[ "$slot" = map ] || lifecycle='  // One object may serve several runs: what your hooks keep from one call to the next during a
  // run, set it in begin_run(const aco::Context&), which every run calls first
  // (docs/writing-plugins.md, "The lifecycle").
'
case "$slot" in
  init|heuristic|update|deadlock|smoother) lifecycle+='  // Plans in voxel worlds (3D) too? Handle them (Graph::cost(e) and reverse_edge(e), cells with z,
  // moves with dz; docs/writing-plugins.md, "Voxel worlds") and say so, for aco-plugin-check to check:
  // bool supports_voxel_worlds() const override { return true; }
' ;;
esac
# Never over an existing project: the author's code would be lost.
if [ -e "$dir/CMakeLists.txt" ] || [ -e "$dir/${name}.cpp" ]; then
  echo "$me: $dir already holds a plugin project (CMakeLists.txt or ${name}.cpp); choose another DIR" >&2
  exit 2
fi
# A bundled plugin of the same name would be shadowed by this one in --plugin-dir.
# Run from a checkout (tools/) the bundled plugins are sources, installed (bin/) they are libraries.
here=$(dirname "$(readlink -f "$0")")
if [ -d "$here/../plugins/$slot/$name" ] || [ -e "$here/../lib/aco/plugins/aco_${slot}_${name}.so" ]; then
  echo "$me: warning: $slot/$name is also a bundled plugin; with --plugin-dir yours replaces it" >&2
fi
mkdir -p "$dir"
cat > "$dir/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(aco_${slot}_${name} LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
# Optimised unless asked otherwise: an unoptimised plugin runs several times slower.
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Debug, Release, RelWithDebInfo or MinSizeRel" FORCE)
endif()
find_package(aco REQUIRED)
aco_add_plugin(${slot} ${name} ${name}.cpp)

# The unit test: the plugin's own example and every check of aco-plugin-check, one ctest test per
# Catch2 case, labelled with its tags (ctest -L conformance).
enable_testing()
find_package(Catch2 REQUIRED)
add_executable(test_${name} test_${name}.cpp)
target_link_libraries(test_${name} PRIVATE aco::conformance Catch2::Catch2)
target_compile_definitions(test_${name} PRIVATE PLUGIN_FILE="\$<TARGET_FILE:aco_${slot}_${name}>")
add_dependencies(test_${name} aco_${slot}_${name})
aco_discover_tests(test_${name})
CMAKE
cat > "$dir/${name}.cpp" <<CPP
// ${slot}/${name}: describe the idea and cite its source here.
#include <fstream>

#include "aco/error.hpp"
#include "aco/path.hpp"
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

// The parameters, their defaults, and their table: name, member, range, help.
struct Parameters {
  double value = 1.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("value", &Parameters::value, "(0:1e6]", "an example parameter (--${slot}.value)"),
});

class Plugin final : public aco::${interface} {
 public:
  explicit Plugin(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
${lifecycle}${method}

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(${slot}, ${name}, Plugin, "0.1", "describe ${name} in one line", kParams)
CPP
cat > "$dir/test_${name}.cpp" <<CPP
// The unit test of ${slot}/${name}: it loads the plugin from the library the build made.
#define CATCH_CONFIG_MAIN
#include <fstream>

#include "aco/path.hpp"
#include "aco/sdk/testing.hpp"

TEST_CASE("${slot}/${name} passes the conformance checks", "[${slot}][${name}][conformance]") {
  // Defaults and parameter range ends, on tiny maps and edge-case iterations: finite values,
  // same output for the same seed, same output on 1 and 4 threads, a reused object's run the same
  // as a fresh one's (as aco-plugin-check).
  aco::testing::check_conformance(PLUGIN_FILE);
}

TEST_CASE("${slot}/${name} ${example}", "[${slot}][${name}]") {
  const aco::testing::Problem problem = aco::testing::standard_problems().front();  // open 8x6, (0,0) to (7,5)
${test}
}
CPP
cat > "$dir/README.md" <<MD
# ${slot}/${name}

What it does, the formula it implements, the source it comes from, and its parameters.
MD
echo "$me: wrote $dir (${slot}/${name})"
