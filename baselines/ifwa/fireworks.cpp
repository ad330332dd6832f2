#include "ifwa/fireworks.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numeric>

#include "aco/error.hpp"
#include "aco/parallel.hpp"
#include "aco/rng.hpp"
#include "aco/settings_table.hpp"

namespace aco {

const SettingsTable<FireworksSettings>& fireworks_table() {
  using F = FireworksSettings;
  static const SettingsTable<F> table({
      field("iterations", &F::iterations, "1:1000000", "generations G_max"),
      field("fireworks", &F::fireworks, "1:100000", "fireworks kept from one generation to the next"),
      field("mutation_sparks", &F::mutation_sparks, "0:100000", "Gaussian mutation sparks per generation"),
      field("sparks", &F::sparks, "1:100000", "explosion count m: sparks shared out among the fireworks by fitness"),
      field("radius", &F::radius, "(0:1e9]", "explosion radius A^ (largest amplitude) at the first generation"),
      field("radius_end", &F::radius_end, "(0:1]",
            "annealing: the radius cools geometrically to radius x radius_end at the last generation (1 = constant)"),
      field("a", &F::a, "0:1", "each firework makes at least round(a m) explosion sparks"),
      field("b", &F::b, "0:1", "each firework makes at most round(b m) explosion sparks (a <= b)"),
      field("inertia_start", &F::inertia_start, "0:10",
            "mutation inertia weight w at the first generation: a mutated weight is multiplied by 1 + w N(0,1)"),
      field("inertia_end", &F::inertia_end, "0:10",
            "mutation inertia weight at the last generation (linear in between)"),
      field("weight_min", &F::weight_min, "(0:1e9)", "smallest node weight a_j (positive: every move stays possible)"),
      field("weight_max", &F::weight_max, "(0:1e9]", "largest node weight a_j"),
      field("max_weights", &F::max_weights, "1:1000000000",
            "most weights per firework: one per cell up to it, on larger maps one per square block of cells"),
      field("walk_limit", &F::walk_limit, "0:1e6",
            "once a path is known, a decoding walk is abandoned after this many times its steps (at least 4096 moves; "
            "0 = never)"),
  });
  return table;
}

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

using Weights = std::vector<double>;

struct Spark {
  Weights weights;  // per active node
  std::vector<NodeId> path;
  double fitness = 0.0;
};

class Search {
 public:
  Search(const Graph& graph, NodeId start, NodeId goal, const FireworksSettings& settings)
      : g_(graph),
        start_(start),
        goal_(goal),
        s_(settings),
        index_(graph.num_nodes(), -1),
        attraction_(graph.num_nodes(), 0.0) {
    std::vector<NodeId> active;  // the nodes a walk can use: those with edges
    for (NodeId n = 0; n < g_.num_nodes(); ++n) {
      if (g_.degree(n) == 0) continue;
      index_[n] = static_cast<int>(active.size());
      active.push_back(n);
      attraction_[n] = n == goal_ ? 0.0 : 1.0 / g_.distance(n, goal_);
    }
    dimensions_ = active.size();
    if (dimensions_ > static_cast<std::size_t>(s_.max_weights)) share_weights_by_block(active);
    // Longer than any walk without repeated nodes: each edge cost counted once per direction.
    penalty_ = 1.0;
    for (EdgeId e = 0; e < g_.num_edges(); ++e) penalty_ += g_.cost(e);
  }

  PlannerResult run() {
    PlannerResult r;
    const SearchClock clock;
    std::vector<Spark> fireworks(s_.fireworks);
    aco::parallel_for(0, s_.fireworks, [&](int i) {
      Rng rng = Rng::stream(s_.seed, 0, static_cast<std::uint64_t>(i));
      Spark& f = fireworks[i];
      f.weights.resize(dimensions_);
      for (double& w : f.weights) w = rng.uniform(s_.weight_min, s_.weight_max);
      evaluate(f, rng);
    });
    r.evaluations += fireworks.size();
    Spark best_so_far = *std::min_element(fireworks.begin(), fireworks.end(), by_fitness);

    for (int generation = 1; generation <= s_.iterations; ++generation) {
      std::vector<Spark> pool = std::move(fireworks);
      max_moves_ = move_limit(best_so_far);
      std::vector<Spark> sparks = make_sparks(pool, generation);
      r.evaluations += sparks.size();
      std::move(sparks.begin(), sparks.end(), std::back_inserter(pool));
      fireworks = select(std::move(pool), generation);
      if (fireworks[0].fitness < best_so_far.fitness) best_so_far = fireworks[0];  // select() puts the best first
      r.best_so_far.push_back(best_so_far.path.empty() ? PlannerResult::none : best_so_far.fitness);
      clock.record(r, r.evaluations);
    }
    r.iterations = s_.iterations;
    if (best_so_far.path.empty()) return r;
    r.solved = true;
    r.path = std::move(best_so_far.path);
    r.length = best_so_far.fitness;
    r.finish();
    return r;
  }

 private:
  static bool by_fitness(const Spark& x, const Spark& y) { return x.fitness < y.fitness; }

