#pragma once
// The strategy interfaces a colony is composed of. Each is small: one pure virtual, plus
// optional hooks with harmless defaults. Plugins implement them; see plugin.hpp.
#include <Eigen/Core>
#include <boost/config.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "aco/graph.hpp"
#include "aco/robot.hpp"

namespace aco {

class FigureSink;

// What every strategy sees of the run in progress.
struct Context {
  const Graph* graph = nullptr;
  NodeId start = 0;
  NodeId goal = 0;
  int ants = 0;
  int max_iterations = 0;
  double alpha = 1.0;
  double beta = 1.0;
  std::uint64_t seed = 0;
  int iteration = 0;  // the current iteration, 0-based
  // Where record() and add() go (aco/figures.hpp); null, as in a plugin's own unit test or
  // aco-plugin-check, checks what they are given and keeps nothing.
  FigureSink* figures = nullptr;
  // When the run's time limit ends (none: no limit). The smoother runs after the search, within
  // the limit too: past it, a smoother that refines in rounds stops and returns what it has.
  std::optional<std::chrono::steady_clock::time_point> deadline;
  bool past_deadline() const { return !leaves_time_for({}); }
  // Whether work taking `duration` from now would end before the deadline (always, with none):
  // a round as long as the last one, say.
  bool leaves_time_for(std::chrono::steady_clock::duration duration) const {
    return !deadline || std::chrono::steady_clock::now() + duration < *deadline;
  }

