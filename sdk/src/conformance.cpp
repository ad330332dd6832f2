#include "aco/conformance.hpp"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <fstream>
#include <mutex>

#include <unistd.h>

#include "aco/astar.hpp"
#include "aco/path.hpp"
#include "aco/pipeline.hpp"
#include "aco/plugin_guard.hpp"

namespace aco::conformance {
namespace {

namespace fs = std::filesystem;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  return text;
}

}  // namespace

// --- Standard problems and iterations --------------------------------------------------------

Context Problem::context(int iteration, int iterations, std::uint64_t seed) const {
  const ColonySettings colony;
  Context c;
  c.graph = &graph;
  c.start = start;
  c.goal = goal;
  c.ants = 8;
  c.max_iterations = iterations;
  c.alpha = colony.alpha;
  c.beta = colony.beta;
  c.seed = seed;
  c.iteration = iteration;
  return c;
}

std::vector<NodeId> Problem::shortest_path() const {
  const auto path = astar(graph, start, goal);
  if (!path) throw Error("conformance: no path from start to goal on the map '" + name + "'");
  return path->nodes;
}

Problem make_problem(const std::string& name, const std::vector<std::string>& rows, Cell start, Cell goal) {
  auto map =
      std::make_shared<OccupancyGrid>(static_cast<int>(rows.front().size()), static_cast<int>(rows.size()), name);
  for (int y = 0; y < map->height(); ++y)
    for (int x = 0; x < map->width(); ++x) map->set_blocked({x, y}, rows[y][x] == '#');
  Problem p{name, map, build_graph(*map, {}), 0, 0};
  p.start = p.graph.node(start);
  p.goal = p.graph.node(goal);
  return p;
}

std::vector<Problem> standard_problems() {
  std::vector<Problem> problems;
  problems.push_back(
      make_problem("open", {"........", "........", "........", "........", "........", "........"}, {0, 0}, {7, 5}));
  problems.push_back(make_problem(
      "obstacles",
      {"..........", "..#####...", "......#...", ".##...#.#.", "..#...#.#.", "..#.###.#.", "..#.....#.", ".........."},
      {0, 0}, {9, 7}));
  // Two pockets (the left column and the box entered at (2,1)) and the walled-in cell (4,4).
  problems.push_back(make_problem(
      "dead end",
      {".........#", ".#.#####.#", ".#.....#..", ".#.###.#..", ".#.#.#.#..", ".#.###.#..", ".#.....#..", ".#######.."},
      {0, 0}, {9, 7}));
  problems.push_back(make_problem("corridor", {"............"}, {0, 0}, {11, 0}));
  return problems;
}

Problem make_voxel_problem(std::shared_ptr<const VoxelMap> world, Cell start, Cell goal, Neighbourhood neighbourhood) {
  GraphOptions options;
  options.neighbourhood = neighbourhood;
  options.corner_cutting = false;
  Problem p{world->name(), world, build_graph(*world, options), 0, 0};
  p.start = p.graph.node(start);
  p.goal = p.graph.node(goal);
  return p;
}

std::vector<Problem> voxel_problems() {
  auto voxels = std::make_shared<VoxelMap>(10, 8, 6, "voxels");
  auto block = [&](int x0, int x1, int y0, int y1, int z0, int z1) {
    for (int z = z0; z <= z1; ++z)
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) voxels->set_blocked({x, y, z}, true);
  };
  block(5, 5, 0, 7, 0, 5);  // a wall across x = 5 ...
  for (int z = 3; z <= 4; ++z)
    for (int y = 5; y <= 6; ++y) voxels->set_blocked({5, y, z}, false);  // ... with a 2x2 gap high up
  block(2, 2, 2, 2, 0, 5);  // pillars, floor to ceiling
  block(3, 3, 5, 5, 0, 5);
  block(7, 7, 2, 2, 0, 3);  // one that ends below the ceiling
  block(0, 2, 6, 7, 2, 2);  // an overhang
  block(8, 9, 0, 1, 0, 1);  // the corner voxel (9,0,0) walled in: no ant reaches it
  voxels->set_blocked({9, 0, 0}, false);
  auto floors = std::make_shared<VoxelMap>(4, 4, 7, "floors");
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      floors->set_blocked({x, y, 2}, x != 3 || y != 3);  // a floor with a hole at (3,3)
      floors->set_blocked({x, y, 4}, x != 0 || y != 0);  // and one with a hole at (0,0)
    }
  std::vector<Problem> problems;
  problems.push_back(make_voxel_problem(voxels, {0, 0, 0}, {9, 7, 5}));
  problems.push_back(make_voxel_problem(floors, {0, 0, 0}, {3, 3, 6}));
  return problems;
}

Ant walk(const Problem& problem, const std::vector<NodeId>& nodes) {
  Ant ant;
  ant.nodes = nodes;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const EdgeId e = problem.graph.find_edge(nodes[i - 1], nodes[i]);
    if (e < 0) throw Error("conformance: a walk steps between nodes that are not neighbours");
    ant.edges.push_back(e);
    ant.length += problem.graph.cost(e);
  }
  ant.arrived = !nodes.empty() && nodes.back() == problem.goal;
  return ant;
}

