#pragma once
// Global-best particle swarm optimisation over waypoints: the PSO baseline of paper 000. A
// particle is K intermediate waypoints in continuous cell coordinates (x = column, y = row).
// Its walk goes start -> waypoint 1 -> ... -> waypoint K -> goal, each leg by grid moves along
// the straight segment between the two cells: every step is the move that gets closer to the
// leg's end and keeps closest to the segment, preferring moves that are graph edges, so the walk
// slides along an obstacle but never searches around one. When no edge gets closer, the walk
// takes the blocked move anyway: an infeasible step, which costs `penalty` on top of its length
// in the fitness. The planner's output is the shortest walk without infeasible steps found by any
// particle at any iteration, so it is a path on the graph, comparable with the colony and A*.
//
// Deterministic: particle i at iteration t draws only from Rng::stream(seed, t, i).
#include <cstdint>
#include <span>
#include <vector>

#include "aco/graph.hpp"
#include "aco/parameters.hpp"
#include "aco/search_result.hpp"

namespace aco {

struct PsoSettings {
  int particles = 50;
  int iterations = 100;
  int waypoints = 3;  // K
  double inertia = 0.7298;  // w (Clerc and Kennedy's constriction values)
  double c1 = 1.49618;  // pull towards the particle's own best
  double c2 = 1.49618;  // pull towards the swarm's best
  double max_velocity = 0.2;  // velocity clamp per coordinate, as a fraction of the map's width or height
  double penalty = 100.0;  // fitness added per infeasible step
  std::uint64_t seed = 1;  // not in the table: acoplan's --seed
};

// The table of every setting but the seed.
std::span<const ParamSpec> pso_parameters();
PsoSettings pso_settings(const ParameterValues& values);

// Throws Error on a bad start, goal or setting. Unsolved when no particle ever walked without
// an infeasible step.
PlannerResult run_pso(const Graph& graph, NodeId start, NodeId goal, const PsoSettings& settings);

// The walk through the given cells (start, waypoints, goal) by moves along each straight leg.
struct WaypointWalk {
  std::vector<NodeId> nodes;
  double length = 0.0;  // graph cost of feasible steps, straight-line length of infeasible ones
  int infeasible = 0;  // steps that are not edges of the graph
};
WaypointWalk walk_waypoints(const Graph& graph, std::span<const Cell> cells);

}  // namespace aco
