#pragma once
// One colony of the engine (colony.cpp): its strategies, pheromone trail and heuristic table, and
// its ants' walks from its start to its goal, with the per-thread buffers they use. colony.cpp's
// searches run one (the plain search), two (the bidirectional search) or several (islands).
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <mutex>
#include <numeric>
#include <span>
#include <string>
#include <vector>

#include "aco/engine/colony.hpp"
#include "construction_scratch.hpp"
#include "deadline.hpp"
#include "huge_pages.hpp"
#include "aco/engine/dead_ends.hpp"
#include "aco/error.hpp"
#include "aco/figures.hpp"
#include "aco/engine/local_search.hpp"
#include "aco/parallel.hpp"
#include "aco/plugin_error.hpp"
#include "aco/engine/plugin_guard.hpp"
#include "aco/rng.hpp"

namespace aco::colony_detail {

// x^p with the common exponents spared a pow() call: it runs once per candidate of every step.
inline double power(double x, double p) {
  if (p == 1.0) return x;
  if (p == 0.0) return 1.0;
  if (p == 2.0) return x * x;
  return std::pow(x, p);
}

// The index of the first value that is negative, NaN or infinite, or values.size() if none is.
// The common case, none, is found by counting the bad values in doubles, in eight independent
// sums: GCC vectorises a double's reduction (not a bool's or an integer's, on baseline x86-64),
// and eight sums do not wait on each other's additions. The index is only looked for after.
inline std::size_t first_invalid(std::span<const double> values) {
  constexpr double kMax = std::numeric_limits<double>::max();
  const auto bad = [](double v) { return v >= 0.0 && v <= kMax ? 0.0 : 1.0; };
  double count[8] = {};
  std::size_t i = 0;
  for (; i + 8 <= values.size(); i += 8)
    for (int k = 0; k < 8; ++k) count[k] += bad(values[i + k]);
  for (; i < values.size(); ++i) count[0] += bad(values[i]);
  if (std::accumulate(std::begin(count), std::end(count), 0.0) == 0.0) return values.size();
  i = 0;
  while (bad(values[i]) == 0.0) ++i;
  return i;
}

// A walk's length pulled taut as Theta* pulls its paths: the waypoint stays while line of sight
// joins it to the next node of the walk, and moves to the node before where it fails (or where
// the segment would be longer than `limit` cells, when limit > 0). Each segment is either in line
// of sight or an edge, so the polyline is valid on the graph's corner rule.
inline double sight_length(const Graph& g, std::span<const NodeId> nodes, int limit) {
  const bool corner_cutting = g.options.corner_cutting;
  const std::int64_t limit_squared = std::int64_t{limit} * limit;
  double length = 0.0;
  std::size_t waypoint = 0;
  Cell from = g.cell(nodes[0]);
  for (std::size_t k = 2; k < nodes.size(); ++k) {
    const Cell to = g.cell(nodes[k]);
    const std::int64_t dx = to.x - from.x, dy = to.y - from.y, dz = to.z - from.z;
    if ((limit == 0 || dx * dx + dy * dy + dz * dz <= limit_squared) && line_of_sight(*g.map, from, to, corner_cutting))
      continue;
    length += g.distance(nodes[waypoint], nodes[k - 1]);
    waypoint = k - 1;
    from = g.cell(nodes[waypoint]);
  }
  return length + g.distance(nodes[waypoint], nodes.back());
}

// A bad pheromone value found where the engine reads the field (an ant's step, the run's end), in
// a run that checks the field there only. run_colony() then repeats the run checking after every
// hook, which names the plugin, hook and iteration that wrote it (plugins are deterministic).
struct PheromoneFoundBad {
  std::size_t edge;
  double value;
  int iteration;
  const char* where;
};

// One colony: its strategies, pheromone field and heuristic, walking from its start to its goal.
// The plain search runs one; the bidirectional search runs two, the second from goal to start.
class Colony {
 public:
  Colony(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& pipeline,
         const ColonySettings& settings, bool check_every_hook, const Deadline& deadline)
      : g_(graph),
        p_(pipeline),
        s_(settings),
        check_every_hook_(check_every_hook),
        deadline_(deadline),
        shortener_(graph, forbidden_, settings.local_search == LocalSearch::loops ? 0 : settings.local_search_window),
        band_(graph, forbidden_, settings.band_search) {
    context_.graph = &graph;
    context_.start = start;
    context_.goal = goal;
    context_.ants = settings.ants;
    context_.max_iterations = settings.iterations;
    context_.alpha = settings.alpha;
    context_.beta = settings.beta;
    context_.seed = settings.seed;
    context_.figures = pipeline.figures;
    if (settings.closed)
      forbidden_ = *settings.closed;
    else
      forbidden_.assign(graph.num_nodes(), 0);
    if (settings.fill_dead_ends)
      forbidden_ = dead_ends(
          graph, start, goal,
          settings.closed ? std::span<const std::uint8_t>(*settings.closed) : std::span<const std::uint8_t>());
    known_forbidden_ = forbidden_;
    local_search_ = settings.local_search != LocalSearch::none;
    for (NodeId n = 0; n < graph.num_nodes(); ++n) max_degree_ = std::max(max_degree_, graph.degree(n));
    scratch_ = std::make_unique<ScratchPool>([this] { return Scratch(g_, known_forbidden_, max_degree_); });
  }