Iteration IterationCase::view() const {
  const Ant* best_ant = best >= 0 ? &ants[best] : nullptr;
  return {ants, best_ant, earlier_best ? &*earlier_best : best_ant};
}

std::vector<IterationCase> standard_iterations(const Problem& problem) {
  const std::vector<NodeId> shortest = problem.shortest_path();
  auto prefix = [&](std::size_t n) {
    return walk(problem, {shortest.begin(), shortest.begin() + std::max<std::size_t>(n, 1)});
  };
  // A longer arrived walk: around the middle node of the shortest path, where the map allows.
  std::vector<NodeId> detour = shortest;
  if (shortest.size() > 2) {
    BreadthFirstSearch search;
    if (search.find(problem.graph, problem.start, problem.goal, {}, shortest[shortest.size() / 2]))
      detour = search.path();
  }

  IterationCase arrived{
      "ants arrived", {walk(problem, detour), walk(problem, shortest), prefix(shortest.size() / 2), prefix(1)}, -1, {}};
  arrived.best = arrived.ants[0].length < arrived.ants[1].length ? 0 : 1;
  IterationCase none{"no ant arrived", {prefix(shortest.size() / 2), prefix(shortest.size() / 4), prefix(1)}, -1, {}};
  none.earlier_best = walk(problem, shortest);
  IterationCase dead{"all ants dead", std::vector<Ant>(4, prefix(1)), -1, {}};
  return {arrived, none, dead};
}

// --- Parameter sets ----------------------------------------------------------------------------

std::vector<ParameterSet> parameter_sets(std::span<const ParamSpec> table, std::int64_t integer_cap) {
  std::vector<ParameterSet> sets{{"defaults", {}, ""}};
  for (const ParamSpec& spec : table) {
    const std::string name = spec.name, default_value = spec.default_value;
    auto add = [&](const std::string& value, const std::string& note = "", const std::string& if_refused = "") {
      if (value != default_value) sets.push_back({name + "=" + value + note, {{name, value}}, if_refused});
    };
    if (spec.type == ParamType::boolean) {
      add(default_value == "true" ? "false" : "true", "", "a categorical with the one value it takes");
      continue;
    }
    if (spec.type == ParamType::categorical) {
      for (const auto& choice : choices(spec)) add(choice, "", "no choice '" + choice + "'");
      continue;
    }
    if (spec.type == ParamType::text) continue;  // no other value to try
    const auto range = numeric_range(spec);
    if (!range) continue;
    const bool integer = spec.type == ParamType::integer;
    const double span = range->high - range->low;
    for (const bool low_end : {true, false}) {
      double value = low_end ? range->low : range->high;
      if (!std::isfinite(value)) continue;  // no run at infinity
      if (!low_end && range->step) value = range->low + std::floor(span / *range->step) * *range->step;
      if (low_end ? range->low_open : range->high_open) {
        // Just inside an open end: a thousandth of its size (at least of 1) in, enough for a
        // resolution such as a sampling step not to turn into millions of samples.
        double inward = integer ? 1.0 : std::max(std::abs(value), 1.0) * 1e-3;
        if (std::isfinite(span)) inward = std::min(inward, span / 2);
        value += low_end ? inward : -inward;
      }
      // An end the plugin refuses should have been declared open.
      const std::string declared = spec.range;
      const bool closed = !(low_end ? range->low_open : range->high_open);
      const std::string open_end =
          closed ? "the range " + (low_end ? "(" + declared : declared + ")") : "a narrower range";
      if (!integer) {
        add(number(value), "", open_end);
      } else if (value > static_cast<double>(integer_cap)) {
        add(std::to_string(std::max<std::int64_t>(integer_cap, static_cast<std::int64_t>(std::ceil(range->low)))),
            " (range end " + number(value) + " capped)", "a narrower range");
      } else {
        add(std::to_string(static_cast<std::int64_t>(value)), "", open_end);
      }
    }
  }
  return sets;
}

// --- Results -----------------------------------------------------------------------------------

std::string CheckResult::line() const {
  const char* word = status == Status::pass ? "PASS" : status == Status::fail ? "FAIL" : "SKIP";
  return std::string(word) + " " + plugin + " [" + parameters + "] " + check + (detail.empty() ? "" : ": " + detail);
}

std::string bad_value(std::span<const double> values, const std::string& what, double minimum, bool strict) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!std::isfinite(v) || v < minimum || (strict && v == minimum))
      return what + "[" + std::to_string(i) + "] = " + number(v) + " (must be finite and " + (strict ? "> " : ">= ") +
             number(minimum) + ")";
  }
  return "";
}

// --- Finding plugins ---------------------------------------------------------------------------