  // A plugin's own figures of its run (restarts, nodes forbidden, deadlocks resolved), kept beside
  // the planner's (PlanOutcome::properties) as "<slot>/<plugin>.<name>": in acoplan's --json,
  // acobench's results database, runs.csv and report. A name is lower-case letters, digits and
  // '_', starting with a letter (at most 64 characters); a value must be finite. Either mistake
  // stops the run with an Error naming the plugin, the hook and the iteration.
  //
  // add(): a count, summed over every call of the run. Thread-safe, and the sum is the same
  // whatever the thread count: the one to use in hooks that run on construction threads
  // (DeadlockPolicy::on_stuck, Heuristic::update_node and step_factors), and for any count.
  // record(): sets a value; the last call of the run wins. Only in single-threaded hooks
  // (begin_run, init, start, update, compute, compute_powered, after_iteration, smooth): called
  // during the ants' construction it is an Error, since which thread's call came last would
  // depend on the thread count. One name is either a count or a value. Add 0 (or record the starting value) in
  // initialize() or start() to have the figure in every run, the ones where nothing happened too.
  void record(std::string_view name, double value) const;
  void add(std::string_view name, std::int64_t delta = 1) const;
};

// One ant's walk in one iteration.
struct Ant {
  std::vector<NodeId> nodes;  // start first; the goal last when the ant arrived
  std::vector<EdgeId> edges;  // edges[i] leads from nodes[i] to nodes[i+1]
  double length = 0.0;  // sum of the step costs of `edges`
  bool arrived = false;
};

// The ants of a finished iteration, in ant order.
struct Iteration {
  std::span<const Ant> ants;
  const Ant* best = nullptr;  // shortest arrived ant of this iteration, or null
  const Ant* best_so_far = nullptr;  // shortest path of the run so far (this iteration included), or null
};

// The lifecycle. A strategy object is made once, by its constructor from its parameters (OMPL's
// setup(), nav2's configure()), and may then serve several runs in turn: studies and benchmarks
// reuse one, and run_colony() repeats a run on the same objects to name the writer of a bad value.
// Every run calls begin_run() first, before any other hook of the run: whatever a strategy keeps
// from one hook to the next (a population, a best length, tables of the map) it sets there, so the
// previous run leaves no trace. The rule, which aco-plugin-check's "reused" check tests: a run of a
// reused object gives bit for bit what a run of a fresh one gives. (Fresh objects for every run
// would need the engine to hold factories rather than the objects callers give it; one hook keeps
// the interfaces as they are and says where the reset goes.) Keep no pointer into a run's data
// (the graph, the context) beyond the run: read them from the Context every hook is given.
//
// Who calls it: the colony, for init, heuristic, update and deadlock (those it asks: a colony of
// the no_learning null model never asks init and update), at the start of every colony
// run; plan() for the smoother before smooth(); acosim for the local planner before a simulation's
// first command (its context holds the seed only: a local planner sees the world through
// LocalView). A map reader has no runs: read() is const and reads one file.
class BOOST_SYMBOL_VISIBLE Strategy {
 public:
  virtual ~Strategy();
  virtual void begin_run(const Context& context);
  // Whether it plans in voxel worlds (Graph::volumetric: cells with z, up to 26 moves, costs and
  // reverse edges by move). False unless a plugin says so: hosts refuse a plugin that does not
  // in a voxel world, with a message naming it, rather than let a grid's assumptions plan wrong.
  virtual bool supports_voxel_worlds() const;
};

// Slot "init": the pheromone of every edge before the first iteration.
class BOOST_SYMBOL_VISIBLE PheromoneInit : public Strategy {
 public:
  ~PheromoneInit() override;
  // Values must be positive and finite; the engine stops the run, naming the plugin, on any that
  // is NaN, infinite or negative (docs/writing-plugins.md, "What the engine checks").
  virtual void initialize(const Context& context, std::span<double> tau) = 0;
};

// What a heuristic can do beyond compute(), read once per run by the engine (after begin_run()).
struct HeuristicSpecs {
  // compute_powered() is called before every iteration, not once per run.
  bool varies_by_iteration = false;
  // A heuristic that changes every iteration costs a pass over every edge per iteration, more
  // than the ants' work on a large map. With varies_by_iteration, it may set this and implement
  // update_node(): the engine then calls compute_powered() in the first iteration only and
  // afterwards brings eta^beta up to date node by node, for the nodes the ants stand on, the
  // first time they do in an iteration. Without varies_by_iteration, it means: computed by node
  // only. The engine never calls compute_powered() for the whole graph, but update_node() with
  // `since` = -1 the first time an ant stands on a node (on a large map most nodes never are).
  bool updates_by_node = false;
  // It depends on the ant's own walk (its heading, say): the engine calls step_factors() once per
  // step with all candidate edges, never once per candidate.
  bool uses_walk = false;
};

// Slot "heuristic": the desirability eta of every edge.
class BOOST_SYMBOL_VISIBLE Heuristic : public Strategy {
 public:
  ~Heuristic() override;
  // Fills eta (>= 0, finite) for every edge. Called once per run, or before every
  // iteration when specs().varies_by_iteration. The engine raises it to beta itself.
  virtual void compute(const Context& context, std::span<double> eta) = 0;
  virtual HeuristicSpecs specs() const { return {}; }
  // What the engine calls: eta^beta for every edge. The default calls compute() and raises
  // each value to beta; a heuristic that changes every iteration may override it to update
  // eta^beta more cheaply than a pow() per edge (see heuristic/adaptive).
  virtual void compute_powered(const Context& context, std::span<double> eta_beta);
  // With specs().updates_by_node. eta_beta: the out-edges of `node` (from graph.offsets[node]),
  // holding eta^beta as it was in iteration `since` (< context.iteration), or anything if `since`
  // is -1 (never computed). Sets them to what compute_powered() gives for context.iteration, bit
  // for bit. Called from construction threads, never twice at once for one node, and (for a
  // heuristic that varies by iteration) only after compute_powered() ran for the run's first
  // iteration.
  virtual void update_node(const Context& context, NodeId node, int since, std::span<double> eta_beta) const;
  // With specs().uses_walk: `ant` holds the walk so far (nodes and edges). factors[i] multiplies
  // candidate i's tau^alpha * eta^beta. Must be thread-safe.
  virtual void step_factors(const Context& context, const Ant& ant, std::span<const EdgeId> candidates,
                            std::span<double> factors) const;
};

// What a heuristic throws when a finite eta raised to beta overflows: the power's doing, said with
// the bound eta must keep at this beta, rather than the engine's check blaming the plugin for an
// infinite eta^beta. The default compute_powered() throws it; a plugin with its own power does too.
[[noreturn]] void throw_power_overflow(double beta);

// The pheromone of a running colony, per edge: tau(e) = clamp(stored(e) x scale, low, high). An
// update rule that evaporates every edge alike and keeps the trail within bounds (MAX-MIN) calls
// evaporate() and bound(), which cost nothing per edge: on a 2048x2048 map a pass over every edge
// (33 M of them) per iteration costs more than the ants' walks. Any other rule asks for values()
// and works on plain per-edge values; then scale and bounds are 1 and [0, infinity), and
// stored(e) is tau(e).
class BOOST_SYMBOL_VISIBLE Trail {
 public:
  static constexpr double kNoBound = std::numeric_limits<double>::infinity();
  explicit Trail(std::span<double> stored) : stored_(stored) {}