  void begin() {
    // Every strategy the run asks starts it afresh (the lifecycle, strategies.hpp); a colony that
    // ignores the pheromone never asks its init and update plugins.
    const bool learning = s_.null_model != NullModel::no_learning;
    p_.heuristic->begin_run(context_);
    p_.deadlock->begin_run(context_);
    if (learning) {
      p_.init->begin_run(context_);
      p_.update->begin_run(context_);
    }
    heuristic_ = p_.heuristic->specs();
    // A heuristic that stays the same through the run and computes by node is computed when an
    // ant first stands on a node: on a large map the ants see a fraction of the nodes, and the
    // run needs no pass over every edge and no double per edge before its first step.
    on_first_visit_ = heuristic_.updates_by_node && !heuristic_.varies_by_iteration &&
                      static_cast<std::size_t>(max_degree_) <= kMaxNeighbours;
    // The heuristic first, the pheromone after: the heuristic's double values are converted to
    // float and dropped (unless it changes by iteration) before the pheromone takes its memory.
    if (on_first_visit_)
      allocate(eta_, static_cast<std::size_t>(g_.num_edges()));
    else
      compute_heuristic();
    by_node_ = heuristic_.updates_by_node;
    if (by_node_) {
      fresh_ = ZeroPages<int>(static_cast<std::size_t>(g_.num_nodes()));  // all kNeverComputed
      if (!on_first_visit_)
        for (NodeId n = 0; n < g_.num_nodes(); ++n) fresh(n).store(context_.iteration + 1, std::memory_order_relaxed);
    }
    allocate(tau_, static_cast<std::size_t>(g_.num_edges()));
    if (learning) return initialize_trail();
    // With tau = 1 every candidate's tau^alpha is 1.
    trail_ = Trail(tau_);
    std::fill(tau_.begin(), tau_.end(), 1.0);
    plain_ = trail_.plain();
  }

  // The init plugin's field, which the update rule may rescale (start()), as a plain trail: a
  // run's first, and each restart's.
  void initialize_trail() {
    trail_ = Trail(tau_);
    p_.init->initialize(context_, tau_);
    check_pheromone(*p_.init, "init", "initialize()");
    p_.update->start(context_, tau_);
    check_pheromone(*p_.update, "update", "start()");
    plain_ = trail_.plain();
  }

  void prepare(int iteration) {
    // Every walk of the restart twin is a run's first: the first iteration's heuristic, and no
    // walk limit, which would hand it the best path so far.
    if (s_.null_model == NullModel::restarts) return;
    context_.iteration = iteration;
    if (s_.walk_limit > 0.0 && has_best_)
      max_moves_ = static_cast<std::uint64_t>(std::ceil(s_.walk_limit * static_cast<double>(best_.edges.size())));
    if (iteration > 0 && heuristic_.varies_by_iteration && !by_node_) compute_heuristic();
  }

