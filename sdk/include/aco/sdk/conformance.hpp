#pragma once
// The plugin conformance checks, in one place for aco-plugin-check and for Catch2 tests
// (aco/sdk/testing.hpp). Every plugin of a library file is run at its defaults and at each end of
// each parameter's range (one parameter at a time), on the standard tiny maps and edge-case
// iterations below, and these checks are made for every parameter set:
//   values         every value it produces is finite and in range (pheromone > 0 after init,
//                  >= 0 after update; eta, factors, path lengths, waypoints, commands), and it
//                  keeps its interface's contract (see run_slot in sdk/src/slot_runs.cpp)
//   deterministic  two runs of fresh objects with the same seed give identical output, bit for bit
//   threads        a run on 4 threads gives what the run on 1 thread gave
//   reused         the lifecycle (aco/strategies.hpp): one object serving a second run, after runs
//                  on the other maps, gives what it gave as a fresh object (begin_run() leaves no
//                  trace of earlier runs); not for map readers, which have no runs
// (The run on 4 threads is the second run when it agrees with the first; when it does not,
// another run on 1 thread tells nondeterminism from thread dependence.)
// The same four checks run again, as "3D values", "3D deterministic", "3D threads" and
// "3D reused", on the voxel worlds below (26-neighbourhood, no corner cutting) for every parameter
// set whose object claims voxel worlds (Strategy::supports_voxel_worlds()). A plugin that does not
// claim them gets one line "SKIP ... 3D: ..." saying it was not run in 3D (a local planner, which
// drives in the plane, likewise); a map reader gets none (it has no runs; its sample is checked
// whatever its dimension). In both dimensions the values check also asks that a colony run's path
// steps along graph edges from start to goal and that a smoother's waypoints lie on free cells
// (voxels) with a free straight line between any two that are cell centres.
// A value the plugin's factory refuses with aco::Error (a combination it rejects, like a > b)
// is reported as skipped, not failed; any other exception is a failure.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "aco/engine/colony.hpp"
#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/map_reader.hpp"
#include "aco/slots.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/voxel.hpp"

namespace aco::conformance {

// A standard tiny map with its graph (8-neighbourhood, no corner cutting; a voxel world's
// 26-neighbourhood, no corner cutting), start and goal.
struct Problem {
  std::string name;  // "open", "obstacles", "dead end", "corridor"; "voxels", "floors"
  std::shared_ptr<const Map> map;  // shared: graph.map points to it (an OccupancyGrid or a VoxelMap)
  Graph graph;
  NodeId start = 0;
  NodeId goal = 0;

  // What a strategy sees in `iteration` of a run of `iterations` iterations of 8 ants.
  Context context(int iteration = 0, int iterations = 10, std::uint64_t seed = 1) const;
  // The shortest path from start to goal (A*).
  std::vector<NodeId> shortest_path() const;
};

// open 8x6; obstacles 10x8 (walls to go around); dead end 10x8 (pockets that end in walls and
// a walled-in cell no ant can reach); corridor 12x1. The goal is reachable on each.
std::vector<Problem> standard_problems();

// A Problem from rows of text ('#' blocked), start and goal given as cells.
Problem make_problem(const std::string& name, const std::vector<std::string>& rows, Cell start, Cell goal);

// The voxel worlds a plugin claiming them (Strategy::supports_voxel_worlds()) is checked on too,
// each with its graph (26-neighbourhood, no corner cutting): "voxels" 10x8x6, a wall across x = 5
// with a 2x2 gap high up, pillars, an overhang and a walled-in voxel no ant can reach, from
// (0,0,0) to (9,7,5); "floors" 4x4x7, two floors with a hole each, at opposite corners, from
// (0,0,0) to (3,3,6). The goal is reachable on each.
std::vector<Problem> voxel_problems();

// A Problem in a voxel world, start and goal given as cells with z.
Problem make_voxel_problem(std::shared_ptr<const VoxelMap> world, Cell start, Cell goal,
                           Neighbourhood neighbourhood = Neighbourhood::twenty_six);

// The ants of one iteration, owning what Iteration points to.
struct IterationCase {
  std::string name;
  std::vector<Ant> ants;
  int best = -1;  // index into ants, or -1
  std::optional<Ant> earlier_best;  // best_so_far from an earlier iteration, if any

