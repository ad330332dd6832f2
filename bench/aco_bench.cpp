// aco_bench: speed figures of the colony engine. Times whole runs with steady_clock and
// reports medians; ns per ant step = run time / moves made by all ants.
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <sys/resource.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numeric>
#include <set>
#include <sstream>

#include "aco/any_angle.hpp"
#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "ifwa/fireworks.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/hosts/program_options_error.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/strategies.hpp"
#include "aco/planning/yardsticks.hpp"

namespace po = boost::program_options;

namespace {

struct Timing {
  double median_ms = 0;
  double min_ms = 0;
  double ns_per_step = 0;
  double mean_length = 0;
  double total_ms = 0;
  std::uint64_t total_steps = 0;
  aco::ColonyResult last;
  std::vector<std::vector<aco::NodeId>> paths;  // per run, empty where it found none
};

// Runs the colony `repeats` times with seeds 1..repeats inside an arena of `threads` threads.
Timing time_runs(const aco::Graph& graph, aco::Cell start, aco::Cell goal, aco::PluginRegistry& registry,
                 const aco::Keys& plugins, aco::ColonySettings settings, int repeats, int threads,
                 bool same_seed = false) {
  const aco::RunSpec run = aco::resolve_run(plugins, registry);
  const aco::PipelineSpec& spec = run.pipeline;
  if (plugins.count("q0")) settings.q0 = run.colony.q0;
  std::vector<double> ms;
  Timing t;
  tbb::task_arena arena(threads);
  for (int i = 0; i < repeats; ++i) {
    const auto pipeline = aco::instantiate(registry, spec);
    settings.seed = same_seed ? 1 : static_cast<std::uint64_t>(i + 1);
    const auto began = std::chrono::steady_clock::now();
    arena.execute([&] {
      t.last = aco::run_pipeline(registry, spec, pipeline, graph, graph.node(start), graph.node(goal), settings);
    });
    const double elapsed = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
    ms.push_back(elapsed);
    t.total_ms += elapsed;
    t.total_steps += t.last.ant_steps;
    t.mean_length += t.last.length / repeats;
    t.paths.push_back(t.last.path);
  }
  std::sort(ms.begin(), ms.end());
  t.median_ms = ms[ms.size() / 2];
  t.min_ms = ms.front();
  t.ns_per_step = t.total_ms * 1e6 / double(std::max<std::uint64_t>(t.total_steps, 1));
  return t;
}

// acs and elite run with the q0 their READMEs give (0.7, 0.8): a colony setting, not theirs.
aco::Keys with_their_q0(aco::Keys keys) {
  const auto update = keys.find("update");
  if (update != keys.end() && update->second == "acs") keys["q0"] = "0.7";
  if (update != keys.end() && update->second == "elite") keys["q0"] = "0.8";
  return keys;
}

// `keys` with `slot` set to `plugin`, without the parameters of the slot's previous plugin.
aco::Keys swapped(aco::Keys keys, const std::string& slot, const std::string& plugin) {
  std::erase_if(keys, [&](const auto& kv) { return kv.first.rfind(slot + ".", 0) == 0; });
  keys[slot] = plugin;
  return with_their_q0(keys);
}

// The python plugins run nothing without a class to name; tools/python-bench.sh times them.
bool needs_a_class(const std::string& plugin) { return plugin == "python"; }

// Whether two runs gave bit-identical results (the determinism promise across thread counts).
bool same_result(const aco::ColonyResult& a, const aco::ColonyResult& b) {
  return a.path == b.path && a.length == b.length && a.ant_steps == b.ant_steps && a.best_so_far == b.best_so_far &&
         a.pheromone == b.pheromone;
}

struct SmootherTiming {
  double us_per_call = 0;
  std::size_t waypoints = 0;
};

// A smoother on a grid path, timed over `calls` calls.
SmootherTiming time_smoother(aco::PluginRegistry& registry, const std::string& smoother, const aco::Graph& graph,
                             const std::vector<aco::NodeId>& path, int calls) {
  const auto pipeline = aco::instantiate(registry, aco::resolve_run({{"smoother", smoother}}, registry).pipeline);
  aco::Context context;
  context.graph = &graph;
  context.start = path.front();
  context.goal = path.back();
  SmootherTiming t;
  const auto began = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) t.waypoints = pipeline.smoother->smooth(context, path).size();
  t.us_per_call = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - began).count() / calls;
  return t;
}