  // Brackets the ants' construction, whose hooks run on several threads (see FigureSink).
  void set_parallel(bool parallel) {
    if (context_.figures) context_.figures->set_parallel(parallel);
  }

  Scratch& local_scratch() { return scratch_->local(); }
  std::chrono::steady_clock::time_point constructed() const { return constructed_; }
  const Context& context() const { return context_; }
  std::vector<double> take_pheromone() {  // at the end of a run
    trail_.values();
    return std::move(tau_);
  }
  const Ant* best() const { return has_best_ ? &best_ : nullptr; }
  // Whether a walk stops after `moves` moves: its step limit (none for an explorer, as for the
  // restarts twin's walks: a way round through other rooms is long before it is short), or the
  // time limit (Deadline).
  bool stops_after(std::uint64_t moves, bool explorer = false) const {
    return (!explorer && moves >= max_moves_) || deadline_.passed(moves);
  }

  void start_walk(Ant& ant, Scratch& scratch) const {
    ant.nodes.clear();
    ant.edges.clear();
    ant.arrived = false;
    ant.length = 0.0;
    scratch.next_stamp();
    ant.nodes.push_back(context_.start);
    scratch.enter(context_.start);
  }

  // Whether ant k of an iteration is an explorer (ColonySettings::explorers): the last ones.
  bool explorer(int k) const { return k >= first_explorer_; }

  // Moves the ant one node on, backing off first while it is stuck. False: the ant died.
  bool step(Ant& ant, Scratch& scratch, Rng& rng, bool explorer) const {
    if (explorer) return step<true, true, true>(ant, scratch, rng);
    const bool tau_alpha_is_tau = s_.alpha == 1.0 || s_.null_model == NullModel::no_learning;
    if (plain_) return tau_alpha_is_tau ? step<true, true>(ant, scratch, rng) : step<false, true>(ant, scratch, rng);
    return tau_alpha_is_tau ? step<true, false>(ant, scratch, rng) : step<false, false>(ant, scratch, rng);
  }

  // One ant's whole walk to the goal; returns the number of moves it made.
  std::uint64_t construct(Ant& ant, Scratch& scratch, Rng& rng, bool explorer = false) const {
    start_walk(ant, scratch);
    std::uint64_t moves = 0;
    while (ant.nodes.back() != context_.goal) {
      if (stops_after(moves, explorer) || !step(ant, scratch, rng, explorer)) return moves;
      ++moves;
    }
    arrive(ant, &scratch);
    return moves;
  }

  // With a scratch, the walk also gets the local search (if the settings ask for it).
  void arrive(Ant& ant, Scratch* scratch) const {
    ant.arrived = true;
    ant.length = 0.0;
    for (EdgeId e : ant.edges) ant.length += g_.cost(e);
    // A walk that retraces the best path (already shortened) has nothing to gain: skip the work.
    // Not in the restart twin, whose walks must not depend on each other.
    const bool retraces_best = s_.null_model != NullModel::restarts && has_best_ && ant.length == best_grid_length_ &&
                               ant.nodes == best_.nodes;
    if (retraces_best) {
      ant.length = best_.length;
      return;
    }
    if (local_search_ && scratch != nullptr) {
      shortener_.shorten(ant, scratch->walk);
      // A first iteration's walk on a large map wanders for hundreds of thousands of steps and
      // shortens to a few thousand: the iteration's ants would otherwise keep the wander's
      // memory until the next walk (on a 2048x2048 map, 50 ants held 220 MB).
      if (ant.nodes.capacity() > 4 * ant.nodes.size() + 4096) {
        ant.nodes.shrink_to_fit();
        ant.edges.shrink_to_fit();
      }
    }
    if (s_.walk_length == WalkLength::line_of_sight) ant.length = sight_length(g_, ant.nodes, s_.sight_limit);
  }

