#include "aco/colony.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "aco/error.hpp"
#include "aco/rng.hpp"

namespace aco {
namespace {

constexpr ParamSpec kColonyParameters[] = {
    {"ants", ParamType::integer, "50", "1:1000000", "ants per iteration"},
    {"iterations", ParamType::integer, "100", "1:100000000", "maximum number of iterations"},
    {"alpha", ParamType::real, "1", "0:20", "pheromone exponent in the transition rule"},
    {"beta", ParamType::real, "7", "0:50", "heuristic exponent in the transition rule"},
    {"seed", ParamType::integer, "1", "0:9.2e18", "random seed: a run is a pure function of its inputs and this seed"},
    {"stagnation", ParamType::integer, "0", "0:100000000",
     "stop after this many iterations without a shorter path (0 = run every iteration)"},
    {"same-path-stop", ParamType::boolean, "false", "",
     "stop once same-path-fraction of an iteration's ants walked the same path (paper 001)"},
    {"same-path-fraction", ParamType::real, "0.9", "(0:1]", "fraction of the ants for --same-path-stop"},
};

// x^p with the common exponents spared a pow() call: it runs once per candidate of every step.
inline double power(double x, double p) {
  if (p == 1.0) return x;
  if (p == 0.0) return 1.0;
  if (p == 2.0) return x * x;
  return std::pow(x, p);
}

// Per-thread construction buffers. `visited` holds a stamp per node: a node is in the current
// ant's tabu list when its stamp equals the ant's, so no clearing between ants.
struct Scratch {
  explicit Scratch(int nodes, int max_degree)
      : visited(nodes, 0), candidates(max_degree), weights(max_degree), factors(max_degree) {}
  std::uint32_t next_stamp() {
    if (++stamp == 0) {
      std::fill(visited.begin(), visited.end(), 0);
      stamp = 1;
    }
    return stamp;
  }
  std::vector<std::uint32_t> visited;
  std::uint32_t stamp = 0;
  std::vector<EdgeId> candidates;
  std::vector<double> weights;
  std::vector<double> factors;
};

class Engine {
 public:
  Engine(const Graph& graph, NodeId start, NodeId goal, const Pipeline& pipeline, const ColonySettings& settings)
      : g_(graph), p_(pipeline), s_(settings) {
    context_.graph = &graph;
    context_.start = start;
    context_.goal = goal;
    context_.ants = settings.ants;
    context_.max_iterations = settings.iterations;
    context_.alpha = settings.alpha;
    context_.beta = settings.beta;
    context_.seed = settings.seed;
    const auto edges = static_cast<std::size_t>(graph.num_edges());
    tau_.assign(edges, 0.0);
    eta_beta_.assign(edges, 0.0);
    forbidden_.assign(graph.num_nodes(), 0);
    for (NodeId n = 0; n < graph.num_nodes(); ++n) max_degree_ = std::max(max_degree_, graph.degree(n));
  }

  ColonyResult run() {
    ColonyResult result;
    p_.init->initialize(context_, tau_);
    p_.update->start(context_, tau_);
    exploitation_ = p_.update->exploitation();
    if (!(exploitation_ >= 0.0 && exploitation_ <= 1.0))
      throw Error("the update plugin's exploitation probability q0 is not within [0, 1]");
    uses_walk_ = p_.heuristic->uses_walk();
    compute_heuristic();

    std::vector<Ant> ants(s_.ants);
    std::vector<std::uint64_t> steps(s_.ants, 0);
    Ant best;
    int last_improvement = 0;
    tbb::enumerable_thread_specific<Scratch> scratch(
        [&] { return Scratch(g_.num_nodes(), std::max(max_degree_, 1)); });

    for (int it = 0; it < s_.iterations; ++it) {
      context_.iteration = it;
      if (it > 0 && p_.heuristic->varies_by_iteration()) compute_heuristic();
      tbb::parallel_for(tbb::blocked_range<int>(0, s_.ants), [&](const tbb::blocked_range<int>& range) {
        Scratch& local = scratch.local();
        for (int k = range.begin(); k != range.end(); ++k) {
          Rng rng = Rng::stream(s_.seed, static_cast<std::uint64_t>(it), static_cast<std::uint64_t>(k));
          steps[k] = construct(ants[k], local, rng);
        }
      });

      const Ant* iteration_best = nullptr;
      int arrived = 0;
      for (int k = 0; k < s_.ants; ++k) {
        result.ant_steps += steps[k];
        if (!ants[k].arrived) continue;
        ++arrived;
        if (iteration_best == nullptr || ants[k].length < iteration_best->length) iteration_best = &ants[k];
      }
      if (iteration_best != nullptr && (!result.solved || iteration_best->length < best.length)) {
        best = *iteration_best;
        result.solved = true;
        result.best_iteration = it + 1;
        last_improvement = it + 1;
      }
      result.iteration_best.push_back(iteration_best ? iteration_best->length : ColonyResult::none);
      result.best_so_far.push_back(result.solved ? best.length : ColonyResult::none);
      result.arrived.push_back(arrived);
      result.iterations = it + 1;

      const Iteration view{ants, iteration_best, result.solved ? &best : nullptr};
      p_.deadlock->after_iteration(context_, view, tau_, forbidden_);
      forbidden_[context_.start] = forbidden_[context_.goal] = 0;
      p_.update->update(context_, view, tau_);

      if (s_.stagnation > 0 && it + 1 - last_improvement >= s_.stagnation) {
        result.stopped_by = "stagnation";
        break;
      }
      if (s_.same_path_stop && largest_same_path(ants) >= s_.same_path_fraction * s_.ants) {
        result.stopped_by = "same path";
        break;
      }
    }
    if (result.solved) {
      result.path = best.nodes;
      result.length = best.length;
    }
    result.pheromone = tau_;
    return result;
  }