std::unique_ptr<aco::Map> load(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file))
    throw aco::Error(file.string() + " not found (give --maps DIR or --large-map FILE)");
  return aco::load_map(file);
}

// Paper 004's fireworks seeding (IFWA with the paper's settings) on its look-alike map, 1 thread.
void time_fireworks(int repeats) {
  const auto map = load(std::filesystem::path(ACO_BENCH_DATA_DIR) / "terrain/paper004.map");
  const aco::Graph graph = aco::build_graph(*map, {aco::Neighbourhood::eight, true});
  aco::FireworksSettings settings = aco::fireworks_settings(aco::resolve(aco::fireworks_parameters(), {}, ""));
  std::vector<double> ms;
  double mean_length = 0;
  std::uint64_t evaluations = 0;
  tbb::task_arena arena(1);
  for (int i = 0; i < repeats; ++i) {
    settings.seed = static_cast<std::uint64_t>(i + 1);
    aco::PlannerResult r;
    const auto began = std::chrono::steady_clock::now();
    arena.execute([&] { r = aco::run_fireworks(graph, graph.node({0, 0}), graph.node({19, 19}), settings); });
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count());
    mean_length += r.length / repeats;
    evaluations += r.evaluations;
  }
  std::sort(ms.begin(), ms.end());
  std::printf(
      "\n== fireworks seeding (IFWA, paper 004 settings) on data/terrain/paper004.map, corner cutting, 1 thread ==\n");
  std::printf("median %.2f ms, min %.2f ms, %.1f us per evaluation, mean best length %.4f\n", ms[ms.size() / 2],
              ms.front(), 1000.0 * std::accumulate(ms.begin(), ms.end(), 0.0) / double(evaluations), mean_length);
}

// Classic map1 with each update rule, then each plugin swapped into the baseline pipeline.
void time_classic(aco::PluginRegistry& registry, int repeats) {
  std::printf(
      "== classic map1, corner cutting, 8-neighbourhood, 50 ants x 100 iterations, alpha 1, beta 7, 1 thread ==\n");
  std::printf("%-12s %10s %10s %12s %12s\n", "update", "median ms", "min ms", "ns/ant step", "mean length");
  const auto map1 = load(std::filesystem::path(ACO_BENCH_DATA_DIR) / "maps/classic20/map1.txt");
  const aco::Graph classic = aco::build_graph(*map1, {aco::Neighbourhood::eight, true});
  for (const char* update : {"ant_system", "max_min", "acs"}) {
    aco::Keys spec = with_their_q0({{"update", update}});
    if (std::string(update) != "max_min") spec.insert({{"update.rho", "0.3"}, {"update.q", "1"}});
    const Timing t = time_runs(classic, {0, 0}, {19, 19}, registry, spec, {}, repeats, 1);
    std::printf("%-12s %10.3f %10.3f %12.1f %12.4f\n", update, t.median_ms, t.min_ms, t.ns_per_step, t.mean_length);
  }

  // Each plugin swapped into the baseline pipeline (the other slots stay at their defaults).
  std::printf(
      "\n== plugins on classic map1 (same setting, 1 thread): ns per ant step against the ant_system baseline ==\n");
  std::printf("%-28s %12s %8s %12s\n", "slot/plugin", "ns/ant step", "ratio", "mean length");
  const aco::Keys baseline{{"update.rho", "0.3"}, {"update.q", "1"}};
  const Timing base = time_runs(classic, {0, 0}, {19, 19}, registry, baseline, {}, repeats, 1);
  std::printf("%-28s %12.1f %8.2f %12.4f\n", "(baseline)", base.ns_per_step, 1.0, base.mean_length);
  for (const char* slot : aco::kSlots) {
    for (const auto& name : registry.names(slot)) {
      if (name == aco::default_plugin(slot) || needs_a_class(name)) continue;
      const Timing t = time_runs(classic, {0, 0}, {19, 19}, registry, swapped(baseline, slot, name), {}, repeats, 1);
      std::printf("%-28s %12.1f %8.2f %12.4f\n", (std::string(slot) + "/" + name).c_str(), t.ns_per_step,
                  t.ns_per_step / base.ns_per_step, t.mean_length);
    }
  }

  // The smoother runs once per plan, on the best path: its cost is per call, not per ant step.
  for (const char* smoother : {"prune", "taut"}) {
    const SmootherTiming small = time_smoother(registry, smoother, classic, base.last.path, 1000);
    std::printf("%-28s %9.2f us per call on the best map1 path (%zu cells -> %zu waypoints)\n",
                ("smoother/" + std::string(smoother)).c_str(), small.us_per_call, base.last.path.size(),
                small.waypoints);
  }
}