  // The band search (ColonySettings::band_search) on the iteration's shortest walk, before its
  // corridor is keyed and the strategies learn from it. A walk that retraces the best path, which
  // had its band search, is left alone (not in the restart twin, whose walks must not depend on
  // each other).
  void search_band(std::span<Ant> ants) {
    if (s_.band_search == 0) return;
    const Ant* walk = shortest(ants);
    // The explorers' shortest, unless it is the iteration's: polished too, or it could never
    // compete with a best path that had its band search.
    const auto first_explorer = std::min(ants.size(), static_cast<std::size_t>(first_explorer_));
    const Ant* scout = shortest(ants.subspan(first_explorer));
    for (const Ant* chosen : {walk, scout == walk ? nullptr : scout}) {
      if (chosen == nullptr) continue;
      Ant& ant = ants[static_cast<std::size_t>(chosen - ants.data())];
      if (s_.null_model != NullModel::restarts && has_best_ && ant.nodes == best_.nodes) continue;
      if (band_.improve(ant) && s_.walk_length == WalkLength::line_of_sight)
        ant.length = sight_length(g_, ant.nodes, s_.sight_limit);
    }
  }

  // A path of the other colony's walks, reversed: the same length, not pulled taut anew from
  // the other end (which may differ), so that both colonies rank the joined walk alike.
  void arrive_reversed(Ant& ant, double length) const {
    if (s_.walk_length == WalkLength::grid) return arrive(ant, nullptr);
    ant.arrived = true;
    ant.length = length;
  }

  // The deadlock and update strategies learn from a finished iteration; `corridors` holds each
  // ant's corridor key (aco::CorridorKeys; none in voxel worlds). Returns the length of its
  // shortest arrived walk (ColonyResult::none if none arrived).
  double learn(std::span<Ant> ants, std::span<const std::uint64_t> corridors) {
    const double length = keep_best(ants);
    if (s_.null_model != NullModel::none) return length;  // the twins learn nothing
    const Ant* iteration_best = shortest(ants);
    const Ant* best_so_far = best();
    if (epochs()) {
      // The strategies see the epoch: its walks, the ones through settled corridors derated, and
      // its best, so that a fresh trail is not marked with an earlier epoch's corridor at once.
      if (s_.corridor_derate > 0.0 && !settled_.empty() && !corridors.empty())
        for (std::size_t k = 0; k < ants.size(); ++k)
          if (ants[k].arrived && std::binary_search(settled_.begin(), settled_.end(), corridors[k]))
            ants[k].length *= 1.0 + s_.corridor_derate;
      iteration_best = shortest(ants);
      if (iteration_best != nullptr && (!has_epoch_best_ || iteration_best->length < epoch_best_.length)) {
        epoch_best_ = *iteration_best;
        epoch_best_corridor_ =
            corridors.empty() ? 0 : corridors[static_cast<std::size_t>(iteration_best - ants.data())];
        has_epoch_best_ = true;
        epoch_improved_ = context_.iteration;
      }
      best_so_far = has_epoch_best_ ? &epoch_best_ : nullptr;
    }
    const Iteration view{ants, iteration_best, best_so_far};
    p_.deadlock->after_iteration(context_, view, trail_, forbidden_);
    if (check_every_hook_) check_pheromone(*p_.deadlock, "deadlock", "after_iteration()");
    forbidden_[context_.start] = forbidden_[context_.goal] = 0;
    publish_forbidden();
    p_.update->update_trail(context_, view, trail_);
    if (check_every_hook_) check_pheromone(*p_.update, "update", "update()");
    if (s_.goal_memory) remember_ways_to_goal(ants);
    plain_ = trail_.plain();
    if (s_.restart_after > 0 && context_.iteration - epoch_improved_ >= s_.restart_after) restart();
    return length;
  }

  // The iteration's shortest walk, kept if it is the run's best; returns its length
  // (ColonyResult::none if none arrived). learn() begins with it; an iteration the time limit cut
  // short ends with it alone.
  double keep_best(std::span<const Ant> ants) {
    const Ant* iteration_best = shortest(ants);
    if (iteration_best == nullptr) return ColonyResult::none;
    if (!has_best_ || iteration_best->length < best_.length) {
      best_ = *iteration_best;
      has_best_ = true;
      best_grid_length_ = best_.length;
      if (s_.walk_length != WalkLength::grid) {
        best_grid_length_ = 0.0;
        for (EdgeId e : best_.edges) best_grid_length_ += g_.cost(e);
      }
    }
    return iteration_best->length;
  }