namespace {

PluginRegistry& registry_of_folder(const fs::path& folder) {
  static std::mutex mutex;
  static std::map<fs::path, std::unique_ptr<PluginRegistry>> registries;
  std::lock_guard lock(mutex);
  auto& registry = registries[folder];
  if (!registry) registry = std::make_unique<PluginRegistry>(std::vector<fs::path>{folder});
  return *registry;
}

std::pair<PluginRegistry*, std::vector<PluginFile>> plugins_of(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw Error(file.string() + ": no such file");
  const fs::path real = fs::canonical(file);
  PluginRegistry& registry = registry_of_folder(real.parent_path());
  std::vector<PluginFile> found;
  for (const auto& plugin : registry.available())
    if (fs::equivalent(plugin.file, real, ec)) found.push_back(plugin);
  if (found.empty())
    throw Error(file.string() +
                ": exports no aco plugin (or each is shadowed by a plugin of the same slot and name in a "
                "file of its folder that sorts before it)");
  return {&registry, found};
}

// The other slots of a colony: the default plugins, found where an installed or build-tree host
// finds them.
PluginRegistry& default_plugins() {
  static PluginRegistry registry(PluginRegistry::default_search_dirs());
  return registry;
}

template <class Interface>
std::unique_ptr<Interface> default_instance(const std::string& slot) {
  PluginRegistry& registry = default_plugins();
  const std::string name = default_plugin(slot);
  return registry.create<Interface>(slot, name, resolve(registry.load(slot, name).parameters(), {}, slot + "."));
}

}  // namespace

std::vector<PluginFile> plugins_in(const fs::path& file) { return plugins_of(file).second; }

std::pair<PluginRegistry*, PluginFile> find_in(const fs::path& file, const std::string& slot) {
  auto [registry, plugins] = plugins_of(file);
  for (const auto& plugin : plugins)
    if (plugin.slot == slot) return {registry, plugin};
  throw Error(file.string() + ": exports no " + slot + " plugin");
}

// --- Running a plugin --------------------------------------------------------------------------

namespace {

// Everything a plugin produced in one run of the checks, in order, and what was wrong with it.
struct Trace {
  std::vector<double> values;
  std::vector<std::pair<std::size_t, std::string>> sections;  // where each labelled part starts
  std::vector<std::string> problems;
  std::string section;  // the label of the part being recorded, for messages

  void begin(const std::string& label) {
    section = label;
    sections.emplace_back(values.size(), label);
  }
  void add(std::span<const double> v) { values.insert(values.end(), v.begin(), v.end()); }
  void add(double v) { values.push_back(v); }
  void problem(const std::string& what) { problems.push_back(section + ": " + what); }
  // Records the values, labelled for messages, and notes the first bad one.
  void add_checked(std::span<const double> v, const std::string& what, double minimum = 0.0, bool strict = false) {
    if (const auto bad = bad_value(v, what, minimum, strict); !bad.empty()) problem(bad);
    sections.emplace_back(values.size(), section + ": " + what);
    add(v);
  }
  // "open: tau after start(): value 12", for the value at `index`.
  std::string describe(std::size_t index) const {
    std::string label = "value " + std::to_string(index);
    for (const auto& [start, name] : sections)
      if (start <= index) label = name + ": value " + std::to_string(index - start);
    return label;
  }
};

bool same_bits(std::span<const double> a, std::span<const double> b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// "" if the traces hold the same values bit for bit, else where they first differ.
std::string difference(const Trace& a, const Trace& b) {
  const std::size_t n = std::min(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < n; ++i)
    if (!same_bits(std::span(a.values).subspan(i, 1), std::span(b.values).subspan(i, 1)))
      return a.describe(i) + " is " + number(a.values[i]) + " in one run and " + number(b.values[i]) + " in the other";
  if (a.values.size() != b.values.size())
    return "one run produced " + std::to_string(a.values.size()) + " values, the other " +
           std::to_string(b.values.size());
  return "";
}

constexpr int kIterations = 10;

void run_slot(PheromoneInit& init, const Problem& problem, Trace& trace) {
  std::vector<double> tau(problem.graph.num_edges(), std::numeric_limits<double>::quiet_NaN());
  init.initialize(problem.context(0, kIterations), tau);
  trace.add_checked(tau, "tau after initialize()", 0.0, true);
}

void run_slot(Heuristic& heuristic, const Problem& problem, Trace& trace) {
  const std::size_t edges = problem.graph.num_edges();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // As the engine calls it: compute_powered() once per run, or in every iteration in turn on the
  // values it left the iteration before (a heuristic may update them rather than recompute).
  std::vector<double> eta_beta(edges, nan), first;
  const HeuristicSpecs specs = heuristic.specs();
  const int last = specs.varies_by_iteration ? kIterations - 1 : 0;
  for (int iteration = 0; iteration <= last; ++iteration) {
    const Context c = problem.context(iteration, kIterations);
    std::vector<double> eta(edges, nan);
    heuristic.compute(c, eta);
    trace.add_checked(eta, "eta after compute() in iteration " + std::to_string(iteration));
    heuristic.compute_powered(c, eta_beta);
    trace.add_checked(eta_beta, "eta^beta after compute_powered() in iteration " + std::to_string(iteration));
    if (iteration == 0) first = eta_beta;
    if (iteration == 0 || !specs.updates_by_node) continue;
    // The contract of update_node(): from iteration 0's values, bit for bit what
    // compute_powered() gives in this iteration.
    for (NodeId n = 0; n < problem.graph.num_nodes(); ++n) {
      const auto begin = problem.graph.edges_begin(n), end = problem.graph.edges_end(n);
      std::vector<double> updated(first.begin() + begin, first.begin() + end);
      heuristic.update_node(c, n, 0, updated);
      if (!same_bits(updated, std::span(eta_beta).subspan(begin, end - begin))) {
        trace.problem("update_node() of node " + std::to_string(n) + " in iteration " + std::to_string(iteration) +
                      " differs from compute_powered()");
        break;
      }
    }
  }
  if (!specs.uses_walk) return;
  const std::vector<NodeId> path = problem.shortest_path();
  Ant ant;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    ant.nodes.push_back(path[i]);
    if (i > 0) ant.edges.push_back(problem.graph.find_edge(path[i - 1], path[i]));
    std::vector<EdgeId> candidates;
    for (EdgeId e = problem.graph.edges_begin(path[i]); e < problem.graph.edges_end(path[i]); ++e)
      candidates.push_back(e);
    std::vector<double> factors(candidates.size(), nan);
    heuristic.step_factors(problem.context(0, kIterations), ant, candidates, factors);
    trace.add_checked(factors, "factors of step_factors() at step " + std::to_string(i));
  }
}

// "(1, 2, 3)"
std::string text(const Eigen::Vector3d& p) {
  return "(" + number(p.x()) + ", " + number(p.y()) + ", " + number(p.z()) + ")";
}

// The cell whose centre (graph position) the point is exactly, if any.
std::optional<Cell> centre_of(const Graph& g, const Eigen::Vector3d& p) {
  if (!p.allFinite()) return std::nullopt;
  const auto in = [](double v, int size) { return v > -0.5 && v < size - 0.5; };
  if (!in(p.x(), g.width) || !in(p.y(), g.height) || !in(p.z(), g.depth)) return std::nullopt;
  const Cell c{static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())),
               g.volumetric ? static_cast<int>(std::lround(p.z())) : 0};
  if (g.positions[g.node(c)] != p) return std::nullopt;
  return c;
}