struct TerrainPipeline {
  const char* name;
  aco::Neighbourhood neighbourhood;
  bool bidirectional;
  std::map<std::string, std::string> plugins;  // slot -> plugin; the other slots keep their defaults
};

// Plain ACO (the default pipeline) and paper 000's full EPF-ACO, as acoplan runs it with
// --neighbourhood 16 --search bidirectional --init potential_field --heuristic potential_field --update elite
// --q0 0.8.
const std::vector<TerrainPipeline>& terrain_pipelines() {
  static const std::vector<TerrainPipeline> pipelines = {
      {"plain", aco::Neighbourhood::eight, false, {}},
      {"EPF",
       aco::Neighbourhood::sixteen,
       true,
       {{"init", "potential_field"}, {"heuristic", "potential_field"}, {"update", "elite"}}},
  };
  return pipelines;
}

// Paper 000's look-alike terrains, each pipeline with 1 thread and with all threads. Returns
// whether every pair of runs gave identical results.
bool time_terrain(aco::PluginRegistry& registry, int repeats) {
  const int all_threads = tbb::info::default_concurrency();
  std::printf(
      "\n== paper 000 look-alike terrains (data/terrain/*.asc.scen), no corner cutting, 50 ants x 100 iterations, "
      "alpha 1, beta 7 ==\n");
  std::printf(
      "plain = uniform/distance/ant_system, 8-neighbourhood; EPF = 16-neighbourhood, bidirectional, "
      "potential_field/potential_field/elite, q0 0.8\n");
  std::printf("%-6s %9s %-8s %8s %10s %10s %12s %12s\n", "map", "optimum", "pipeline", "threads", "median ms", "min ms",
              "ns/ant step", "mean length");
  bool identical = true;
  for (const char* name : {"epf20", "epf30", "epf50"}) {
    const auto scen_file = std::filesystem::path(ACO_BENCH_DATA_DIR) / "terrain" / (std::string(name) + ".asc.scen");
    if (!std::filesystem::exists(scen_file)) throw aco::Error(scen_file.string() + " not found");
    const auto scenarios = aco::load_scenarios(scen_file);
    if (scenarios.empty()) throw aco::Error(scen_file.string() + " has no scenario");
    const aco::Scenario& s = scenarios.front();
    const auto map = load(aco::scenario_map_file(scen_file));
    for (const TerrainPipeline& p : terrain_pipelines()) {
      const aco::Graph graph = aco::build_graph(*map, {p.neighbourhood, false});
      aco::Keys spec;
      for (const auto& [slot, plugin] : p.plugins) spec[slot] = plugin;
      // EPF's elite with paper 000's q0 0.8 (it lost it when q0 became a colony setting).
      spec = with_their_q0(spec);
      aco::ColonySettings settings;
      settings.bidirectional = p.bidirectional;
      aco::ColonyResult one_thread;
      for (const int threads : std::set<int>{1, all_threads}) {
        const Timing t = time_runs(graph, s.start, s.goal, registry, spec, settings, repeats, threads);
        std::printf("%-6s %9.2f %-8s %8d %10.2f %10.2f %12.1f %12.2f\n", name, s.optimal_length, p.name, threads,
                    t.median_ms, t.min_ms, t.ns_per_step, t.mean_length);
        if (threads == 1)
          one_thread = t.last;
        else
          identical = identical && same_result(one_thread, t.last);
      }
    }
  }
  std::printf("results with 1 and %d threads identical (last seed: path, length, steps, curve, pheromone): %s\n",
              all_threads, identical ? "yes" : "NO");
  return identical;
}

// The large map's scenario and its graph (8-neighbourhood, no corner cutting).
struct LargeProblem {
  aco::Scenario scenario;
  std::unique_ptr<aco::Map> map;
  aco::Graph graph;
};