  int restarts() const { return restarts_; }
  // Epochs: restarts, or islands, whose colonies start afresh when they duplicate a corridor.
  bool epochs() const { return s_.restart_after > 0 || s_.colonies > 1; }
  // The epoch's best walk (derated length) and its corridor; none before one arrives in the epoch.
  const Ant* epoch_best() const { return has_epoch_best_ ? &epoch_best_ : nullptr; }
  std::uint64_t epoch_corridor() const { return epoch_best_corridor_; }

  // ColonySettings::goal_memory, in ant order. A node's first distance is only remembered: on the
  // first walks every node would improve, and marking all their edges would mark nothing.
  void remember_ways_to_goal(std::span<const Ant> ants) {
    if (to_goal_.empty()) to_goal_.assign(static_cast<std::size_t>(g_.num_nodes()), ColonyResult::none);
    for (const Ant& ant : ants) {
      if (!ant.arrived) continue;
      double remaining = 0.0;
      for (std::size_t i = ant.edges.size(); i-- > 0;) {
        const EdgeId e = ant.edges[i];
        remaining += g_.cost(e);
        double& known = to_goal_[static_cast<std::size_t>(ant.nodes[i])];
        if (!(remaining < known)) continue;
        const bool seen = known != ColonyResult::none;
        known = remaining;
        if (!seen) continue;
        const NodeId n = ant.nodes[i];
        double strongest = 0.0;
        for (EdgeId f = g_.edges_begin(n); f < g_.edges_end(n); ++f) strongest = std::max(strongest, trail_[f]);
        if (trail_[e] < strongest) trail_.set(e, strongest);
      }
    }
  }

  static const Ant* shortest(std::span<const Ant> ants) {
    const Ant* best = nullptr;
    for (const Ant& ant : ants)
      if (ant.arrived && (best == nullptr || ant.length < best->length)) best = &ant;
    return best;
  }

  // A new epoch: the epoch's corridor is settled, and the init and update plugins start a new run
  // on a fresh trail. The deadlock policy's forbidden nodes and the run's best path stay.
  void restart() {
    if (has_epoch_best_) {
      const auto at = std::lower_bound(settled_.begin(), settled_.end(), epoch_best_corridor_);
      if (at == settled_.end() || *at != epoch_best_corridor_) settled_.insert(at, epoch_best_corridor_);
    }
    has_epoch_best_ = false;
    epoch_improved_ = context_.iteration + 1;
    ++restarts_;
    p_.init->begin_run(context_);
    p_.update->begin_run(context_);
    initialize_trail();
  }

  // The last iteration's writes, which no ant reads: none may reach a result.
  void check_final_pheromone() const {
    if (check_every_hook_) return;  // checked after the hooks that wrote it
    const std::size_t e = first_invalid(tau_);
    if (e != tau_.size()) throw PheromoneFoundBad{e, tau_[e], context_.iteration, "at the end of the run"};
  }

 private:
  template <class T>
  static void allocate(std::vector<T>& field, std::size_t size) {
    field.reserve(size);
    prefer_huge_pages(field.data(), size * sizeof(T));
    field.assign(size, T{});
  }

  // eta^beta in double for the plugin, then in float for the ants: half the memory and half the
  // bytes an ant reads per candidate. Each node's values are divided by the node's largest first:
  // the ants compare a node's candidates only among themselves (the roulette and q0's best both
  // ignore a common factor), so this changes no choice, and no value falls outside float's range
  // whatever beta and the map's size. A heuristic that changes by iteration keeps its double
  // values, which it may update from (Heuristic::update_node()).
  void compute_heuristic() {
    if (eta_double_.empty()) allocate(eta_double_, static_cast<std::size_t>(g_.num_edges()));
    p_.heuristic->compute_powered(context_, eta_double_);
    check_heuristic(eta_double_, "compute_powered()", 0);
    if (eta_.empty()) allocate(eta_, eta_double_.size());
    aco::parallel_for(tbb::blocked_range<NodeId>(0, g_.num_nodes(), 4096), [&](const tbb::blocked_range<NodeId>& r) {
      for (NodeId n = r.begin(); n != r.end(); ++n) store_node_eta(n, eta_double_.data() + g_.offsets[n]);
    });
    if (!heuristic_.varies_by_iteration) std::vector<double>().swap(eta_double_);
  }

