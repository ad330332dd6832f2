#pragma once
// What a planned path is measured by: the exact A* optimum on the run's graph, and on flat grids
// the exact any-angle optimum and its corridor (aco/corridor.hpp). acoplan, Python and acobench
// measure their runs here, so that a run's gap means the same everywhere.
#include <cstdint>
#include <optional>
#include <vector>

#include "aco/corridor.hpp"
#include "aco/graph.hpp"
#include "aco/planning/planning.hpp"

namespace aco {

struct PlanRun : PlanOutcome {
  std::optional<double> optimal_length;  // exact A* reference on the same graph; none if unreachable
  // The exact any-angle optimum (aco/any_angle.hpp), the yardstick of the final path's length, and
  // whether the final path runs through its corridor (aco/corridor.hpp); none on maps other than
  // flat grids, or when no path joins start and goal.
  std::optional<double> any_angle_length;
  std::optional<bool> optimal_corridor;
};

// A problem's yardsticks on a graph: A*'s optimum on it and, on flat grids, the exact any-angle
// optimum (`corridor`'s, made on the graph's map; null: none asked for); none where no path joins
// start and goal.
struct Yardsticks {
  std::optional<double> optimal_length;
  std::optional<double> any_angle_length;
};
Yardsticks yardsticks(const Graph& graph, NodeId start, NodeId goal, const OptimalCorridor* corridor);

// The excess of a length over its optimum: length / optimal - 1, and 0 where the length is the
// optimum (0 where start = goal); gap_percent() is 100 times it.
double relative_gap(double length, double optimal);
double gap_percent(double length, double optimal);

// The run against the optimum's corridor: whether its final path runs through it (none where the
// optimum is unknown, or the run has no path); and a colony run's property
// "optimal_corridor_walked" (a run with "corridors"): 1 when any of its walks took the optimum's
// corridor, 0 when none did. With the final path's corridor, that tells a run that never explored
// the right corridor from one that explored it and left it.
std::optional<bool> judge_corridor(const OptimalCorridor& corridor, PlanOutcome& run);

// `count` runs of `run` with seeds seed, seed+1, ..., each with the A* optimum, the any-angle
// optimum and its corridor. Not `whole_map`: the graph is a corridor of its map (a voxel world
// planned coarse to fine, aco/planning/plan_request.hpp), whose optimum is not the map's: none.
std::vector<PlanRun> plan_runs(PluginRegistry& registry, const Graph& graph, NodeId start, NodeId goal,
                               const RunSpec& run, std::int64_t count, bool whole_map = true);

}  // namespace aco