// What the engine's ants read of a trail: tau(e) for every edge, or the stored value where that
// is negative or NaN (the check's business, which reading within the bounds would hide).
std::vector<double> read(const Trail& trail) {
  std::vector<double> tau(trail.size());
  for (std::size_t e = 0; e < tau.size(); ++e) {
    const double stored = trail.stored()[e];
    tau[e] = stored >= 0.0 ? trail[static_cast<EdgeId>(e)] : stored;
  }
  return tau;
}

// As the engine calls it: update_trail() on one trail kept through the run (the default calls
// update() with its values; a rule such as max_min keeps a scale and bounds in it instead).
void run_slot(PheromoneUpdate& update, const Problem& problem, Trace& trace) {
  std::vector<double> stored(problem.graph.num_edges(), 1.0);
  update.start(problem.context(0, kIterations), stored);
  trace.add_checked(stored, "tau after start()");
  Trail trail(stored);
  int iteration = 0;
  for (const auto& ants : standard_iterations(problem)) {
    update.update_trail(problem.context(iteration++, kIterations), ants.view(), trail);
    trace.add_checked(read(trail), "tau after update() of '" + ants.name + "'");
  }
}

void run_slot(DeadlockPolicy& deadlock, const Problem& problem, Trace& trace) {
  std::vector<double> tau(problem.graph.num_edges(), 1.0);
  std::vector<std::uint8_t> forbidden(problem.graph.num_nodes(), 0);
  int iteration = 0;
  for (const auto& ants : standard_iterations(problem)) {
    const Context c = problem.context(iteration++, kIterations);
    for (const Ant& ant : ants.ants) {
      if (ant.arrived) continue;
      const int back = deadlock.on_stuck(c, ant.nodes);
      if (back < 0) trace.problem("on_stuck() returned " + std::to_string(back) + " (must be >= 0)");
      trace.add(back);
    }
    Trail trail(tau);
    deadlock.after_iteration(c, ants.view(), trail, forbidden);
    trace.add_checked(read(trail), "tau after after_iteration() of '" + ants.name + "'");
    if (forbidden.size() != static_cast<std::size_t>(problem.graph.num_nodes()))
      trace.problem("after_iteration() resized the forbidden nodes to " + std::to_string(forbidden.size()));
    for (const auto f : forbidden) trace.add(f);
  }
}