  std::size_t size() const { return stored_.size(); }
  double operator[](EdgeId e) const { return std::clamp(stored_[e] * scale_, low_, high_); }
  // tau(e) = tau, within the bounds (a negative or NaN value is kept for the engine's check).
  void set(EdgeId e, double tau) { stored_[e] = (tau >= 0.0 ? std::clamp(tau, low_, high_) : tau) / scale_; }
  // Every tau(e) times 1 - rho, in O(1) (the stored values are rescaled once the scale gets tiny).
  void evaporate(double rho);
  // Every tau(e) kept within [low, high] from now on, in O(1): applied where tau is read.
  void bound(double low, double high);
  void fill(double tau);  // every edge; O(edges)
  // The plain values: scale and bounds applied to every edge (O(edges) unless already plain).
  // Writes to them are tau; the bounds stay in force where tau is read.
  std::span<double> values();

  // How the engine reads the trail in its inner loop.
  bool plain() const { return scale_ == 1.0 && low_ == 0.0 && high_ == kNoBound; }
  std::span<const double> stored() const { return stored_; }
  double scale() const { return scale_; }
  double low() const { return low_; }
  double high() const { return high_; }

 private:
  std::span<double> stored_;
  double scale_ = 1.0;
  double low_ = 0.0;
  double high_ = kNoBound;
};

// Slot "update": pheromone evaporation and deposit after every iteration.
class BOOST_SYMBOL_VISIBLE PheromoneUpdate : public Strategy {
 public:
  ~PheromoneUpdate() override;
  virtual void update(const Context& context, const Iteration& iteration, std::span<double> tau) = 0;
  // Called once after the init plugin set the pheromone. An update rule that fixes the
  // pheromone scale (ACS's tau0) may rescale the field here, keeping the init plugin's shape.
  virtual void start(const Context& context, std::span<double> tau);
  // What the engine calls after every iteration. The default calls update() with
  // trail.values(); a rule that evaporates every edge alike overrides it to use the trail's
  // evaporate() and bound() instead (see update/max_min), and keeps update() for callers with
  // plain values.
  virtual void update_trail(const Context& context, const Iteration& iteration, Trail& trail);
};

// Slot "deadlock": what happens to an ant that is not at the goal and has nowhere to go.
class BOOST_SYMBOL_VISIBLE DeadlockPolicy : public Strategy {
 public:
  ~DeadlockPolicy() override;
  // Called from construction threads (must be thread-safe). Returns how many nodes the ant
  // steps back before it continues (the nodes it leaves stay tabu), or 0 to let it die.
  virtual int on_stuck(const Context& context, std::span<const NodeId> walk) const = 0;
  // Called once per iteration, before the pheromone update, with all ants in ant order. May
  // change the pheromone (trail.set(), or trail.values() for plain per-edge values) and forbid
  // nodes (forbidden[n] = 1) for the rest of the run.
  virtual void after_iteration(const Context& context, const Iteration& iteration, Trail& trail,
                               std::vector<std::uint8_t>& forbidden);
};

// Slot "smoother": turns the best grid path into the final waypoints.
class BOOST_SYMBOL_VISIBLE Smoother : public Strategy {
 public:
  ~Smoother() override;
  // Finite waypoints on free cells (aco::on_free_cell), the first and last the positions of the
  // path's ends; aco::plan() refuses others, naming the plugin.
  virtual std::vector<Eigen::Vector3d> smooth(const Context& context, std::span<const NodeId> path) const = 0;
};

// What a local planner sees at one control step: the robot, its limits, the intermediate goal
// it drives to, the rest of the global path, and the obstacles its sensor reports (blocked map
// cells, known or not, and moving discs), all within the sensor range.
struct MovingObstacle {
  Eigen::Vector2d position;
  Eigen::Vector2d velocity;  // map units per second, as sensed
  double radius = 0.0;
};

struct LocalView {
  RobotState robot;
  RobotLimits limits;
  double period = 0.1;  // control period: the command is held this long
  Eigen::Vector2d goal;  // the current intermediate goal
  std::span<const Eigen::Vector2d> cells;  // centres of sensed blocked cells
  double cell_size = 1.0;  // a cell is a square of this side
  std::span<const MovingObstacle> moving;  // sensed moving obstacles
  // The rest of the global path: from the point on it nearest to the robot, through goal, to the
  // final goal (empty: only goal is known). A planner may follow it instead of heading for goal.
  std::span<const Eigen::Vector2d> path;
};

// Slot "local": the velocity command for the next control period, which follows the global
// path's intermediate goals and avoids what the sensor sees (used by acosim; acoplan plans the
// global path only). The command must lie in dynamic_window(view.robot, view.limits,
// view.period); the simulator clamps rounding's excess (kWindowTolerance) and stops on more, or
// on NaN, naming the plugin and the control step.
class BOOST_SYMBOL_VISIBLE LocalPlanner : public Strategy {
 public:
  ~LocalPlanner() override;
  virtual VelocityCommand command(const LocalView& view) = 0;
};

}  // namespace aco
