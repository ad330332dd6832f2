// The colony's settings table: its keys, ranges and help texts next to the ColonySettings members.
#include "aco/engine/colony.hpp"
#include "aco/settings_table.hpp"

namespace aco {
namespace {

const SettingsTable<ColonySettings>& colony_table() {
  using S = ColonySettings;
  static const SettingsTable<S> table({
      field("ants", &S::ants, "1:1000000", "ants per iteration"),
      field("iterations", &S::iterations, "1:100000000", "maximum number of iterations"),
      field("alpha", &S::alpha, "0:20", "pheromone exponent in the transition rule"),
      field("beta", &S::beta, "0:50", "heuristic exponent in the transition rule"),
      field("seed", &S::seed, "0:9.2e18", "random seed: a run is a pure function of its inputs and this seed"),
      field("q0", &S::q0, "0:1",
            "probability that an ant takes its best candidate instead of the roulette (Ant Colony System's q0; "
            "0 = classic rule)"),
      field("stagnation", &S::stagnation, "0:100000000",
            "stop after this many iterations without a shorter path (0 = run every iteration)"),
      field("time-limit", &S::time_limit, "0:1e9",
            "stop after this many seconds of search, inside an iteration if need be (its walks cut short), and "
            "return the best path so far (0 = no limit); the result then depends on the machine, so studies keep "
            "iteration budgets"),
      field("same-path-stop", &S::same_path_stop, "",
            "stop once same-path-fraction of an iteration's ants walked the same path (paper 001)"),
      field("same-path-fraction", &S::same_path_fraction, "(0:1]", "fraction of the ants for --same-path-stop"),
      choice("search", &S::bidirectional, {"single", "bidirectional"}, {false, true},
             "single = one colony from start to goal; bidirectional = two colonies meeting halfway (paper 000)"),
      field("fill-dead-ends", &S::fill_dead_ends, "",
            "forbid, before the first iteration, every cell that lies on no loop-free start-goal path (dead-end "
            "filling)"),
      choice("local-search", &S::local_search, {"none", "loops", "straighten"},
             {LocalSearch::none, LocalSearch::loops, LocalSearch::straighten},
             "shorten each arrived ant's walk before the update: cut its loops, or also straighten stretches of it"),
      field("local-search-window", &S::local_search_window, "2:4096",
            "longest stretch of a walk, in nodes, that straighten replaces by one straight segment"),
      field("band-search", &S::band_search, "0:64",
            "replace each iteration's shortest walk by the shortest path within this many moves of it, so it takes a "
            "nearby door it missed (0 = none)"),
      field("explorers", &S::explorers, "0:1",
            "this share of each iteration's ants walk by the heuristic alone, ignoring the pheromone, and the "
            "shortest of their walks gets a band search of its own, so that a settled colony still samples other "
            "corridors (0 = none)"),
      field("walk-limit", &S::walk_limit, "0:1e6",
            "an ant dies after this many times as many moves as the best path so far has steps (0 = no limit)"),
      field("coarse-to-fine", &S::coarse_to_fine, "0:64",
            "on a 2D map at least 256 such blocks wide or high: plan first on the map coarsened into blocks of this "
            "many cells a side (free where all their cells are), then let the ants walk only within one block of "
            "that colony's best path (0 or 1 = plan on the map alone)"),
      field("coarse-explorers", &S::coarse_explorers, "0:1",
            "with coarse-to-fine: the share of explorers (as --explorers) of the coarse colonies, which choose the "
            "corridor; the colony on the map itself keeps --explorers"),
      choice("walk-length", &S::walk_length, {"grid", "line-of-sight"}, {WalkLength::grid, WalkLength::line_of_sight},
             "the length an arrived walk is ranked and rewarded by: the sum of its grid steps, or its length pulled "
             "taut Theta*-style (a waypoint is kept while the walk's next cells are in line of sight of it)"),
      field("sight-limit", &S::sight_limit, "0:1000000",
            "line-of-sight walks: the longest segment, in cells, checked from a waypoint (0 = no limit); a longer "
            "one ends a segment there"),
      field("restart-after", &S::restart_after, "0:100000000",
            "start the trail afresh after this many iterations without a shorter walk in the current epoch, and "
            "settle the epoch's corridor (0 = never; the result is the shortest walk of every epoch)"),
      field("corridor-derate", &S::corridor_derate, "0:10",
            "with restart-after: a walk through a corridor an earlier epoch settled in is ranked and rewarded as if "
            "1 + this times as long, so that the next epoch settles elsewhere (0 = plain restarts)"),
      field("colonies", &S::colonies, "1:8",
            "islands: this many colonies with trails of their own share the ants; every exchange-every iterations a "
            "colony whose best walk runs through a better colony's corridor starts afresh (1 = one colony)"),
      field("exchange-every", &S::exchange_every, "1:100000000",
            "islands: iterations between two comparisons of the colonies' corridors"),
      field("goal-memory", &S::goal_memory, "",
            "every node keeps the shortest way on to the goal that arrived walks took from it; a walk that goes on "
            "shorter from a node raises its edge there to the node's strongest pheromone (after the update)"),
      choice(
          "null-model", &S::null_model, {"none", "no-learning", "restarts"},
          {NullModel::none, NullModel::no_learning, NullModel::restarts},
          "run a null model of the pipeline instead (docs/learning.md): no-learning = the pheromone ignored and never "
          "updated; restarts = the same number of walks as independent one-iteration runs"),
  });
  return table;
}

}  // namespace

std::span<const ParamSpec> colony_parameters() { return colony_table().parameters(); }
ColonySettings colony_settings(const ParameterValues& values) { return colony_table().read(values); }
ParameterValues colony_values(const ColonySettings& settings) { return colony_table().write(settings); }

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::stagnation:
      return "stagnation";
    case StopReason::same_path:
      return "same path";
    case StopReason::time:
      return "time";
    case StopReason::iterations:
      break;
  }
  return "iterations";
}

}  // namespace aco