std::unique_ptr<LargeProblem> load_large(const std::filesystem::path& shared, const std::string& large,
                                         int large_index) {
  const std::filesystem::path large_file = shared / large;
  const auto scenarios = aco::load_scenarios(large_file.string() + ".scen");
  if (large_index < 0 || large_index >= int(scenarios.size())) throw aco::Error("--large-scen-index out of range");
  auto p = std::make_unique<LargeProblem>();
  p->scenario = scenarios[large_index];
  p->map = load(large_file);
  p->graph = aco::build_graph(*p->map, {});
  return p;
}

// The thread-scaling run on a large Moving AI map. Returns whether 1 and 2 threads agree.
bool time_large(aco::PluginRegistry& registry, const std::filesystem::path& shared, const std::string& large,
                int large_index, int large_repeats) {
  const auto problem = load_large(shared, large, large_index);
  const aco::Scenario& s = problem->scenario;
  const aco::Graph& graph = problem->graph;
  std::printf("\n== %s (%dx%d, %d edges), scenario %d: %s -> %s, optimum %.2f; ant_system defaults ==\n", large.c_str(),
              graph.width, graph.height, graph.num_edges(), large_index, aco::to_string(s.start).c_str(),
              aco::to_string(s.goal).c_str(), s.optimal_length);
  std::printf("%-8s %10s %10s %12s %10s %8s\n", "threads", "median ms", "min ms", "ns/ant step", "length", "speedup");
  const aco::Keys defaults;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 2);
  const Timing one = time_runs(graph, s.start, s.goal, registry, defaults, {}, large_repeats, 1, true);
  const Timing two = time_runs(graph, s.start, s.goal, registry, defaults, {}, large_repeats, 2, true);
  std::printf("%-8d %10.1f %10.1f %12.1f %10.2f %8s\n", 1, one.median_ms, one.min_ms, one.ns_per_step, one.last.length,
              "1.00");
  std::printf("%-8d %10.1f %10.1f %12.1f %10.2f %8.2f\n", 2, two.median_ms, two.min_ms, two.ns_per_step,
              two.last.length, one.median_ms / two.median_ms);
  const bool identical = same_result(one.last, two.last);
  if (one.last.solved) {
    for (const char* smoother : {"prune", "taut"}) {
      const SmootherTiming t = time_smoother(registry, smoother, graph, one.last.path, 1);
      std::printf("smoother/%s on this path: %.2f ms (%zu cells -> %zu waypoints)\n", smoother, t.us_per_call / 1000,
                  one.last.path.size(), t.waypoints);
    }
  }
  std::printf(
      "results with 1 and 2 threads identical (path, length, steps, curve, pheromone): %s; solved: %s, %d iterations\n",
      identical ? "yes" : "NO", one.last.solved ? "yes" : "no", one.last.iterations);
  return identical;
}

// The recommended 2D pipeline: data/presets/robust.ini read as run keys (INI's "rho" under
// [update] is the key "update.rho"), so the benchmark times what the preset says.
aco::Keys robust_preset() { return aco::read_config_file(std::string(ACO_BENCH_DATA_DIR) + "/presets/robust.ini"); }

