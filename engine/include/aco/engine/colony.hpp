#pragma once
// The colony engine: iterations x ants, classic transition rule, tabu lists, ants built in
// parallel with TBB and bit-identical for any thread count.
#include <chrono>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "aco/parameters.hpp"
#include "aco/search_result.hpp"
#include "aco/strategies.hpp"

namespace aco {

// The null models a colony is compared with to ask whether its pheromone matters
// (docs/learning.md says exactly what each keeps and drops):
// - no_learning: the same pipeline and budget with the pheromone ignored in the ants' choice and
//   never changed; nothing passes from one iteration to the next but the best-so-far path;
// - restarts: the same number of walks as independent one-iteration runs, each on the initial
//   pheromone; they share nothing but the best result.
enum class NullModel { none, no_learning, restarts };

// Local search on every arrived ant's walk before the update (aco/engine/local_search.hpp): none, cut
// loops only, or also replace straight-line-visible stretches up to the window by one segment.
enum class LocalSearch { none, loops, straighten };

// What an arrived walk's length is, for the best-so-far, the ranking and the deposits: the sum of
// its grid steps, or its length as Theta* would pull it taut (a waypoint is kept while the next
// cells are in line of sight of it). The colony then ranks corridors by a length close to the
// continuous one a smoother makes of them, not by the grid's octile length (docs/any-angle-ants.md).
enum class WalkLength { grid, line_of_sight };

struct ColonySettings {
  int ants = 50;
  int iterations = 100;
  double alpha = 1.0;
  double beta = 7.0;
  std::uint64_t seed = 1;
  // Ant Colony System's pseudo-random proportional rule (a construction rule, hence here): with
  // probability q0 an ant takes its best candidate instead of spinning the roulette. 0 = classic.
  double q0 = 0.0;
  int stagnation = 0;  // stop after this many iterations without improvement; 0 = run them all
  // Stop at the first iteration boundary after this many seconds since run_colony() began (the
  // colony's setup included); 0 = no limit. OMPL's termination condition: the result then
  // depends on the machine, so studies keep iteration budgets.
  double time_limit = 0.0;
  // Paper 001's rule: stop once this fraction of an iteration's ants walked one and the same path.
  bool same_path_stop = false;
  double same_path_fraction = 0.9;
  // Paper 000's bidirectional search: a second colony walks from the goal and ants join where
  // their walks meet. Needs a second set of strategy objects (see run_colony).
  bool bidirectional = false;
  // Before the first iteration, forbid the cells that lie on no loop-free start-goal path
  // (aco/engine/dead_ends.hpp).
  bool fill_dead_ends = false;
  LocalSearch local_search = LocalSearch::none;
  int local_search_window = 64;
  // The band search (aco::BandSearch): each iteration's shortest walk is replaced by the shortest
  // path among the nodes within band_search moves of it, so that it takes a nearby door or gap it
  // missed (0 = none).
  int band_search = 0;
  // Explorers: this share of each iteration's ants (the last ones) walk by the heuristic alone,
  // as the restarts twin's ants do, and the iteration's shortest explorer walk gets a band search
  // of its own; the colony learns from their walks like any other. A colony settled in one
  // corridor then still samples the others, and moves when an explorer finds a shorter one.
  double explorers = 0.0;
  // An ant that has made walk_limit times as many moves as the best path so far has steps dies
  // (0 = no limit): on large maps a lost ant can otherwise fill whole rooms before it backs out.
  double walk_limit = 0.0;
  // Coarse to fine (multilevel ant colony optimisation; Korošec, Šilc and Robič 2004): on a 2D
  // map of at least 256 blocks of this many cells along its longer side, a colony with these
  // settings first plans on the map coarsened into those blocks (a block is free where all its
  // cells are; coarse to fine in turn while still that large), and the ants on the map itself
  // then walk only within one block of the coarse colony's best path. The coarse colony has half
  // of a time limit. Where the coarse map does not connect start and goal, or its corridor does
  // not, the colony plans on the whole map. Smaller maps, and 0 or 1: one level.
  int coarse_to_fine = 0;
  // The explorers' share (explorers) at the coarse levels of coarse_to_fine: there the colony
  // chooses the corridor the ants on the map itself keep, and its walks are short.
  double coarse_explorers = 0.0;
  WalkLength walk_length = WalkLength::grid;
  // Line-of-sight walks: the longest straight segment, in cells, checked from a waypoint (0 = no
  // limit). A check costs its length in cells, so unlimited segments cost a walk's length squared
  // in open space; a longer segment is cut where the limit falls, which adds length only where
  // the walk turns there. 32 halved the cost on 512x512 maps and gave the same final lengths
  // (docs/any-angle-ants.md).
  int sight_limit = 32;
  // Restarts with a memory of corridors (docs/corridors.md): after restart_after iterations
  // without a shorter walk in the current epoch, the init and update plugins start afresh on a
  // fresh trail and the epoch's best corridor (aco::CorridorKeys) is settled; in later epochs a
  // walk through a settled corridor is ranked and rewarded as if 1 + corridor_derate times as long,
  // so that the colony settles elsewhere. The run's result is the shortest walk of every epoch.
  // The strategies' best-so-far is the epoch's. 0 = one epoch. corridor_derate does nothing without
  // epochs (restarts or islands), nor in voxel worlds, whose corridors have no keys. In the
  // bidirectional search each colony restarts on its own, and the forward one derates.
  int restart_after = 0;
  double corridor_derate = 0.0;
  // Islands (Middendorf, Reischle and Schmeck 2002): `colonies` colonies with trails of their own
  // share each iteration's ants (the first ants % colonies of them one more). Every
  // `exchange_every` iterations the colonies are ranked by their epoch's best walk, and a colony
  // whose best runs through the corridor of a better colony's best starts a new epoch (its
  // corridor settled, so derated with corridor_derate): the colonies keep distinct corridors (in
  // voxel worlds, with no corridor keys, they only run side by side). Single search only. Each
  // needs its own strategy objects (run_colony's `islands`). The result is the best of them all.
  int colonies = 1;
  int exchange_every = 10;
  // Per-node learning of the way to the goal: every node keeps the shortest distance to the goal
  // (grid steps) an arrived walk went on from it; a later walk that goes on shorter from a node it
  // has been seen at raises its out-edge there to the node's strongest pheromone, after the
  // update. A long walk through the right door then still marks that door.
  bool goal_memory = false;
  NullModel null_model = NullModel::none;
  // Not a key: what a host calls after every iteration but the last, on the thread that called
  // run_colony(). It may throw to abandon the run (the Python package raises KeyboardInterrupt
  // so on Ctrl-C); it must not change the run, which stays the same whether it is set or not.
  std::function<void()> between_iterations;
  // Not a key: when the search began, which time_limit counts from; none: when run_colony()
  // starts. A host whose search begins earlier (acoplan's reachability test) sets it.
  std::optional<std::chrono::steady_clock::time_point> search_began;
  // Not a key: per node, 1 where no ant may go (coarse_to_fine's corridor, for one); none: every
  // passable node is open. Dead-end filling works within it.
  std::shared_ptr<const std::vector<std::uint8_t>> closed;
};

// The colony's parameter table (ants, iterations, alpha, beta, seed, ...; defaults from the
// struct), reading resolved values into settings and writing them back.
std::span<const ParamSpec> colony_parameters();
ColonySettings colony_settings(const ParameterValues& values);
ParameterValues colony_values(const ColonySettings& settings);

// Borrowed strategies; init, heuristic, update and deadlock are all required. `figures`, if set,
// keeps what they record (Context::record(), add()); the two colonies of the bidirectional search
// may share one: their counts add up, and of two values the backward colony's, recorded last, stays.
struct ColonyStrategies {
  PheromoneInit* init = nullptr;
  Heuristic* heuristic = nullptr;
  PheromoneUpdate* update = nullptr;
  DeadlockPolicy* deadlock = nullptr;
  FigureSink* figures = nullptr;
};

// Why a colony stopped: its iteration budget, stagnation, paper 001's same-path rule, the time limit.
enum class StopReason { iterations, stagnation, same_path, time };
// "iterations", "stagnation", "same path", "time": the run property stopped_by.
const char* to_string(StopReason reason);

struct ColonyResult : SearchResult {
  std::vector<double> iteration_best;  // per iteration (none if no ant arrived)
  std::vector<int> arrived;  // per iteration: ants that reached the goal
  std::uint64_t ant_steps = 0;  // moves made by all ants, backtracking included
  StopReason stopped_by = StopReason::iterations;
  std::vector<double> pheromone;  // final tau per edge
  // The corridors the arrived walks took, each once, as keys (aco::CorridorKeys, after the local
  // search), in increasing order: how widely the colony searched, and with OptimalCorridor::among()
  // whether it ever walked the optimum's corridor. None in voxel worlds.
  std::vector<std::uint64_t> corridors;
  int restarts = 0;  // epochs begun by restart_after
  // Coarse to fine (ColonySettings::coarse_to_fine): the coarse colony's result (its path in the
  // coarse map's nodes) and whether its corridor bounded the walks on the map itself. Where it
  // did, the ants walked the corridor's graph (subgraph()), and `pheromone` is per edge of that:
  // `pheromone_edges` gives each value's edge in the run's graph (per_edge() spreads them out).
  std::shared_ptr<const ColonyResult> coarse;
  bool walked_coarse_corridor = false;
  std::vector<EdgeId> pheromone_edges;  // empty: `pheromone` is per edge of the run's graph
};

// Runs the colony in the calling thread's TBB arena. Throws Error if a strategy writes a
// non-finite or negative pheromone or heuristic value, naming the plugin (aco::describe_plugin),
// the hook, the iteration, the edge and the value (the pheromone of every iteration is checked
// where it is read; a bad value there repeats the run with a check after every hook, which names
// the writer: docs/writing-plugins.md, "What the engine checks"). With settings.bidirectional, `backward`
// is the backward colony's pipeline: separate objects of the same (or other) plugins, since
// strategies keep per-run state. Its result is the forward colony's view (its pheromone).
// With settings.colonies = K > 1, `islands` holds the strategies of colonies 2..K: K - 1 more
// sets of separate objects, as for the backward colony.
ColonyResult run_colony(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& pipeline,
                        const ColonySettings& settings, const ColonyStrategies* backward = nullptr,
                        std::span<const ColonyStrategies> islands = {});

}  // namespace aco
