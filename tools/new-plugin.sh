#!/usr/bin/env bash
# Scaffolds an out-of-tree plugin project that builds against an installed aco SDK:
#   tools/new-plugin.sh KIND NAME DIR      (KIND: init, heuristic, update, deadlock, smoother, local)
# then: cmake -S DIR -B DIR/build -DCMAKE_PREFIX_PATH=<aco prefix> && cmake --build DIR/build
#       acoplan --plugin-dir DIR/build/plugins --KIND NAME
# The generated class compiles and runs as it is; replace its one method with your idea.
set -euo pipefail
if [ $# -ne 3 ]; then echo "usage: $0 KIND NAME DIR" >&2; exit 2; fi
kind=$1 name=$2 dir=$3
[[ "$name" =~ ^[a-z][a-z0-9_]*$ ]] || { echo "new-plugin: NAME must be lower_case_with_underscores" >&2; exit 2; }
case "$kind" in
  init) interface=PheromoneInit; method='  void initialize(const aco::Context&, std::span<double> tau) override {
    for (double& t : tau) t = p_.value;
  }' ;;
  heuristic) interface=Heuristic; method='  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) eta[e] = p_.value / (1.0 + g.distance(g.targets[e], c.goal));
  }' ;;
  update) interface=PheromoneUpdate; method='  void update(const aco::Context&, const aco::Iteration& it, std::span<double> tau) override {
    aco::evaporate(tau, 0.1);
    if (it.best) aco::deposit(tau, *it.best, p_.value / it.best->length);
  }' ;;
  deadlock) interface=DeadlockPolicy; method='  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override {
    return static_cast<int>(p_.value);  // nodes to step back; 0 lets the ant die
  }' ;;
  smoother) interface=Smoother; method='  std::vector<Eigen::Vector3d> smooth(const aco::Context& c, std::span<const aco::NodeId> path) const override {
    return aco::to_waypoints(*c.graph, path);
  }' ;;
  local) interface=LocalPlanner; method='  aco::VelocityCommand command(const aco::LocalView& view) override {
    return aco::dynamic_window(view.robot, view.limits, view.period).clamp({p_.value, 0.0});  // straight ahead
  }' ;;
  *) echo "new-plugin: unknown KIND '$kind' (init, heuristic, update, deadlock, smoother, local)" >&2; exit 2 ;;
esac
# Never over an existing project: the author's code would be lost.
if [ -e "$dir/CMakeLists.txt" ] || [ -e "$dir/${name}.cpp" ]; then
  echo "new-plugin: $dir already holds a plugin project (CMakeLists.txt or ${name}.cpp); choose another DIR" >&2
  exit 2
fi
# A bundled plugin of the same name would be shadowed by this one in --plugin-dir.
if [ -d "$(dirname "$0")/../plugins/$kind/$name" ]; then
  echo "new-plugin: warning: $kind/$name is also a bundled plugin; with --plugin-dir yours replaces it" >&2
fi
mkdir -p "$dir"
cat > "$dir/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(aco_${kind}_${name} LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
# Optimised unless asked otherwise: an unoptimised plugin runs several times slower.
if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Debug, Release, RelWithDebInfo or MinSizeRel" FORCE)
endif()
find_package(aco REQUIRED)
aco_add_plugin(${kind} ${name} ${name}.cpp)
CMAKE
cat > "$dir/${name}.cpp" <<CPP
// ${kind}/${name}: describe the idea and cite its source here.
#include "aco/path.hpp"
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

// The parameters, their defaults, and their table: name, member, range, help.
struct Parameters {
  double value = 1.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("value", &Parameters::value, "(0:1e6]", "an example parameter (--${kind}.value)"),
});

class Plugin final : public aco::${interface} {
 public:
  explicit Plugin(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
${method}

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(${kind}, ${name}, Plugin, "0.1", "describe ${name} in one line", kParams)
CPP
cat > "$dir/README.md" <<MD
# ${kind}/${name}

What it does, the formula it implements, the source it comes from, and its parameters.
MD
echo "new-plugin: wrote $dir (${kind}/${name})"