  Iteration view() const;
};

// An ant walking `nodes` (consecutive nodes must be neighbours); arrived when it ends at goal.
Ant walk(const Problem& problem, const std::vector<NodeId>& nodes);

// "ants arrived": three ants on the shortest path or around it, one dead, best set;
// "no ant arrived": every ant stopped short, only an earlier best path;
// "all ants dead": every ant died on the start node, no best path at all.
std::vector<IterationCase> standard_iterations(const Problem& problem);

// One parameter set of a plugin: the values given (the rest at their defaults) and a label.
struct ParameterSet {
  std::string label;  // "defaults" or "rho=0.01"
  std::map<std::string, std::string> given;
  // A set of one value the declared range admits: what to declare if the plugin refuses it
  // ("the range (0:1]", "no choice 'x'"); empty for the defaults.
  std::string if_refused;
};

// The defaults, then each parameter at each end of its range, one at a time (an open end a
// thousandth of its size, at least of 1, inside it; an infinite end not at all; a whole number
// above integer_cap at the cap: counts like iterations scale the work), each other choice of a
// categorical, the other value of a boolean; a text parameter stays at its default. A plugin
// refusing one of these single values (aco::Error from its factory) fails "constructs": its
// table declares a value it does not take, unless the refusal is of a combination the table
// cannot express (a < b): its message names another parameter, or the factory takes the value
// beside another parameter's tried value. Refusing the defaults is a SKIP (a text parameter
// such as python's class may need a value; give it with Options::fixed).
std::vector<ParameterSet> parameter_sets(std::span<const ParamSpec> table, std::int64_t integer_cap);

struct Options {
  std::int64_t integer_cap = 100;
  // Values every parameter set runs with (aco-plugin-check --set NAME=VALUE): a text parameter's
  // above all, which the sets never vary (python's class has no value that runs everywhere).
  std::map<std::string, std::string> fixed;
  // Which worlds to run the plugins on: the standard 2D maps, and the voxel worlds (for the
  // parameter sets whose object claims them). A test may run the 3D checks alone.
  bool grids = true;
  bool voxel_worlds = true;
  ColonySettings colony = [] {
    ColonySettings s;
    s.ants = 8;
    s.iterations = 10;
    s.seed = 7;
    return s;
  }();
};

struct CheckResult {
  std::string plugin;  // "update/ant_system"
  std::string parameters;  // ParameterSet::label
  // "values", "deterministic", "threads", "reused" ("constructs" when skipped or failed); in the
  // voxel worlds "3D values", "3D deterministic", "3D threads", "3D reused" ("3D" when not run)
  std::string check;
  enum class Status { pass, fail, skip } status = Status::pass;
  std::string detail;  // what failed, where (map, iteration, value)

  // "PASS update/ant_system [rho=0] deterministic", "FAIL ... values: open, ...: tau[3] = nan"
  std::string line() const;
};

using Report = std::function<void(const CheckResult&)>;

// The plugins exported by a library file. Throws Error if it exports none, or if another file in
// its folder exports a plugin of the same slot and name first.
std::vector<PluginFile> plugins_in(const std::filesystem::path& file);

// Runs every check on one plugin and reports each result. The colony slots run inside a colony
// whose other slots are the default plugins found by PluginRegistry::default_search_dirs().
void check_plugin(const PluginFile& plugin, const Options& options, const Report& report);

// check_plugin for every plugin in the file; returns how many checks failed.
int check_file(const std::filesystem::path& file, const Options& options, const Report& report);

// "" if every value is finite and >= minimum (or > minimum when `strict`), else the first
// offender: "tau[3] = nan".
std::string bad_value(std::span<const double> values, const std::string& what, double minimum = 0.0,
                      bool strict = false);

// The slot whose interface is Interface: "init" for PheromoneInit, ... (aco/slots.hpp)
template <class Interface>
constexpr const char* slot_of() {
#define ACO_SLOT_OF_(NAME, INTERFACE)                 \
  if constexpr (std::is_same_v<Interface, INTERFACE>) \
    return #NAME;                                     \
  else
  ACO_SLOTS(ACO_SLOT_OF_) {
    static_assert(!std::is_same_v<Interface, Interface>, "not a slot interface");
    return "";
  }
#undef ACO_SLOT_OF_
}

// The registry over a file's folder (one per folder, kept for the process) and the file's plugin
// of slot `slot` (the first, if it holds several). Throws Error if it has none.
std::pair<PluginRegistry*, PluginFile> find_in(const std::filesystem::path& file, const std::string& slot);

// The file's plugin of Interface's slot, behind the error boundary, its defaults overridden by
// `given` ({{"rho", "0.2"}}).
template <class Interface>
std::unique_ptr<Interface> create(const std::filesystem::path& file,
                                  const std::map<std::string, std::string>& given = {}) {
  const auto found = find_in(file, slot_of<Interface>());
  PluginRegistry& registry = *found.first;
  const PluginFile& plugin = found.second;
  const PluginDescriptor& descriptor = registry.load(plugin.slot, plugin.name);
  return registry.create<Interface>(plugin.slot, plugin.name,
                                    resolve(descriptor.parameters(), given, plugin.slot + "."));
}

}  // namespace aco::conformance
