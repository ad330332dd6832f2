// Batches of generated variations of a scenario: unknown cells near the global path, and discs
// crossing it.
#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/parallel.hpp"
#include "aco/planning/planning.hpp"
#include "aco/rng.hpp"
#include "aco/thread_limit.hpp"
#include "aco/simulation/batch.hpp"

namespace aco::simulation {
namespace {

using nlohmann::json;

// The point at arc-length share u of a polyline, and the direction of travel there.
std::pair<Eigen::Vector2d, Eigen::Vector2d> along(const std::vector<Eigen::Vector2d>& path, double u) {
  double total = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) total += (path[i] - path[i - 1]).norm();
  double left = u * total;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d leg = path[i] - path[i - 1];
    if (left <= leg.norm() || i + 1 == path.size())
      return {path[i - 1] + leg * std::min(1.0, left / leg.norm()), leg.normalized()};
    left -= leg.norm();
  }
  return {path.front(), Eigen::Vector2d(1.0, 0.0)};
}

// A variation's result between processes, without its frames: JSON sent as CBOR, which keeps
// every double's bits (the smallest clearance of a run that saw nothing is infinite).
json result_json(const SimulationResult& r) {
  json plans = json::array(), sensed = json::array();
  for (const auto& plan : r.plans) {
    json points = json::array();
    for (const Eigen::Vector2d& p : plan) points.push_back({p.x(), p.y()});
    plans.push_back(std::move(points));
  }
  for (const aco::Cell& c : r.sensed) sensed.push_back({c.x, c.y});
  return {{"reached", r.reached},
          {"outcome", r.outcome},
          {"reason", r.reason},
          {"time", r.time},
          {"distance", r.distance},
          {"min_clearance", r.min_clearance},
          {"collisions", r.collisions},
          {"replans", r.replans},
          {"steps", r.steps},
          {"plans", plans},
          {"sensed", sensed}};
}

SimulationResult result_from(const json& j) {
  SimulationResult r;
  r.reached = j.at("reached");
  r.outcome = j.at("outcome");
  r.reason = j.at("reason");
  r.time = j.at("time");
  r.distance = j.at("distance");
  r.min_clearance = j.at("min_clearance");
  r.collisions = j.at("collisions");
  r.replans = j.at("replans");
  r.steps = j.at("steps");
  for (const json& points : j.at("plans")) {
    r.plans.emplace_back();
    for (const json& p : points) r.plans.back().emplace_back(p.at(0).get<double>(), p.at(1).get<double>());
  }
  for (const json& c : j.at("sensed")) r.sensed.push_back({c.at(0).get<int>(), c.at(1).get<int>()});
  return r;
}

BatchSummary summarize(std::vector<SimulationResult> results) {
  BatchSummary b;
  b.runs = static_cast<int>(results.size());
  double time = 0.0, clearance = 0.0;
  int clear_count = 0;
  for (const SimulationResult& r : results) {
    b.reached += r.reached;
    b.collisions += r.collisions;
    b.replans += r.replans;
    b.outcomes[r.outcome] += 1;
    if (r.reached) time += r.time;
    if (std::isfinite(r.min_clearance)) clearance += r.min_clearance, ++clear_count;
    if (r.reached && r.collisions > 0) ++b.reached_with_collision;
  }
  b.results = std::move(results);
  b.mean_time = b.reached ? time / b.reached : 0.0;
  b.mean_clearance = clear_count ? clearance / clear_count : 0.0;
  return b;
}

}  // namespace