 private:
  void compute_heuristic() {
    p_.heuristic->compute_powered(context_, eta_beta_);
    for (std::size_t e = 0; e < eta_beta_.size(); ++e)
      if (!(eta_beta_[e] >= 0.0 && std::isfinite(eta_beta_[e])))
        fail_value("heuristic^beta", "the heuristic plugin", eta_beta_[e], e);
  }

  [[noreturn]] void fail_value(const char* what, const char* source, double value, std::size_t e) const {
    const NodeId from = g_.source(static_cast<EdgeId>(e));
    throw Error(std::string(what) + " of edge " + to_string(g_.cell(from)) + " -> " + to_string(g_.cell(g_.targets[e])) +
                " is " + std::to_string(value) + " in iteration " + std::to_string(context_.iteration + 1) + " (set by " +
                source + "; it must be finite and >= 0)");
  }

  std::uint64_t construct(Ant& ant, Scratch& scratch, Rng& rng) const {
    return s_.alpha == 1.0 ? construct<true>(ant, scratch, rng) : construct<false>(ant, scratch, rng);
  }

  // One ant's walk; returns the number of moves it made. Specialised for alpha = 1, the usual
  // case, which needs no pow() in the inner loop.
  template <bool kAlphaOne>
  std::uint64_t construct(Ant& ant, Scratch& scratch, Rng& rng) const {
    ant.nodes.clear();
    ant.edges.clear();
    ant.arrived = false;
    ant.length = 0.0;
    const std::uint32_t stamp = scratch.next_stamp();
    std::uint32_t* visited = scratch.visited.data();
    EdgeId* candidates = scratch.candidates.data();
    double* weights = scratch.weights.data();
    const EdgeId* offsets = g_.offsets.data();
    const NodeId* targets = g_.targets.data();
    const std::uint8_t* forbidden = forbidden_.data();
    const double* tau = tau_.data();
    const double* eta_beta = eta_beta_.data();
    const double alpha = s_.alpha;  // unused when kAlphaOne

    NodeId current = context_.start;
    ant.nodes.push_back(current);
    visited[current] = stamp;
    std::uint64_t moves = 0;
    while (current != context_.goal) {
      int n = 0;
      double total = 0.0;
      bool negative = false;
      for (EdgeId e = offsets[current], end = offsets[current + 1]; e < end; ++e) {
        const NodeId j = targets[e];
        if (visited[j] == stamp || forbidden[j]) continue;
        const double t = tau[e];
        negative |= !(t >= 0.0);
        const double w = (kAlphaOne ? t : power(t, alpha)) * eta_beta[e];
        candidates[n] = e;
        weights[n] = w;
        total += w;
        ++n;
      }
      // The pheromone is checked here, where it is used, not in a pass over every edge per
      // iteration, which on large maps would cost more than the ants. NaN and infinity reach
      // the total; a negative value may not, hence its own flag.
      if (negative || !(total <= std::numeric_limits<double>::max())) reject_pheromone(candidates, n);
      if (n == 0) {
        const int back = std::min<int>(p_.deadlock->on_stuck(context_, ant.nodes), int(ant.nodes.size()) - 1);
        if (back <= 0) return moves;  // the ant dies
        ant.nodes.resize(ant.nodes.size() - back);
        ant.edges.resize(ant.edges.size() - back);
        current = ant.nodes.back();
        continue;
      }
      if (uses_walk_) {
        std::span<double> factors(scratch.factors.data(), n);
        p_.heuristic->step_factors(context_, ant, {candidates, std::size_t(n)}, factors);
        total = 0.0;
        for (int i = 0; i < n; ++i) total += weights[i] *= factors[i];
      }
      const EdgeId e = candidates[choose(rng, n, weights, total)];
      current = targets[e];
      ant.edges.push_back(e);
      ant.nodes.push_back(current);
      visited[current] = stamp;
      ++moves;
    }
    ant.arrived = true;
    for (EdgeId e : ant.edges) ant.length += g_.costs[e];
    return moves;
  }