void run_slot(Smoother& smoother, const Problem& problem, Trace& trace) {
  const std::vector<NodeId> shortest = problem.shortest_path();
  const std::vector<std::vector<NodeId>> paths{shortest, {problem.start}, {shortest[0], shortest[1]}};
  for (const auto& path : paths) {
    const auto points = smoother.smooth(problem.context(kIterations - 1, kIterations), path);
    const std::string what = "smooth() of a path of " + std::to_string(path.size()) + " nodes";
    if (points.empty()) {
      trace.problem(what + " returned no waypoints");
      continue;
    }
    for (const auto& p : points)
      trace.add_checked(std::span<const double>(p.data(), 3), what + ": waypoint coordinate", -INFINITY);
    const double length = polyline_length(points);
    trace.add_checked(std::span(&length, 1), what + ": length");
    if ((points.front() - problem.graph.positions[path.front()]).norm() > 1e-9 ||
        (points.back() - problem.graph.positions[path.back()]).norm() > 1e-9)
      trace.problem(what + " does not begin at the path's first node and end at its last");
    // As plan() checks them: every waypoint on a free cell (a free voxel in 3D). And where two
    // consecutive waypoints are cell centres, the straight line between them is free by the
    // graph's corner rule (in 3D through every layer it crosses, not only the start's).
    const auto& g = problem.graph;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].allFinite() && !on_free_cell(g, points[i])) {
        trace.problem(what + ": waypoint " + std::to_string(i) + " (0-based), " + text(points[i]) +
                      ", lies on no free " + (g.volumetric ? "voxel" : "cell"));
        break;
      }
    for (std::size_t i = 1; i < points.size(); ++i) {
      const auto a = centre_of(g, points[i - 1]), b = centre_of(g, points[i]);
      if (a && b && !line_of_sight(*g.map, *a, *b, g.options.corner_cutting)) {
        trace.problem(what + ": the segment from waypoint " + std::to_string(i - 1) + " " + text(points[i - 1]) +
                      " to waypoint " + std::to_string(i) + " " + text(points[i]) + " passes through a blocked " +
                      (g.volumetric ? "voxel" : "cell"));
        break;
      }
    }
  }
}

void run_slot(LocalPlanner& planner, const Problem& problem, Trace& trace) {
  const std::vector<NodeId> shortest = problem.shortest_path();
  std::vector<Eigen::Vector2d> path;
  for (const NodeId n : shortest) path.push_back(problem.graph.positions[n].head<2>());
  const double sensor_range = 3.0;
  struct Drive {
    std::string name;
    Eigen::Vector2d from;
    std::span<const Eigen::Vector2d> path;
    bool moving_obstacle;
  };
  const std::vector<Drive> drives{{"along the path, a moving obstacle ahead", path.front(), path, true},
                                  {"no path known", path.front(), {}, false},
                                  {"at the goal", path.back(), std::span(path).last(1), false}};
  for (const auto& drive : drives) {
    LocalView view;
    view.robot.x = drive.from.x();
    view.robot.y = drive.from.y();
    const Eigen::Vector2d towards = path.back() - path.front();
    view.robot.heading = std::atan2(towards.y(), towards.x());
    view.goal = path[std::min<std::size_t>(3, path.size() - 1)];
    if (drive.from == path.back()) view.goal = path.back();
    std::vector<MovingObstacle> moving;
    if (drive.moving_obstacle) moving.push_back({(drive.from + view.goal) / 2, {-0.2, 0.0}, 0.3});
    for (int step = 0; step < 15; ++step) {
      std::vector<Eigen::Vector2d> cells;
      for (int y = -1; y <= problem.map->height(); ++y)
        for (int x = -1; x <= problem.map->width(); ++x)
          if (!problem.map->passable({x, y}) && (Eigen::Vector2d(x, y) - view.robot.position()).norm() <= sensor_range)
            cells.emplace_back(x, y);
      view.cells = cells;
      view.moving = moving;
      view.path = drive.path;
      trace.begin(problem.name + ", " + drive.name + ", step " + std::to_string(step));
      const VelocityCommand command = planner.command(view);
      const DynamicWindow window = dynamic_window(view.robot, view.limits, view.period);
      trace.add_checked(std::vector<double>{command.v, command.w}, "command (v, w)", -INFINITY);
      if (!window.contains(command, kWindowTolerance))
        trace.problem("command (" + number(command.v) + ", " + number(command.w) + ") lies outside the dynamic window");
      view.robot = move(view.robot, window.clamp(command), view.period);
      for (auto& m : moving) m.position += m.velocity * view.period;
    }
  }
}