// Every plugin and large-map engine option on a 512x512 map, 1 thread: ns per ant step against
// two baselines. With the default pipeline (ants die when stuck) a 512x512 run does little ant
// work, so per-step figures there mostly spread the per-run set-up (per-edge fields, heuristic
// table) over few steps; with backtrack every ant walks to the goal. Deadlock plugins replace
// backtrack in the second baseline. Then the recommended pipeline with 1 and 2 threads.
bool time_large_plugins(aco::PluginRegistry& registry, const std::filesystem::path& shared, const std::string& large,
                        int large_index, int repeats) {
  const auto problem = load_large(shared, large, large_index);
  const aco::Scenario& s = problem->scenario;
  const aco::Graph& graph = problem->graph;
  std::printf(
      "\n== plugins on %s, scenario %d (optimum %.2f), 50 ants x 100 iterations, beta 7, 1 thread, %d runs each ==\n",
      large.c_str(), large_index, s.optimal_length, repeats);
  std::printf(
      "per ant step = (time of 100 iterations - time of the first) / (steps of 100 - steps of the first), same\n"
      "seeds: the per-run set-up (per-edge fields, heuristic table, fireworks search, dead-end filling) is\n"
      "the first iteration's time, shown apart; \"all\" divides the whole run time by all steps\n");
  std::printf("%-32s %12s %8s %12s %12s %12s %12s %12s %8s\n", "slot/plugin or option", "ns/ant step", "ratio",
              "ns/step all", "1st it. ms", "ms per run", "ant steps", "mean length", "solved");
  struct Row {
    std::string name;
    aco::Keys spec;
    aco::ColonySettings settings;
  };
  const aco::Keys with_backtrack{{"deadlock", "backtrack"}};
  for (const auto& [label, baseline] : {std::pair{"baseline: default pipeline", aco::Keys{}},
                                        std::pair{"baseline: ant_system + backtrack", with_backtrack}}) {
    std::vector<Row> rows{{label, baseline, {}}};
    for (const char* slot : aco::kSlots) {
      if (std::string(slot) == "smoother") continue;  // once per plan, timed in the large section
      for (const auto& name : registry.names(slot)) {
        const auto chosen = baseline.find(slot);
        if (name == (chosen != baseline.end() ? chosen->second : aco::default_plugin(slot)) || needs_a_class(name))
          continue;
        rows.push_back({std::string(slot) + "/" + name, swapped(baseline, slot, name), {}});
      }
    }
    for (const char* option : {"fill-dead-ends", "local-search straighten", "walk-limit 4"}) {
      Row row{std::string("option ") + option, baseline, {}};
      row.settings.fill_dead_ends = std::string(option) == "fill-dead-ends";
      if (std::string(option) == "local-search straighten") row.settings.local_search = aco::LocalSearch::straighten;
      if (std::string(option) == "walk-limit 4") row.settings.walk_limit = 4;
      rows.push_back(row);
    }
    double base_ns = 0;
    for (const Row& row : rows) {
      const Timing t = time_runs(graph, s.start, s.goal, registry, row.spec, row.settings, repeats, 1);
      aco::ColonySettings first_only = row.settings;
      first_only.iterations = 1;
      const Timing first = time_runs(graph, s.start, s.goal, registry, row.spec, first_only, repeats, 1);
      const double steps = double(t.total_steps) - double(first.total_steps);
      const double ns = steps > 0 ? (t.total_ms - first.total_ms) * 1e6 / steps : 0.0;
      if (base_ns == 0) base_ns = ns;
      std::printf("%-32s %12.1f %8.2f %12.1f %12.1f %12.1f %12llu %12.2f %8s\n", row.name.c_str(), ns, ns / base_ns,
                  t.ns_per_step, first.median_ms, t.median_ms, static_cast<unsigned long long>(t.last.ant_steps),
                  t.mean_length, t.last.solved ? "yes" : "no");
    }
  }
  const aco::Keys robust = robust_preset();
  const aco::ColonySettings settings = aco::resolve_run(robust, registry).colony;
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 2);
  const Timing one = time_runs(graph, s.start, s.goal, registry, robust, settings, repeats, 1, true);
  const Timing two = time_runs(graph, s.start, s.goal, registry, robust, settings, repeats, 2, true);
  const bool identical = same_result(one.last, two.last);
  std::printf(
      "recommended pipeline (data/presets/robust.ini): 1 thread %.1f ms, 2 threads %.1f ms (median), speedup %.2f, "
      "length %.2f (optimum %.2f); results with 1 and 2 threads identical: %s\n",
      one.median_ms, two.median_ms, one.median_ms / two.median_ms, one.last.length, s.optimal_length,
      identical ? "yes" : "NO");
  return identical;
}