  void store_node_eta(NodeId n, const double* values) const {
    const EdgeId first = g_.offsets[n], degree = g_.offsets[n + 1] - first;
    double top = 0.0;
    for (EdgeId i = 0; i < degree; ++i) top = std::max(top, values[i]);
    const double scale = top > 0.0 ? 1.0 / top : 1.0;
    for (EdgeId i = 0; i < degree; ++i) eta_[first + i] = static_cast<float>(values[i] * scale);
  }

  // The forbidden nodes a deadlock policy added or took back, into every thread's marks. Most
  // iterations change none: equal blocks are skipped at memcmp's speed.
  void publish_forbidden() {
    constexpr std::size_t kBlock = 4096;
    for (std::size_t first = 0; first < forbidden_.size(); first += kBlock) {
      const std::size_t last = std::min(forbidden_.size(), first + kBlock);
      if (std::memcmp(forbidden_.data() + first, known_forbidden_.data() + first, last - first) == 0) continue;
      for (std::size_t n = first; n < last; ++n) {
        if (forbidden_[n] == known_forbidden_[n]) continue;
        known_forbidden_[n] = forbidden_[n];
        for (Scratch& scratch : *scratch_) scratch.forbid(static_cast<NodeId>(n), forbidden_[n] != 0);
      }
    }
  }

  // A check of what a hook wrote: a bad value is named where it was made (plugin, hook,
  // iteration), not where an ant happens to read it later. A pass over every edge, as costly as
  // the plugin's own evaporation, so after the per-iteration hooks (update, after_iteration) it
  // runs only in the repeat of a run that found a bad value where it reads the field.
  void check_pheromone(const Strategy& plugin, const char* slot, const char* hook) const {
    const std::size_t e = first_invalid(tau_);
    if (e != tau_.size()) reject_value(plugin, slot, hook, "pheromone", tau_[e], e);
  }

  // `values`: eta^beta of the edges from `first` on.
  void check_heuristic(std::span<const double> values, const char* hook, std::size_t first) const {
    const std::size_t i = first_invalid(values);
    if (i != values.size())
      reject_value(*p_.heuristic, "heuristic", hook, "heuristic (eta^beta)", values[i], first + i);
  }

  [[noreturn]] void reject_value(const Strategy& plugin, const char* slot, const char* hook, const std::string& field,
                                 double value, std::size_t e) const {
    const NodeId from = g_.source(static_cast<EdgeId>(e));
    throw InvalidValueError(describe_plugin(plugin, slot) + " wrote " + to_string(ParamValue(value)) + " to the " +
                            field + " of edge " + to_string(g_.cell(from)) + " -> " +
                            to_string(g_.cell(g_.targets[e])) + " in " + describe_hook(hook, context_.iteration) +
                            "; the " + field + " must be finite and >= 0");
  }

  // Brings node n's edges to the current iteration (heuristics that update by node). Ants on
  // other threads may stand on n at the same time: the first takes n's lock and updates, the
  // others wait for it; the acquire/release pair publishes the values to every later reader.
  void update_heuristic(NodeId n) const {
    const int now = on_first_visit_ ? 0 : context_.iteration;
    if (fresh(n).load(std::memory_order_acquire) == now + 1) return;
    std::lock_guard lock(update_locks_[static_cast<std::size_t>(n) % update_locks_.size()]);
    const int since = fresh(n).load(std::memory_order_relaxed) - 1;
    if (since == now) return;
    const EdgeId first = g_.offsets[n];
    const auto degree = static_cast<std::size_t>(g_.offsets[n + 1] - first);
    std::array<double, kMaxNeighbours> computed;  // a node's values, when no table of doubles is kept
    const std::span<double> values = on_first_visit_ ? std::span<double>(computed.data(), degree)
                                                     : std::span<double>(eta_double_.data() + first, degree);
    p_.heuristic->update_node(context_, n, since, values);
    check_heuristic(values, "update_node()", first);
    store_node_eta(n, values.data());
    fresh(n).store(now + 1, std::memory_order_release);
  }
  std::atomic_ref<int> fresh(NodeId n) const { return std::atomic_ref<int>(fresh_[static_cast<std::size_t>(n)]); }