// A map reader: it claims an ending or is chosen by name (a name it has: its plugin's); a missing
// file is an Error naming it; its sample, if it gives one, reads into a map of positive size with
// finite positions on its free cells, the same every time (the trace holds the map).
void run_slot(MapReader& reader, const Problem& problem, Trace& trace) {
  if (problem.name != "open") return;  // the first standard problem; nothing depends on it: once per pass
  const std::vector<std::string> extensions = reader.extensions();
  for (const auto& e : extensions)
    if (e.size() < 2 || e.front() != '.')
      trace.problem("extensions(): '" + e + "' is not a file ending such as '.shapes'");
  const std::string ending = extensions.empty() ? ".sample" : extensions.front();
  // Removed however the reads end.
  const struct Folder {
    fs::path path;
    ~Folder() {
      std::error_code ignored;
      fs::remove_all(path, ignored);
    }
  } scratch{fs::temp_directory_path() / ("aco-plugin-check-" + std::to_string(::getpid()))};
  const fs::path& folder = scratch.path;
  fs::create_directories(folder);
  const fs::path missing = folder / ("no such map" + ending);
  try {
    reader.read(missing, {});
    trace.problem("read() of a missing file returned a map instead of an aco::Error naming " + missing.string());
  } catch (const std::exception& e) {
    if (std::string(e.what()).find(missing.string()) == std::string::npos)
      trace.problem("read() of a missing file threw '" + std::string(e.what()) + "', which does not name " +
                    missing.string());
  }
  const std::string sample = reader.sample();
  if (sample.empty()) return;
  const fs::path file = folder / ("sample" + ending);
  std::ofstream(file, std::ios::binary) << sample;
  const std::unique_ptr<Map> map = reader.read(file, {});
  if (!map) return trace.problem("read() of its sample returned no map");
  trace.add(map->width());
  trace.add(map->height());
  trace.add(map->depth());
  const std::string size = std::to_string(map->width()) + "x" + std::to_string(map->height()) +
                           (map->depth() != 1 ? "x" + std::to_string(map->depth()) : "");
  if (map->width() <= 0 || map->height() <= 0 || map->depth() <= 0)
    return trace.problem("its sample reads into a " + size + (map->volumetric() ? " voxel world" : " map"));
  if (map->depth() > 1 && !map->volumetric())
    return trace.problem("its sample reads into a " + size + " map of several layers that is not volumetric()");
  std::vector<double> free_positions;
  for (int z = 0; z < map->depth(); ++z)  // every layer of a voxel world
    for (int y = 0; y < map->height(); ++y)
      for (int x = 0; x < map->width(); ++x) {
        trace.add(map->passable({x, y, z}) ? 1.0 : 0.0);
        if (!map->passable({x, y, z})) continue;
        const Eigen::Vector3d p = map->position({x, y, z});
        free_positions.insert(free_positions.end(), {p.x(), p.y(), p.z()});
      }
  trace.add_checked(free_positions, "positions of the sample's free cells", -INFINITY);
}

// The colony with the plugin in its slot and the default plugins in the others.
template <class Interface>
void run_colony_with(Interface& plugin, const Problem& problem, const ColonySettings& settings, Trace& trace) {
  auto init = default_instance<PheromoneInit>("init");
  auto heuristic = default_instance<Heuristic>("heuristic");
  auto update = default_instance<PheromoneUpdate>("update");
  auto deadlock = default_instance<DeadlockPolicy>("deadlock");
  ColonyStrategies pipeline{init.get(), heuristic.get(), update.get(), deadlock.get()};
  if constexpr (std::is_same_v<Interface, PheromoneInit>) pipeline.init = &plugin;
  if constexpr (std::is_same_v<Interface, Heuristic>) pipeline.heuristic = &plugin;
  if constexpr (std::is_same_v<Interface, PheromoneUpdate>) pipeline.update = &plugin;
  if constexpr (std::is_same_v<Interface, DeadlockPolicy>) pipeline.deadlock = &plugin;
  trace.begin(problem.name + ": colony run");
  const ColonyResult result = run_colony(problem.graph, problem.start, problem.goal, pipeline, settings);
  if (result.solved) {
    trace.add_checked(std::span(&result.length, 1), "path length");
    // The path goes from start to goal along graph edges (in 3D: moves with dz too).
    const Graph& g = problem.graph;
    if (result.path.empty() || result.path.front() != problem.start || result.path.back() != problem.goal)
      trace.problem("the path does not go from the start to the goal");
    bool along_edges = true;
    for (std::size_t i = 1; along_edges && i < result.path.size(); ++i)
      if (g.find_edge(result.path[i - 1], result.path[i]) < 0) {
        trace.problem("the path's step " + std::to_string(i - 1) + " (0-based) from " +
                      to_string(g.cell(result.path[i - 1])) + " to " + to_string(g.cell(result.path[i])) +
                      " is no edge of the graph");
        along_edges = false;
      }
    if (along_edges && std::abs(result.length - path_length(g, result.path)) > 1e-9 * (1 + result.length))
      trace.problem("the path's length is not the sum of its steps");
  }
  for (const NodeId n : result.path) trace.add(n);
  trace.add(result.iteration_best);
  for (const int a : result.arrived) trace.add(a);
  trace.add(static_cast<double>(result.ant_steps));
  trace.add_checked(result.pheromone, "final pheromone");
}

