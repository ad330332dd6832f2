#pragma once
// OMPL's sampling-based planners (RRT-Connect, RRT*, Informed RRT*, BIT*, PRM*, AIT*) as a
// baseline: they plan in the plane over the map, not on its graph. A state is a point (x = column,
// y = row; cell (x, y) is the unit square centred on it) in [-0.5, width - 0.5] x [-0.5, height
// - 0.5], valid where a passable cell holds it; a motion is checked exactly by segment_free()
// with the graph's corner rule. The path is a polyline at any angles (no grid path): OMPL's
// PathSimplifier shortens it when `simplify` is on, as OMPL users run it.
//
// Not reproducible as the colony is: OMPL's seed is process-global (ompl::RNG::setSeed) and the
// optimizing planners run until the time budget is spent, so what they find depends on the
// machine and its load. baselines/ompl/README.md says what the seed does and does not fix.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/parameters.hpp"
#include "aco/path.hpp"
#include "aco/search_result.hpp"

namespace aco {

struct OmplSettings {
  std::string planner = "rrtconnect";  // rrtconnect, rrtstar, informedrrtstar, bitstar, prmstar, aitstar
  double time_limit = 1.0;  // seconds of OMPL's solve(); the simplification comes on top
  bool simplify = true;  // OMPL's PathSimplifier on the solution (SimpleSetup::simplifySolution)
  double range = 0.0;  // longest motion the RRTs add in one step; 0: OMPL's default
  std::uint64_t seed = 1;  // not in the table: acoplan's --seed
};

// The table of every setting but the seed; ompl_settings() reads it, and refuses a range for a
// planner that has none (Error).
std::span<const ParamSpec> ompl_parameters();
OmplSettings ompl_settings(const ParameterValues& values);

struct OmplResult {
  bool solved = false;  // an exact solution (an approximate one, ending short of the goal, is not)
  std::string reason;  // why not solved
  Waypoints path;  // start's position to goal's position, z = 0
  double length = SearchResult::none;  // polyline_length(path)
  // The anytime curve: one entry per solution the planner reported (the optimizing ones report
  // each improvement; the others only their one solution), then the simplified path: its length,
  // seconds since solve() began, and the solutions so far.
  std::vector<double> best_so_far;
  std::vector<double> elapsed_s;
  std::vector<std::uint64_t> walks;
  std::int64_t graph_states = 0;  // vertices of the planner's graph or trees (ompl::base::PlannerData)
  std::int64_t motion_checks = 0;  // segment_free() calls of the solve (the simplification's not counted)
  double solve_time_s = 0.0;  // OMPL's own measure of solve()
  double simplification_time_s = 0.0;
  std::string status;  // OMPL's PlannerStatus: "Exact solution", "Timeout", ...
};

// Throws Error on a bad start or goal, or a map whose cells are not the plane's unit squares (a
// terrain). Runs one at a time per process (OMPL's seed is process-global).
OmplResult run_ompl(const Graph& graph, NodeId start, NodeId goal, const OmplSettings& settings);

}  // namespace aco