  // Specialised for alpha = 1, the usual case, which needs no pow() in the inner loop, and for a
  // plain trail (stored values are tau), which needs no scale and bounds; an explorer reads no
  // pheromone (tau = 1 on every edge).
  template <bool kAlphaOne, bool kPlain, bool kExplorer = false>
  bool step(Ant& ant, Scratch& scratch, Rng& rng) const {
    const std::uint32_t tabu = 2 * scratch.stamp;
    const Scratch::MarkT* marks = scratch.marks.begin();
    EdgeId* candidates = scratch.candidates.data();
    double* weights = scratch.weights.data();
    const EdgeId* offsets = g_.offsets.data();
    const NodeId* targets = g_.targets.data();
    const double* tau = tau_.data();
    const float* eta = eta_.data();
    const double alpha = s_.alpha;  // unused when kAlphaOne
    const double scale = trail_.scale(), low = trail_.low(), high = trail_.high();  // unused when kPlain
    for (;;) {
      const NodeId current = ant.nodes.back();
      if (by_node_) update_heuristic(current);
      int n = 0;
      double total = 0.0;
      bool negative = false;
      for (EdgeId e = offsets[current], end = offsets[current + 1]; e < end; ++e) {
        const NodeId j = targets[e];
        if (marks[j] >= tabu) continue;  // on the walk, backed off or forbidden
        const double stored = kExplorer ? 1.0 : tau[e];
        negative |= !(stored >= 0.0);
        // min and max pass NaN on (std::max(NaN, low) is NaN), for the check below to see.
        const double t = kPlain ? stored : std::min(std::max(stored * scale, low), high);
        const double w = (kAlphaOne ? t : power(t, alpha)) * eta[e];
        candidates[n] = e;
        weights[n] = w;
        total += w;
        ++n;
      }
      // eta^beta was checked when written. The pheromone is checked here, where it is read: NaN
      // and infinity reach the total, a negative value may not, hence its own flag. Valid values
      // whose products overflow are the one other way to a total that is not finite.
      if (negative || !(total <= std::numeric_limits<double>::max())) reject_pheromone_or_overflow(candidates, n);
      if (n == 0) {
        const int back = std::min<int>(p_.deadlock->on_stuck(context_, ant.nodes), int(ant.nodes.size()) - 1);
        if (back <= 0) return false;
        for (std::size_t i = ant.nodes.size() - back; i < ant.nodes.size(); ++i) scratch.leave(ant.nodes[i]);
        ant.nodes.resize(ant.nodes.size() - back);
        ant.edges.resize(ant.edges.size() - back);
        continue;
      }
      if (heuristic_.uses_walk) {
        std::span<double> factors(scratch.factors.data(), n);
        p_.heuristic->step_factors(context_, ant, {candidates, std::size_t(n)}, factors);
        total = 0.0;
        bool negative_factor = false;
        for (int i = 0; i < n; ++i) {
          negative_factor |= !(factors[i] >= 0.0);
          total += weights[i] *= factors[i];
        }
        // In the pass that applies them, as for the pheromone: NaN and infinity reach the total.
        if (negative_factor || !(total <= std::numeric_limits<double>::max()))
          reject_factors_or_overflow(factors, candidates);
      }
      const EdgeId e = candidates[choose(rng, n, weights, total)];
      const NodeId next = targets[e];
      ant.edges.push_back(e);
      ant.nodes.push_back(next);
      scratch.enter(next);
      return true;
    }
  }