std::vector<Scenario> variations(const Scenario& base, int count, std::uint64_t seed, aco::PluginRegistry& registry) {
  const aco::Graph graph = aco::build_graph(*base.map, base.run.graph);
  const aco::PlanOutcome plan = aco::plan(registry, graph, graph.node(base.start), graph.node(base.goal), base.run);
  if (!plan.solved()) throw aco::Error("batch: the scenario's map has no path from start to goal: " + plan.reason);
  std::vector<Eigen::Vector2d> path;
  for (const auto& p : plan.path) path.push_back(p.head<2>());
  const Eigen::Vector2d start(base.start.x, base.start.y), goal(base.goal.x, base.goal.y);

  aco::BreadthFirstSearch reach;
  std::vector<Scenario> out;
  for (int k = 0; k < count; ++k) {
    aco::Rng rng = aco::Rng::stream(seed, static_cast<std::uint64_t>(k));
    Scenario s = base;
    s.unknown.clear();
    s.moving.clear();
    // One to three unknown cells on or next to the path, clear of the start and the goal, and
    // never sealing the goal off: a variation no robot could finish measures nothing.
    const int cells = 1 + static_cast<int>(rng.below(3));
    std::vector<std::uint8_t> closed(graph.num_nodes(), 0);
    for (int tries = 0; static_cast<int>(s.unknown.size()) < cells && tries < 100; ++tries) {
      const Eigen::Vector2d p = along(path, rng.uniform(0.15, 0.85)).first;
      const aco::Cell c{static_cast<int>(std::lround(p.x())) + static_cast<int>(rng.below(3)) - 1,
                        static_cast<int>(std::lround(p.y())) + static_cast<int>(rng.below(3)) - 1};
      if (!base.map->passable(c) || (Eigen::Vector2d(c.x, c.y) - start).norm() < 2.5 ||
          (Eigen::Vector2d(c.x, c.y) - goal).norm() < 2.5 || closed[graph.node(c)])
        continue;
      closed[graph.node(c)] = 1;
      if (!reach.find(graph, graph.node(base.start), graph.node(base.goal), closed)) {
        closed[graph.node(c)] = 0;
        continue;
      }
      s.unknown.push_back(c);
    }
    // One or two discs crossing the path from 3 to 5 away on either side, 0.2 to 0.5 per second.
    const int discs = 1 + static_cast<int>(rng.below(2));
    for (int d = 0; d < discs; ++d) {
      const auto [p, direction] = along(path, rng.uniform(0.2, 0.8));
      const Eigen::Vector2d across(-direction.y(), direction.x());
      const double side = rng.below(2) ? 1.0 : -1.0, distance = rng.uniform(3.0, 5.0), speed = rng.uniform(0.2, 0.5);
      MovingObstacle m;
      m.route = {p + side * distance * across};
      m.velocity = -side * speed * across;
      m.radius = 0.3;
      if ((m.position(0.0) - start).norm() < m.radius + base.robot.radius + 1.0) continue;
      s.moving.push_back(m);
    }
    out.push_back(std::move(s));
  }
  return out;
}

BatchSummary run_batch(const std::vector<Scenario>& scenarios, aco::PluginRegistry& registry) {
  std::vector<SimulationResult> results(scenarios.size());
  aco::parallel_for(std::size_t(0), scenarios.size(), [&](std::size_t i) {
    SimulationResult r = simulate(scenarios[i], registry);
    r.frames.clear();  // a batch keeps the figures, not the trajectories
    results[i] = std::move(r);
  });
  return summarize(std::move(results));
}

BatchSummary run_batch_in_workers(int count, const std::vector<std::string>& command, int lanes,
                                  const aco::WorkerLimits& limits,
                                  const std::function<void(int variation, const SimulationResult&)>& failed) {
  std::vector<std::unique_ptr<aco::WorkerProcess>> workers;  // each started by its first request
  for (int i = 0; i < lanes; ++i) workers.push_back(std::make_unique<aco::WorkerProcess>(command));
  std::vector<SimulationResult> results(static_cast<std::size_t>(count));
  std::mutex mutex;
  aco::run_on_lanes(lanes, results.size(), [&](int lane, std::size_t k) {
    const aco::WorkerReply reply = workers[static_cast<std::size_t>(lane)]->request(std::to_string(k), limits);
    if (reply.failure_kind == aco::FailureKind::none) {
      results[k] = result_from(json::from_cbor(reply.bytes));
      return;
    }
    // A variation over the time limit ran out of time, as one over its scenario's own limit does:
    // the outcome is the outcome table's. A crash or a memory overrun is no outcome a simulation
    // has: its failure's text.
    results[k].outcome = reply.failure_kind == aco::FailureKind::timed_out ? to_string(Outcome::timeout)
                                                                           : aco::to_string(reply.failure_kind);
    results[k].reason = reply.failure;
    const std::lock_guard lock(mutex);
    failed(static_cast<int>(k), results[k]);
  });
  return summarize(std::move(results));
}

void serve_variations(const Scenario& base, int count, std::uint64_t seed, aco::PluginRegistry& registry) {
  // One variation at a time on this thread: the parent runs a worker per core, and its "where
  // are you" signal goes to this thread.
  const aco::ThreadLimit threads(1);
  std::vector<Scenario> runs;
  aco::serve_worker_requests([&](const std::string& request) {
    if (runs.empty()) runs = variations(base, count, seed, registry);
    SimulationResult r = simulate(runs.at(std::stoul(request)), registry);
    r.frames.clear();
    const std::vector<std::uint8_t> reply = json::to_cbor(result_json(r));
    return std::string(reply.begin(), reply.end());
  });
}

}  // namespace aco::simulation
