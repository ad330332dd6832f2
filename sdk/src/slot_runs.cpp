#include "slot_runs.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>

#include "aco/path.hpp"
#include "plugin_files.hpp"

namespace aco::conformance {
namespace {

namespace fs = std::filesystem;

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
  if (g.position(g.node(c)) != p) return std::nullopt;
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

}  // namespace

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
    if (!specs.updates_by_node || (iteration == 0 && specs.varies_by_iteration)) continue;
    // The contract of update_node(): from iteration 0's values (a heuristic that varies by
    // iteration) or from nothing (one computed by node only, `since` -1), bit for bit what
    // compute_powered() gives in this iteration.
    const int since = specs.varies_by_iteration ? 0 : -1;
    for (NodeId n = 0; n < problem.graph.num_nodes(); ++n) {
      const auto begin = problem.graph.edges_begin(n), end = problem.graph.edges_end(n);
      std::vector<double> updated(first.begin() + begin, first.begin() + end);
      if (since < 0) std::fill(updated.begin(), updated.end(), nan);
      heuristic.update_node(c, n, since, updated);
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
    if ((points.front() - problem.graph.position(path.front())).norm() > 1e-9 ||
        (points.back() - problem.graph.position(path.back())).norm() > 1e-9)
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
  for (const NodeId n : shortest) path.push_back(problem.graph.position(n).head<2>());
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

void run_colony_filled(ColonyStrategies pipeline, const Problem& problem, const ColonySettings& settings,
                       Trace& trace) {
  auto init = default_instance<PheromoneInit>("init");
  auto heuristic = default_instance<Heuristic>("heuristic");
  auto update = default_instance<PheromoneUpdate>("update");
  auto deadlock = default_instance<DeadlockPolicy>("deadlock");
  if (!pipeline.init) pipeline.init = init.get();
  if (!pipeline.heuristic) pipeline.heuristic = heuristic.get();
  if (!pipeline.update) pipeline.update = update.get();
  if (!pipeline.deadlock) pipeline.deadlock = deadlock.get();
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

}  // namespace aco::conformance