  [[noreturn]] void reject_pheromone_or_overflow(const EdgeId* candidates, int n) const {
    for (int i = 0; i < n; ++i) {
      const double t = tau_[candidates[i]];
      if (!(t >= 0.0 && t <= std::numeric_limits<double>::max()))
        throw PheromoneFoundBad{static_cast<std::size_t>(candidates[i]), t, context_.iteration, "where an ant read it"};
    }
    overflowed();
  }

  [[noreturn]] static void overflowed() {
    throw Error("the transition weights overflowed: pheromone or heuristic values are too large");
  }

  [[noreturn]] void reject_factors_or_overflow(std::span<const double> factors, const EdgeId* candidates) const {
    const std::size_t i = first_invalid(factors);
    if (i != factors.size())
      reject_value(*p_.heuristic, "heuristic", "step_factors()", "step factor", factors[i],
                   static_cast<std::size_t>(candidates[i]));
    overflowed();
  }

  // Pseudo-random proportional rule: with probability q0 the best candidate, else the roulette.
  int choose(Rng& rng, int n, const double* weights, double total) const {
    if (s_.q0 > 0.0 && rng.uniform() < s_.q0) return static_cast<int>(std::max_element(weights, weights + n) - weights);
    if (!(total > 0.0)) return static_cast<int>(rng.below(n));  // every weight underflowed to 0
    return static_cast<int>(roulette(rng, {weights, static_cast<std::size_t>(n)}, total));
  }

  // First: the colony's set-up is timed from here (constructed()).
  const std::chrono::steady_clock::time_point constructed_ = std::chrono::steady_clock::now();
  const Graph& g_;
  ColonyStrategies p_;
  ColonySettings s_;
  bool check_every_hook_;
  const Deadline& deadline_;
  Context context_;
  std::vector<double> tau_;  // the trail's stored values
  Trail trail_{std::span<double>()};
  bool plain_ = true;  // trail_.plain(), cached between the hooks that may change it
  // eta^beta as the ants read it (compute_heuristic()), and as the heuristic wrote it, kept only
  // for one that changes by iteration. Mutable for heuristics that update by node: the (const,
  // multi-threaded) construction brings a node's eta^beta up to date when an ant first stands on
  // it in an iteration.
  mutable std::vector<float> eta_;
  mutable std::vector<double> eta_double_;
  bool by_node_ = false;
  bool on_first_visit_ = false;  // the heuristic is computed node by node, once (see begin())
  int max_degree_ = 1;
  // Ants from this index on are explorers (ColonySettings::explorers).
  int first_explorer_ = s_.ants - static_cast<int>(std::lround(s_.explorers * s_.ants));
  static constexpr int kNeverComputed = -1;
  static constexpr std::size_t kMaxNeighbours = 32;  // the largest neighbourhood is 26 (voxel worlds)
  // Per node (fresh()): 1 + the iteration its eta^beta is for, 0 (kNeverComputed + 1) at first; the
  // pages of the nodes ants stood on only.
  mutable ZeroPages<int> fresh_;
  mutable std::array<std::mutex, 64> update_locks_;
  std::vector<std::uint8_t> forbidden_;
  std::vector<std::uint8_t> known_forbidden_;  // what the threads' marks hold (publish_forbidden())
  std::unique_ptr<ScratchPool> scratch_;
  WalkShortener shortener_;
  BandSearch band_;
  bool local_search_ = false;
  HeuristicSpecs heuristic_;  // read once per run, after the heuristic's begin_run()
  std::uint64_t max_moves_ = std::numeric_limits<std::uint64_t>::max();
  Ant best_;
  double best_grid_length_ = 0.0;  // the sum of best_'s steps, which best_.length need not be
  bool has_best_ = false;
  // Restarts (ColonySettings::restart_after): the epoch's best walk (lengths derated), its
  // corridor, the iteration it was found in (or the epoch began), and the settled corridors.
  Ant epoch_best_;
  bool has_epoch_best_ = false;
  std::uint64_t epoch_best_corridor_ = 0;
  int epoch_improved_ = 0;
  int restarts_ = 0;
  std::vector<std::uint64_t> settled_;  // sorted
  std::vector<double> to_goal_;  // goal_memory: per node, the shortest way on to the goal walked
};

}  // namespace aco::colony_detail