  // Explosion sparks of every firework, then the mutation sparks; spark k draws from stream
  // (seed, generation, k) for its weights and its walk.
  std::vector<Spark> make_sparks(const std::vector<Spark>& fireworks, int generation) const {
    std::vector<double> fitness;
    for (const auto& f : fireworks) fitness.push_back(f.fitness);
    const auto counts = explosion_counts(fitness, s_.sparks, s_.a, s_.b);
    const auto amplitudes = explosion_amplitudes(fitness, explosion_radius(s_, generation));
    std::vector<int> exploding;  // parent of each explosion spark
    for (std::size_t i = 0; i < fireworks.size(); ++i)
      exploding.insert(exploding.end(), counts[i], static_cast<int>(i));
    const double progress = s_.iterations > 1 ? double(generation - 1) / (s_.iterations - 1) : 0.0;
    const double inertia = s_.inertia_start + (s_.inertia_end - s_.inertia_start) * progress;

    std::vector<Spark> sparks(exploding.size() + s_.mutation_sparks);
    aco::parallel_for(std::size_t{0}, sparks.size(), [&](std::size_t k) {
      Rng rng = Rng::stream(s_.seed, static_cast<std::uint64_t>(generation), k);
      Spark& spark = sparks[k];
      if (k < exploding.size()) {
        spark.weights = fireworks[exploding[k]].weights;
        const double amplitude = amplitudes[exploding[k]];
        for (double& w : spark.weights)
          if (rng.uniform() < 0.5) w = into_range(w + amplitude * rng.uniform(-1.0, 1.0));
      } else {
        spark.weights = fireworks[rng.below(fireworks.size())].weights;
        for (double& w : spark.weights)
          if (rng.uniform() < 0.5) w = into_range(w * (1.0 + inertia * rng.normal()));
      }
      evaluate(spark, rng);
    });
    return sparks;
  }

  // Keeps the best, then draws the other fireworks without replacement with probability
  // proportional to their summed distance to every candidate (paper 004 eq. 7-8).
  std::vector<Spark> select(std::vector<Spark> pool, int generation) const {
    std::stable_sort(pool.begin(), pool.end(), by_fitness);
    if (pool.size() <= static_cast<std::size_t>(s_.fireworks)) return pool;
    std::vector<double> spread(pool.size(), 0.0);
    aco::parallel_for(std::size_t{0}, pool.size(), [&](std::size_t i) {
      for (const auto& other : pool) {
        double d2 = 0.0;
        for (std::size_t k = 0; k < dimensions_; ++k)
          d2 += (pool[i].weights[k] - other.weights[k]) * (pool[i].weights[k] - other.weights[k]);
        spread[i] += std::sqrt(d2);
      }
    });
    Rng rng = Rng::stream(s_.seed, static_cast<std::uint64_t>(generation), pool.size());
    std::vector<bool> taken(pool.size(), false);
    std::vector<Spark> kept;
    for (std::size_t pick = 0; kept.size() < static_cast<std::size_t>(s_.fireworks);) {
      kept.push_back(std::move(pool[pick]));
      taken[pick] = true;
      spread[pick] = 0.0;
      // Candidates identical to all others have no spread: then the next fittest one.
      const bool spread_left = std::any_of(spread.begin(), spread.end(), [](double v) { return v > 0.0; });
      pick = spread_left ? roulette(rng, spread, std::accumulate(spread.begin(), spread.end(), 0.0))
                         : std::find(taken.begin(), taken.end(), false) - taken.begin();
    }
    return kept;
  }

  // A decoding walk is a depth-first search guided by a_j / d(j, goal); on a large map it can
  // wander over most of the map before it arrives. Once a path is known, walks far longer than it
  // are abandoned (penalty fitness). Never below 4096 moves, so on maps of up to 4096 cells
  // (every map of the papers) no walk is ever cut: a walk enters each node at most once.
  std::size_t move_limit(const Spark& best) const {
    if (s_.walk_limit <= 0.0 || best.path.empty()) return std::numeric_limits<std::size_t>::max();
    return std::max<std::size_t>(4096,
                                 static_cast<std::size_t>(std::ceil(s_.walk_limit * double(best.path.size() - 1))));
  }

  // Paper 004 gives every node its own weight, which on a 512x512 map makes a firework 260,000
  // numbers: every spark copies and mutates them all, and selection compares all pairs of them.
  // Above max_weights the nodes of each b x b block of cells share one weight, with the
  // smallest b that keeps the number of blocks within max_weights.
  void share_weights_by_block(const std::vector<NodeId>& active) {
    int side = 1;
    const auto blocks = [&](int b) {
      return static_cast<std::size_t>((g_.width + b - 1) / b) * static_cast<std::size_t>((g_.height + b - 1) / b);
    };
    while (blocks(side) > static_cast<std::size_t>(s_.max_weights)) ++side;
    const int columns = (g_.width + side - 1) / side;
    for (NodeId n : active) {
      const Cell c = g_.cell(n);
      index_[n] = (c.y / side) * columns + c.x / side;
    }
    dimensions_ = blocks(side);
  }