// One pass of every check's runs over the standard problems with one instance of the plugin,
// then the first problem once more with the same instance: the lifecycle's rule (strategies.hpp)
// is that a reused object's run gives what a fresh object's gives.
template <class Interface>
struct Pass {
  static constexpr bool kHasRuns = !std::is_same_v<Interface, MapReader>;
  Trace trace;
  std::string reuse;  // how the second run on the first problem differed, or ""

  Pass(Interface& plugin, const std::vector<Problem>& problems, const Options& options, bool colony) {
    auto run = [&](const Problem& problem, Trace& into) {
      try {
        into.begin(problem.name);
        // A run of the hooks begins as a host's does (the colony run below begins its own).
        if constexpr (kHasRuns) plugin.begin_run(problem.context(0, kIterations));
        run_slot(plugin, problem, into);
        if constexpr (!std::is_same_v<Interface, Smoother> && !std::is_same_v<Interface, LocalPlanner> &&
                      !std::is_same_v<Interface, MapReader>)
          if (colony) run_colony_with(plugin, problem, options.colony, into);
      } catch (const std::exception& e) {
        into.problem(e.what());
      }
    };
    std::size_t first_end = 0;
    for (const auto& problem : problems) {
      run(problem, trace);
      if (first_end == 0) first_end = trace.values.size();
    }
    if constexpr (!kHasRuns) return;
    Trace again;
    run(problems.front(), again);
    Trace first = trace;
    first.values.resize(first_end);
    reuse = difference(first, again);
  }
};