// Grid ants against line-of-sight walks (ColonySettings::walk_length, docs/any-angle-ants.md):
// the recommended pipeline on a small and a 512x512 Moving AI map, 1 thread, seeds 1..N. An ant
// step is one move of one ant: its transition rule over the node's candidates and the move,
// backtracking included (ColonyResult::ant_steps). ns per ant step divides the whole run's time
// by the run's ant steps, so the per-run set-up, the local search and the line-of-sight length of
// each arrived walk are spread over them. Lengths: the colony's own (the taut length for
// line-of-sight walks), the path's grid length, and the prune smoother's on the path, against the
// exact any-angle optimum.
void time_any_angle(aco::PluginRegistry& registry, const std::filesystem::path& shared,
                    const std::vector<std::pair<std::string, int>>& problems, int repeats) {
  const aco::Keys robust = robust_preset();
  const aco::ColonySettings preset = aco::resolve_run(robust, registry).colony;
  const auto prune = aco::instantiate(registry, aco::resolve_run({{"smoother", "prune"}}, registry).pipeline);
  struct Variant {
    const char* name;
    aco::Neighbourhood neighbourhood;
    aco::WalkLength walk_length;
    int sight_limit;
  };
  const std::vector<Variant> variants = {
      {"8, grid", aco::Neighbourhood::eight, aco::WalkLength::grid, 0},
      {"16, grid", aco::Neighbourhood::sixteen, aco::WalkLength::grid, 0},
      {"8, line-of-sight, no limit", aco::Neighbourhood::eight, aco::WalkLength::line_of_sight, 0},
      {"8, line-of-sight, limit 32", aco::Neighbourhood::eight, aco::WalkLength::line_of_sight, 32},
      {"16, line-of-sight, limit 32", aco::Neighbourhood::sixteen, aco::WalkLength::line_of_sight, 32},
  };
  for (const auto& [file, index] : problems) {
    const auto scenarios = aco::load_scenarios((shared / file).string() + ".scen");
    if (index < 0 || index >= int(scenarios.size())) throw aco::Error("scenario index out of range for " + file);
    const aco::Scenario& s = scenarios[index];
    const auto map = load(shared / file);
    const auto optimum = aco::any_angle_optimum(*map, s.start, s.goal);
    std::printf(
        "\n== grid ants and line-of-sight walks on %s #%d (%dx%d), %s -> %s, robust preset, 1 thread, %d runs ==\n"
        "any-angle optimum %.2f, octile optimum %.2f; lengths are means, \"prune\" is the prune smoother's\n",
        file.c_str(), index, map->width(), map->height(), aco::to_string(s.start).c_str(),
        aco::to_string(s.goal).c_str(), repeats, optimum ? optimum->length : -1.0, s.optimal_length);
    std::printf("%-28s %12s %8s %10s %12s %10s %10s %10s %12s\n", "neighbourhood, walk length", "ns/ant step", "ratio",
                "ms/run", "steps/run", "colony", "grid", "prune", "prune/opt.");
    double base_ns = 0;
    for (const Variant& v : variants) {
      const aco::Graph graph = aco::build_graph(*map, {v.neighbourhood, false});
      aco::ColonySettings settings = preset;
      settings.walk_length = v.walk_length;
      settings.sight_limit = v.sight_limit;
      const Timing t = time_runs(graph, s.start, s.goal, registry, robust, settings, repeats, 1);
      double grid = 0, pruned = 0;
      int solved = 0;
      aco::Context context;
      context.graph = &graph;
      for (const auto& path : t.paths) {
        if (path.empty()) continue;
        ++solved;
        context.start = path.front();
        context.goal = path.back();
        grid += aco::path_length(graph, path);
        pruned += aco::polyline_length(prune.smoother->smooth(context, path));
      }
      if (base_ns == 0) base_ns = t.ns_per_step;
      const double n = std::max(solved, 1);
      std::printf("%-28s %12.1f %8.2f %10.1f %12llu %10.2f %10.2f %10.2f %12.4f\n", v.name, t.ns_per_step,
                  t.ns_per_step / base_ns, t.total_ms / repeats,
                  static_cast<unsigned long long>(t.total_steps / repeats), t.mean_length, grid / n, pruned / n,
                  optimum ? pruned / n / optimum->length : -1.0);
    }
  }
}

// A map drawn `factor` times larger: every cell a factor x factor block.
aco::OccupancyGrid upsampled(const aco::Map& map, int factor) {
  aco::OccupancyGrid big(map.width() * factor, map.height() * factor, map.name() + " x" + std::to_string(factor));
  for (int y = 0; y < big.height(); ++y)
    for (int x = 0; x < big.width(); ++x) big.set_blocked({x, y}, !map.passable({x / factor, y / factor}));
  return big;
}