  // How many arrived ants of the iteration share the most common path.
  static int largest_same_path(const std::vector<Ant>& ants) {
    std::vector<const std::vector<NodeId>*> paths;
    for (const Ant& ant : ants)
      if (ant.arrived) paths.push_back(&ant.nodes);
    std::sort(paths.begin(), paths.end(), [](auto* a, auto* b) { return *a < *b; });
    int largest = 0;
    for (std::size_t i = 0, j = 0; i < paths.size(); i = j) {
      while (j < paths.size() && *paths[j] == *paths[i]) ++j;
      largest = std::max(largest, int(j - i));
    }
    return largest;
  }

  [[noreturn]] void reject_pheromone(const EdgeId* candidates, int n) const {
    for (int i = 0; i < n; ++i) {
      const double t = tau_[candidates[i]];
      if (!(t >= 0.0 && std::isfinite(t))) fail_value("pheromone", "the init, update or deadlock plugin", t, candidates[i]);
    }
    throw Error("the transition weights overflowed: pheromone or heuristic values are too large");
  }

  // Pseudo-random proportional rule: with probability q0 the best candidate, else the roulette.
  int choose(Rng& rng, int n, const double* weights, double total) const {
    if (exploitation_ > 0.0 && rng.uniform() < exploitation_)
      return static_cast<int>(std::max_element(weights, weights + n) - weights);
    if (!(total > 0.0)) return static_cast<int>(rng.below(n));  // every weight underflowed to 0
    double r = rng.uniform() * total;
    int last_positive = 0;
    for (int i = 0; i < n; ++i) {
      if (weights[i] <= 0.0) continue;
      r -= weights[i];
      if (r < 0.0) return i;
      last_positive = i;
    }
    return last_positive;  // rounding left r just above 0
  }

  const Graph& g_;
  Pipeline p_;
  ColonySettings s_;
  Context context_;
  std::vector<double> tau_;
  std::vector<double> eta_beta_;
  std::vector<std::uint8_t> forbidden_;
  int max_degree_ = 0;
  double exploitation_ = 0.0;
  bool uses_walk_ = false;
};

void check_inputs(const Graph& graph, NodeId start, NodeId goal, const Pipeline& p, const ColonySettings& s) {
  for (const auto& [node, what] : {std::pair{start, "start"}, std::pair{goal, "goal"}}) {
    if (node < 0 || node >= graph.num_nodes()) throw Error(std::string(what) + " node is outside the map");
    if (!graph.passable(node))
      throw Error(std::string(what) + " " + to_string(graph.cell(node)) + " is a blocked cell (" +
                  graph.map->blocked_reason(graph.cell(node)) + ")");
  }
  if (!p.init || !p.heuristic || !p.update || !p.deadlock)
    throw Error("a colony needs an init, a heuristic, an update and a deadlock strategy");
  if (s.ants < 1) throw Error("ants must be at least 1");
  if (s.iterations < 1) throw Error("iterations must be at least 1");
  if (!(s.alpha >= 0 && std::isfinite(s.alpha)) || !(s.beta >= 0 && std::isfinite(s.beta)))
    throw Error("alpha and beta must be finite and >= 0");
  if (s.stagnation < 0) throw Error("stagnation must be >= 0");
  if (!(s.same_path_fraction > 0 && s.same_path_fraction <= 1)) throw Error("same-path-fraction must be in (0, 1]");
}

}  // namespace

std::span<const ParamSpec> colony_parameters() { return kColonyParameters; }

ColonySettings colony_settings(const ParameterValues& v) {
  ColonySettings s;
  s.ants = static_cast<int>(v.integer("ants"));
  s.iterations = static_cast<int>(v.integer("iterations"));
  s.alpha = v.real("alpha");
  s.beta = v.real("beta");
  s.seed = static_cast<std::uint64_t>(v.integer("seed"));
  s.stagnation = static_cast<int>(v.integer("stagnation"));
  s.same_path_stop = v.boolean("same-path-stop");
  s.same_path_fraction = v.real("same-path-fraction");
  return s;
}

ColonyResult run_colony(const Graph& graph, NodeId start, NodeId goal, const Pipeline& pipeline,
                        const ColonySettings& settings) {
  check_inputs(graph, start, goal, pipeline, settings);
  if (start == goal) {
    ColonyResult trivial;
    trivial.solved = true;
    trivial.path = {start};
    trivial.length = 0.0;
    return trivial;
  }
  return Engine(graph, start, goal, pipeline, settings).run();
}

}  // namespace aco