template <class Interface>
void check_typed(PluginRegistry& registry, const PluginFile& plugin, const Options& options, const Report& report) {
  const PluginDescriptor& descriptor = registry.load(plugin.slot, plugin.name);
  const PluginIdentity who{plugin.slot, plugin.name, plugin.file.string()};
  const std::string label = plugin.slot + "/" + plugin.name;
  const std::vector<Problem> problems = standard_problems();
  const std::vector<Problem> voxels = options.voxel_worlds ? voxel_problems() : std::vector<Problem>{};
  bool said_not_3d = false;  // the SKIP line of a plugin that does not claim voxel worlds, once
  const bool colony = !std::is_same_v<Interface, Smoother> && !std::is_same_v<Interface, LocalPlanner> &&
                      !std::is_same_v<Interface, MapReader>;
  const std::vector<ParameterSet> sets = parameter_sets(descriptor.parameters(), options.integer_cap);
  // Whether a refusal of `set`'s value is of a combination the table cannot express (a < b):
  // the message names another parameter, or the factory takes the value beside another
  // parameter's tried value.
  auto taken_in_some_combination = [&](const ParameterSet& set, const std::string& message) {
    for (const ParamSpec& spec : descriptor.parameters()) {
      const std::string name = spec.name;
      if (name == set.given.begin()->first) continue;
      for (auto at = message.find(name); at != std::string::npos; at = message.find(name, at + 1)) {
        const auto word = [&](std::size_t i) {
          return i < message.size() && (std::isalnum(static_cast<unsigned char>(message[i])) || message[i] == '_');
        };
        if ((at == 0 || !word(at - 1)) && !word(at + name.size())) return true;
      }
    }
    for (const auto& other : sets) {
      if (other.given.empty() || other.given.begin()->first == set.given.begin()->first) continue;
      std::map<std::string, std::string> given = set.given;
      given.insert(other.given.begin(), other.given.end());
      given.insert(options.fixed.begin(), options.fixed.end());
      try {
        std::unique_ptr<Strategy>(descriptor.create(resolve(descriptor.parameters(), given, plugin.slot + ".")));
        return true;
      } catch (const Error&) {}
    }
    return false;
  };
  for (const auto& set : sets) {
    auto result = [&](const std::string& check, const std::string& detail, CheckResult::Status status) {
      report({label, set.label, check, status, detail});
    };
    std::map<std::string, std::string> given = set.given;
    given.insert(options.fixed.begin(), options.fixed.end());  // the set's own value wins
    const ParameterValues values = resolve(descriptor.parameters(), given, plugin.slot + ".");
    // A fresh instance per pass; the factory refusing a value with aco::Error is its right.
    auto make = [&]() -> std::unique_ptr<Interface> {
      std::unique_ptr<Strategy> strategy(descriptor.create(values));
      auto* typed = dynamic_cast<Interface*>(strategy.get());
      if (!typed) throw Error("the factory made an object that does not implement the " + plugin.slot + " interface");
      strategy.release();
      return guard(std::unique_ptr<Interface>(typed), who);
    };
    std::unique_ptr<Interface> first;
    try {
      first = make();
    } catch (const Error& e) {
      if (set.if_refused.empty() || taken_in_some_combination(set, e.what())) {
        result("constructs", std::string("refused with an error: ") + e.what(), CheckResult::Status::skip);
      } else {
        const ParamSpec& spec = *std::find_if(descriptor.parameters().begin(), descriptor.parameters().end(),
                                              [&](const ParamSpec& p) { return set.given.count(p.name); });
        result("constructs",
               "refused " + set.label + ", which its declared " +
                   (spec.range && *spec.range ? "range " + std::string(spec.range) : "type") + " admits (" + e.what() +
                   "); declare " + set.if_refused + " or accept the value",
               CheckResult::Status::fail);
      }
      continue;
    } catch (...) {
      result("constructs", "the factory threw " + describe_current_exception(), CheckResult::Status::fail);
      continue;
    }
    using S = CheckResult::Status;
    // The four checks on `worlds`, the first pass with `fresh`; `prefix` ("" or "3D ") names them.
    auto run_checks = [&](const std::string& prefix, const std::vector<Problem>& worlds,
                          std::unique_ptr<Interface> fresh) {
      auto pass = [&](std::unique_ptr<Interface> instance, int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        tbb::task_arena arena(threads);
        return arena.execute([&] { return Pass<Interface>(*instance, worlds, options, colony); });
      };
      // A run on 1 thread and one on 4: the same output shows determinism and thread independence
      // at once. Only when they differ does another run on 1 thread tell which of the two failed.
      const Pass<Interface> one = pass(std::move(fresh), 1);
      std::string by_threads = difference(one.trace, pass(make(), 4).trace);
      std::string nondeterminism;
      if (!by_threads.empty()) {
        nondeterminism = difference(one.trace, pass(make(), 1).trace);
        if (!nondeterminism.empty()) by_threads = "not separable: two runs on 1 thread differ as well";
      }
      const auto& problems_found = one.trace.problems;
      // In a voxel world, what a plugin written for grids gets wrong.
      const std::string hint = prefix.empty() ? ""
                                              : " [in a voxel world Graph::edge_costs and reverse_edges are empty: "
                                                "use cost(e) and reverse_edge(e); cells have z, moves dz]";
      result(
          prefix + "values",
          problems_found.empty()
              ? ""
              : problems_found.front() +
                    (problems_found.size() > 1 ? " (and " + std::to_string(problems_found.size() - 1) + " more)" : "") +
                    hint,
          problems_found.empty() ? S::pass : S::fail);
      result(prefix + "deterministic", nondeterminism, nondeterminism.empty() ? S::pass : S::fail);
      result(prefix + "threads", by_threads.empty() ? "" : "1 vs 4 threads: " + by_threads,
             by_threads.empty() ? S::pass : S::fail);
      if (!Pass<Interface>::kHasRuns) return;
      if (!nondeterminism.empty())
        result(prefix + "reused", "two runs of fresh objects differ already", S::skip);
      else
        result(prefix + "reused",
               one.reuse.empty()
                   ? ""
                   : "a second run of the same object, after runs on other maps, differs from its first: " + one.reuse,
               one.reuse.empty() ? S::pass : S::fail);
    };
    // Whether this object plans in voxel worlds, asked before its first run (as plan() asks).
    // A map reader has no runs to check there (its sample is read whatever its dimension).
    const bool in_3d = options.voxel_worlds && Pass<Interface>::kHasRuns;
    bool claims_3d = false;
    std::string claim_failed;
    if (in_3d) {
      try {
        claims_3d = first->supports_voxel_worlds();
      } catch (...) {
        claim_failed = describe_current_exception();
      }
    }
    if (options.grids) run_checks("", problems, std::move(first));
    if (!in_3d) continue;
    if (!claim_failed.empty()) {
      result("3D", "supports_voxel_worlds() threw " + claim_failed, S::fail);
    } else if (!claims_3d) {
      // Once per plugin: every set after the first that does not claim them would say the same.
      if (!said_not_3d)
        result("3D", "not run in 3D: it does not claim voxel worlds (supports_voxel_worlds() is false)", S::skip);
      said_not_3d = true;
    } else if (std::is_same_v<Interface, LocalPlanner>) {
      result("3D", "not run in 3D: a local planner drives in the plane (acosim); no voxel world reaches it", S::skip);
    } else {
      run_checks("3D ", voxels, first ? std::move(first) : make());
    }
  }
}

}  // namespace

void check_plugin(const PluginFile& plugin, const Options& options, const Report& report) {
  PluginRegistry& registry = *plugins_of(plugin.file).first;
#define ACO_CHECK_SLOT_(NAME, INTERFACE) \
  if (plugin.slot == #NAME) return check_typed<INTERFACE>(registry, plugin, options, report);
  ACO_SLOTS(ACO_CHECK_SLOT_)
#undef ACO_CHECK_SLOT_
  throw Error("plugin " + plugin.slot + "/" + plugin.name + ": unknown slot '" + plugin.slot + "'");
}

int check_file(const fs::path& file, const Options& options, const Report& report) {
  int failures = 0;
  for (const auto& plugin : plugins_in(file)) {
    check_plugin(plugin, options, [&](const CheckResult& r) {
      if (r.status == CheckResult::Status::fail) ++failures;
      report(r);
    });
  }
  return failures;
}

}  // namespace aco::conformance