// The recommended pipeline (data/presets/robust.ini) as the map grows, 2 threads: classic map1
// (20x20) corner to corner, the large map's scenario (512x512), and the same map drawn 4 times
// larger (2048x2048) with the scenario's cells scaled. ns per ant step = run time / ant steps;
// the process's peak memory after the 2048x2048 runs is theirs (the largest by far).
void time_scale(aco::PluginRegistry& registry, const std::filesystem::path& shared, const std::string& large,
                int large_index, int repeats, int large_repeats, int scale_repeats) {
  const aco::Keys robust = robust_preset();
  const aco::ColonySettings settings = aco::resolve_run(robust, registry).colony;
  std::printf("\n== the recommended pipeline (data/presets/robust.ini) as the map grows, 2 threads ==\n");
  std::printf("%-34s %12s %12s %12s %14s %8s %10s\n", "map", "edges", "median ms", "ns/ant step", "ant steps", "gap %",
              "peak MiB");
  tbb::global_control allow(tbb::global_control::max_allowed_parallelism, 2);
  const auto row = [&](const std::string& name, const aco::Graph& graph, aco::Cell start, aco::Cell goal, int runs) {
    const Timing t = time_runs(graph, start, goal, registry, robust, settings, runs, 2);
    const auto optimal = aco::astar(graph, graph.node(start), graph.node(goal));
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("%-34s %12d %12.1f %12.1f %14llu %8.2f %10.0f\n", name.c_str(), graph.num_edges(), t.median_ms,
                t.ns_per_step, static_cast<unsigned long long>(t.total_steps / runs),
                optimal && t.last.solved ? aco::gap_percent(t.mean_length, optimal->length) : -1.0,
                usage.ru_maxrss / 1024.0);
  };
  const auto classic = load(std::filesystem::path(ACO_BENCH_DATA_DIR) / "maps/classic20/map1.txt");
  row("classic map1 (20x20)", aco::build_graph(*classic, {}), {0, 0}, {19, 19}, repeats);
  const auto problem = load_large(shared, large, large_index);
  const aco::Scenario& s = problem->scenario;
  row(large + " #" + std::to_string(large_index), problem->graph, s.start, s.goal, large_repeats);
  constexpr int kFactor = 4;
  const aco::OccupancyGrid big = upsampled(*problem->map, kFactor);
  row(large + " x4 #" + std::to_string(large_index), aco::build_graph(big, {}),
      {s.start.x * kFactor, s.start.y * kFactor}, {s.goal.x * kFactor, s.goal.y * kFactor}, scale_repeats);
}

// Paper 003's DWA (local/dwa) at one control step on its 20x20 map: the robot at (5, 6) heading
// for (8, 7) at 0.5 m/s, every blocked cell within 7 sensed, one disc moving; with the paper's
// defaults, then following the path (local.follow 0.5). Reports microseconds per step and the
// sampled velocities (each rolled out) per second.
void time_dwa(aco::PluginRegistry& registry, int repeats) {
  const auto map = load(std::filesystem::path(ACO_BENCH_DATA_DIR) / "maps/papers/paper003_20.map");
  const auto& descriptor = registry.load("local", "dwa");
  aco::LocalView view;
  view.robot.x = 5.0, view.robot.y = 6.0, view.robot.heading = 0.3, view.robot.v = 0.5;
  view.goal = {8.0, 7.0};
  const std::vector<Eigen::Vector2d> path = {{5.0, 6.0}, {8.0, 7.0}, {12.0, 12.0}, {19.0, 19.0}};
  view.path = path;
  std::vector<Eigen::Vector2d> cells;
  for (int y = -1; y <= map->height(); ++y)
    for (int x = -1; x <= map->width(); ++x)
      if (!map->passable({x, y}) && (Eigen::Vector2d(x, y) - view.robot.position()).norm() <= 7.0)
        cells.emplace_back(x, y);
  const std::vector<aco::MovingObstacle> moving = {{{9.0, 9.0}, {-0.3, 0.0}, 0.3}};
  view.cells = cells;
  view.moving = moving;
  std::printf("\n== local/dwa on data/maps/papers/paper003_20.map, %zu cells sensed, 1 moving disc ==\n", cells.size());
  for (const char* follow : {"0", "0.5"}) {
    const aco::ParameterValues values = aco::resolve(descriptor.parameters(), {{"follow", follow}}, "local.");
    const auto dwa = registry.create<aco::LocalPlanner>("local", "dwa", values);
    const aco::DynamicWindow w = aco::dynamic_window(view.robot, view.limits, view.period);
    // The plugin samples each range every resolution, both ends included, plus w = 0.
    const int samples = static_cast<int>(std::floor((w.v_high - w.v_low) / values.real("v_resolution") + 1e-9) + 1) *
                        static_cast<int>(std::floor((w.w_high - w.w_low) / values.real("w_resolution") + 1e-9) + 2);
    const int calls = 200 * repeats;
    aco::VelocityCommand c;
    const auto began = std::chrono::steady_clock::now();
    for (int i = 0; i < calls; ++i) c = dwa->command(view);
    const double us =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - began).count() / calls;
    std::printf(
        "follow %-3s: %.1f us per control step, about %d sampled velocities each: %.0f rollouts per second "
        "(command v %.2f, w %.3f)\n",
        follow, us, samples, samples * 1e6 / us, c.v, c.w);
  }
}