  // Paper 004 eq. 6: a weight outside [min, max] is mapped to min + |w| mod (max - min).
  double into_range(double w) const {
    if (w >= s_.weight_min && w <= s_.weight_max) return w;
    return s_.weight_min + std::fmod(std::abs(w), s_.weight_max - s_.weight_min);
  }

  // The walk of paper 004 eq. 1 with back-off: from the current node, an untried neighbour j
  // with probability a_j / d(j, goal) / sum (the goal itself at once). A dead end is left and
  // stays tried. Fitness = the walk's length, or the penalty if it backs off past the start.
  void evaluate(Spark& spark, Rng& rng) const {
    std::vector<std::uint8_t> tried(g_.num_nodes(), 0);
    std::vector<NodeId>& walk = spark.path;
    walk.assign(1, start_);
    tried[start_] = 1;
    std::vector<double> chances;
    std::vector<NodeId> options;
    std::size_t moves = 0;
    while (!walk.empty() && walk.back() != goal_) {
      if (moves >= max_moves_) {
        walk.clear();  // abandoned: as if it had backed off past the start
        break;
      }
      const NodeId at = walk.back();
      chances.clear();
      options.clear();
      NodeId next = -1;
      for (EdgeId e = g_.edges_begin(at); e < g_.edges_end(at) && next < 0; ++e) {
        const NodeId j = g_.targets[e];
        if (tried[j]) continue;
        if (j == goal_) next = j;
        options.push_back(j);
        chances.push_back(spark.weights[index_[j]] * attraction_[j]);
      }
      if (next < 0 && !options.empty())
        next = options[roulette(rng, chances, std::accumulate(chances.begin(), chances.end(), 0.0))];
      if (next < 0) {
        walk.pop_back();
        continue;
      }
      tried[next] = 1;
      walk.push_back(next);
      ++moves;
    }
    spark.fitness = walk.empty() ? penalty_ : path_length(g_, walk);
  }

  const Graph& g_;
  NodeId start_;
  NodeId goal_;
  FireworksSettings s_;
  std::size_t dimensions_ = 0;  // weights per firework
  std::size_t max_moves_ = std::numeric_limits<std::size_t>::max();  // per decoding walk, this generation
  std::vector<int> index_;  // node -> its weight's index in a firework, or -1
  std::vector<double> attraction_;  // per node: 1 / distance to the goal
  double penalty_ = 0.0;
};

}  // namespace

std::span<const ParamSpec> fireworks_parameters() { return fireworks_table().parameters(); }

FireworksSettings fireworks_settings(const ParameterValues& v) {
  const FireworksSettings s = fireworks_table().read(v);
  check(s);
  return s;
}

void check(const FireworksSettings& s) {
  if (s.a > s.b)
    throw Error("fireworks: a = " + to_string(ParamValue(s.a)) + " is above b = " + to_string(ParamValue(s.b)) +
                " (the spark count bounds are [round(a m), round(b m)])");
  if (s.weight_min >= s.weight_max)
    throw Error("fireworks: weight_min = " + to_string(ParamValue(s.weight_min)) +
                " must be below weight_max = " + to_string(ParamValue(s.weight_max)));
}

std::vector<int> explosion_counts(std::span<const double> fitness, int m, double a, double b) {
  const double worst = *std::max_element(fitness.begin(), fitness.end());
  double total = kEps;
  for (double f : fitness) total += worst - f;
  const long low = std::lround(a * m), high = std::lround(b * m);
  std::vector<int> counts;
  for (double f : fitness)
    counts.push_back(static_cast<int>(std::clamp(std::lround(m * (worst - f + kEps) / total), low, high)));
  return counts;
}

std::vector<double> explosion_amplitudes(std::span<const double> fitness, double radius) {
  const double best = *std::min_element(fitness.begin(), fitness.end());
  double total = kEps;
  for (double f : fitness) total += f - best;
  std::vector<double> amplitudes;
  for (double f : fitness) amplitudes.push_back(radius * (f - best + kEps) / total);
  return amplitudes;
}

double explosion_radius(const FireworksSettings& s, int generation) {
  return s.radius * std::pow(s.radius_end, double(generation) / s.iterations);
}

PlannerResult run_fireworks(const Graph& graph, NodeId start, NodeId goal, const FireworksSettings& s) {
  check_endpoints(graph, start, goal, "fireworks");
  if (s.iterations < 1 || s.fireworks < 1 || s.sparks < 1 || s.mutation_sparks < 0)
    throw Error("fireworks: iterations, fireworks and sparks must be at least 1, mutation_sparks at least 0");
  if (!(s.a >= 0 && s.a <= s.b && s.b <= 1)) throw Error("fireworks: need 0 <= a <= b <= 1");
  if (!(s.weight_min > 0 && s.weight_min < s.weight_max && std::isfinite(s.weight_max)))
    throw Error("fireworks: need 0 < weight_min < weight_max");
  if (!(s.radius > 0 && std::isfinite(s.radius) && s.radius_end > 0 && s.radius_end <= 1))
    throw Error("fireworks: need radius > 0 and radius_end in (0, 1]");
  if (start == goal) return PlannerResult::already_there(start);
  return Search(graph, start, goal, s).run();
}

}  // namespace aco
