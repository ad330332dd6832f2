#pragma once
// The improved fireworks algorithm (IFWA) of paper 004 on a graph: a coarse path search whose
// best path seeds the colony's pheromone (plugin init/fireworks) or stands alone as a baseline
// planner (acoplan --planner ifwa).
//
// A firework is one weight a_j per node, in [weight_min, weight_max] (on maps with more nodes than
// max_weights, one weight per square block of cells). Decoding walks from the
// start, choosing among the untried neighbours with probability proportional to a_j / d(j, goal),
// backing off from dead ends, until the goal; its fitness is the walk's length. Sparks come from
// explosions (count and amplitude from fitness, radius annealed over the generations) and from
// Gaussian mutation (with an inertia weight); selection keeps the best and draws the rest by
// their summed distance to the others.
//
// Deterministic: spark k of generation g draws only from Rng::stream(seed, g, k), so the result
// does not depend on the thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "aco/graph.hpp"
#include "aco/settings_table.hpp"
#include "aco/search_result.hpp"

namespace aco {

struct FireworksSettings {
  int iterations = 50;  // generations G_max
  int fireworks = 15;  // fireworks kept per generation
  int mutation_sparks = 10;  // Gaussian sparks per generation
  int sparks = 5;  // explosion count m
  double radius = 3.0;  // maximum explosion amplitude A^ at the first generation
  double radius_end = 0.1;  // the amplitude cools geometrically to radius * radius_end at G_max
  double a = 0.3;  // spark count bounds: [round(a m), round(b m)]
  double b = 0.5;
  double inertia_start = 0.9;  // mutation inertia weight, linear from start to end over the run
  double inertia_end = 0.4;
  double weight_min = 0.01;  // range of a node weight
  double weight_max = 1.0;
  int max_weights = 4096;  // above it, the nodes of a square block of cells share one weight
  double walk_limit = 3.0;  // decoding walks longer than this x the best path (and 4096 moves) are abandoned
  std::uint64_t seed = 1;  // not in the table: acoplan's --seed, the plugin's context seed
};

// The table of every setting but the seed (paper 004's set-up as defaults), and its rows.
const SettingsTable<FireworksSettings>& fireworks_table();
std::span<const ParamSpec> fireworks_parameters();
// Throw Error if the values are inconsistent (a > b, weight_min >= weight_max).
FireworksSettings fireworks_settings(const ParameterValues& values);
void check(const FireworksSettings& settings);

// Runs IFWA from start to goal. Throws Error on a bad start, goal or setting. Unsolved when the
// goal cannot be reached: every walk then ends in a dead end and gets the penalty fitness.
PlannerResult run_fireworks(const Graph& graph, NodeId start, NodeId goal, const FireworksSettings& settings);

// Explosion sparks per firework from its fitness f (smaller is better), paper 004 eq. 2:
// S_i = m (Y_max - f_i + eps) / (sum_j (Y_max - f_j) + eps), rounded and clamped to
// [round(a m), round(b m)].
std::vector<int> explosion_counts(std::span<const double> fitness, int m, double a, double b);

// Explosion amplitude per firework, paper 004 eq. 3:
// A_i = radius (f_i - Y_min + eps) / (sum_j (f_j - Y_min) + eps).
std::vector<double> explosion_amplitudes(std::span<const double> fitness, double radius);

// The simulated-annealing radius of generation G (1-based) of G_max = settings.iterations:
// radius * radius_end^(G / G_max), a geometric cooling from radius to radius * radius_end.
double explosion_radius(const FireworksSettings& settings, int generation);

}  // namespace aco