const std::set<std::string> kSections = {"classic",       "fireworks", "terrain",   "large",
                                         "large-plugins", "scale",     "any-angle", "dwa"};

// "--only terrain,large" -> {"terrain", "large"}; empty text = every section.
std::set<std::string> parse_sections(const std::string& text) {
  if (text.empty()) return kSections;
  std::set<std::string> sections;
  std::istringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    if (!kSections.count(name))
      throw aco::Error("--only: unknown section '" + name +
                       "' (sections: classic, fireworks, terrain, large, large-plugins, scale, any-angle, dwa)");
    sections.insert(name);
  }
  return sections;
}

}  // namespace

int main(int argc, char** argv) try {
  int repeats = 30;
  std::string maps = ACO_BENCH_DATA_DIR "/maps";
  std::string large = "movingai/street/Berlin_0_512.map";
  int large_index = 400;
  int large_repeats = 5;
  int large_plugin_repeats = 3;
  int scale_repeats = 3;
  int any_angle_repeats = 5;
  std::string small = "movingai/arena.map";
  int small_index = 159;
  std::string only;
  po::options_description options("aco_bench options");
  options.add_options()("help,h", "print this help")("repeats", po::value(&repeats),
                                                     "runs per small-map measurement (seeds 1..N)")(
      "only", po::value(&only),
      "comma-separated sections to run: classic, fireworks, terrain, large, large-plugins, scale, any-angle, dwa "
      "(default: all)")("maps", po::value(&maps), "folder the large map is in (default: the project's data/maps)")(
      "large-map", po::value(&large), "512x512 map for the large-map sections, relative to --maps")(
      "large-scen-index", po::value(&large_index), "scenario of the large map (from its .scen file)")(
      "large-repeats", po::value(&large_repeats), "runs per thread count on the large map")(
      "large-plugin-repeats", po::value(&large_plugin_repeats), "runs per plugin in the large-plugins section")(
      "scale-repeats", po::value(&scale_repeats), "runs on the 2048x2048 map in the scale section")(
      "small-map", po::value(&small), "small map for the any-angle section, relative to --maps")(
      "small-scen-index", po::value(&small_index), "scenario of the small map")(
      "any-angle-repeats", po::value(&any_angle_repeats), "runs per variant and map in the any-angle section");
  po::variables_map vm;
  po::store(po::parse_command_line(argc, argv, options), vm);
  po::notify(vm);
  if (vm.count("help")) {
    std::cout << options;
    return 0;
  }
  if (repeats < 1 || large_repeats < 1 || large_plugin_repeats < 1 || scale_repeats < 1 || any_angle_repeats < 1)
    throw aco::Error("repeats must be >= 1");
  const std::set<std::string> sections = parse_sections(only);
  aco::PluginRegistry registry(aco::PluginRegistry::default_search_dirs());

  bool identical = true;
  if (sections.count("classic")) time_classic(registry, repeats);
  if (sections.count("fireworks")) time_fireworks(repeats);
  if (sections.count("dwa")) time_dwa(registry, repeats);
  if (sections.count("terrain")) identical = time_terrain(registry, repeats) && identical;
  if (sections.count("large")) identical = time_large(registry, maps, large, large_index, large_repeats) && identical;
  if (sections.count("large-plugins"))
    identical = time_large_plugins(registry, maps, large, large_index, large_plugin_repeats) && identical;
  if (sections.count("scale")) time_scale(registry, maps, large, large_index, repeats, large_repeats, scale_repeats);
  if (sections.count("any-angle"))
    time_any_angle(registry, maps, {{small, small_index}, {large, large_index}}, any_angle_repeats);
  return identical ? 0 : 1;
} catch (po::error& e) {
  std::cerr << "aco_bench: error: " << aco::program_options_message(e) << "\n";
  return 1;
} catch (const std::exception& e) {
  std::cerr << "aco_bench: error: " << e.what() << "\n";
  return 1;
}
