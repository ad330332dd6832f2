#include "aco/engine/colony.hpp"

#include "aco/engine/coarse_to_fine.hpp"

#include <tbb/blocked_range.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <optional>

#include "aco/corridor.hpp"
#include "aco/error.hpp"
#include "aco/parallel.hpp"
#include "aco/rng.hpp"
#include "colony_walks.hpp"

namespace aco {
namespace {

using colony_detail::Colony;
using colony_detail::Deadline;
using colony_detail::PheromoneFoundBad;
using colony_detail::Scratch;

// How many arrived ants of the iteration share the most common path.
int largest_same_path(const std::vector<Ant>& ants) {
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

// The walk from `ant`'s end back along `reversed` (a walk in the opposite direction) to its start.
void append_reversed(const Graph& g, Ant& ant, const Ant& reversed, std::size_t from_index) {
  for (std::size_t i = from_index; i-- > 0;) {
    ant.edges.push_back(g.reverse_edge(reversed.edges[i]));
    ant.nodes.push_back(reversed.nodes[i]);
  }
}

// Paper 000's bidirectional search: ant k of the forward colony (start -> goal) and ant k of the
// backward colony (goal -> start) walk in turns, one step each. When either steps onto a node of
// the other's current walk, the two partial walks are joined there into one start -> goal path;
// checking every step keeps that node the only one they share, so the joined path is simple.
// Reaching the other colony's start is such a meeting. An ant that dies leaves its walk to be met.
// Both ants then carry the joined path (each in its own direction) into their colony's update.
// `explorers`: both ants of the pair are explorers (ColonySettings::explorers).
std::uint64_t construct_pair(const Graph& g, const Colony& forward, const Colony& backward, Ant& fa, Ant& ba,
                             Scratch& fs, Scratch& bs, Rng& frng, Rng& brng, bool explorers) {
  forward.start_walk(fa, fs);
  backward.start_walk(ba, bs);
  std::uint64_t moves = 0;
  bool forward_alive = true, backward_alive = true;
  NodeId meeting = -1;
  while (meeting < 0 && (forward_alive || backward_alive) && !forward.stops_after(moves, explorers)) {
    if (forward_alive) {
      forward_alive = forward.step(fa, fs, frng, explorers);
      if (forward_alive) {
        ++moves;
        if (bs.walked(fa.nodes.back())) meeting = fa.nodes.back();
      }
    }
    if (meeting < 0 && backward_alive) {
      backward_alive = backward.step(ba, bs, brng, explorers);
      if (backward_alive) {
        ++moves;
        if (fs.walked(ba.nodes.back())) meeting = ba.nodes.back();
      }
    }
  }
  if (meeting < 0) return moves;  // both died apart: no path this time
  const auto index_in = [meeting](const Ant& a) {
    return static_cast<std::size_t>(std::find(a.nodes.begin(), a.nodes.end(), meeting) - a.nodes.begin());
  };
  const std::size_t fi = index_in(fa), bi = index_in(ba);
  Ant joined;
  joined.nodes.assign(fa.nodes.begin(), fa.nodes.begin() + fi + 1);
  joined.edges.assign(fa.edges.begin(), fa.edges.begin() + fi);
  append_reversed(g, joined, ba, bi);
  forward.arrive(joined, &fs);
  Ant back;
  back.nodes.push_back(joined.nodes.back());
  append_reversed(g, back, joined, joined.edges.size());
  backward.arrive_reversed(back, joined.length);
  fa = std::move(joined);
  ba = std::move(back);
  return moves;
}

// The random stream of walk k of iteration `it` (of `walks_per_iteration`). The restart twin
// numbers its walks through the whole run instead, so that its result depends on the walks
// alone, not on how they are split into iterations.
Rng walk_stream(const ColonySettings& s, int it, std::uint64_t k, std::uint64_t walks_per_iteration) {
  if (s.null_model == NullModel::restarts)
    return Rng::stream(s.seed, 0, static_cast<std::uint64_t>(it) * walks_per_iteration + k);
  return Rng::stream(s.seed, static_cast<std::uint64_t>(it), k);
}

using Clock = std::chrono::steady_clock;

// Islands: the colonies ranked by their epoch's best walk, a colony whose best runs through a
// better colony's corridor starts a new epoch (settling that corridor), so that they keep distinct
// corridors. A colony with no walk in its epoch yet is left alone.
void exchange_corridors(std::span<Colony* const> colonies) {
  std::vector<Colony*> order(colonies.begin(), colonies.end());
  const auto length = [](const Colony* c) { return c->epoch_best() ? c->epoch_best()->length : ColonyResult::none; };
  std::stable_sort(order.begin(), order.end(), [&](const Colony* a, const Colony* b) { return length(a) < length(b); });
  std::vector<std::uint64_t> kept;
  for (Colony* colony : order) {
    if (!colony->epoch_best()) continue;
    if (std::find(kept.begin(), kept.end(), colony->epoch_corridor()) != kept.end())
      colony->restart();
    else
      kept.push_back(colony->epoch_corridor());
  }
}

// The iteration loop shared by the searches: `construct` fills every colony's ants for one
// iteration and returns the moves made. `islands`: every colony walks from start to goal (the
// islands search); otherwise colony 0 does, and a second colony is the bidirectional search's
// backward one, whose walks are colony 0's reversed.
template <class Construct>
ColonyResult iterate(const Graph& graph, const ColonySettings& s, const Deadline& deadline,
                     std::span<Colony* const> colonies, std::span<std::vector<Ant>> ants, bool islands,
                     Construct&& construct) {
  ColonyResult result;
  const SearchClock clock;
  for (Colony* colony : colonies) colony->begin();
  // The run ends with passes over the per-node and per-edge fields its set-up made (the final
  // check, the pheromone handed out, their memory freed): a time limit leaves them as long.
  deadline.hold_back(Clock::now() - colonies.front()->constructed());
  const std::size_t searching = islands ? colonies.size() : 1;
  // The corridors walked; in voxel worlds corridors are not classes of one key.
  std::optional<CorridorKeys> corridor_keys;
  if (!graph.volumetric) corridor_keys.emplace(*graph.map);
  std::vector<std::vector<std::uint64_t>> walk_corridors(searching);  // per ant of an iteration
  for (std::size_t c = 0; c < searching && corridor_keys; ++c) walk_corridors[c].assign(ants[c].size(), 0);
  std::vector<std::pair<double, std::uint64_t>> keyed_best(searching, {ColonyResult::none, 0});  // length, key
  const std::uint64_t walks_per_iteration = static_cast<std::uint64_t>(s.ants) * (islands ? 1 : colonies.size());
  int last_improvement = 0;
  for (int it = 0; it < s.iterations; ++it) {
    for (Colony* colony : colonies) colony->prepare(it), colony->set_parallel(true);
    result.ant_steps += construct(it);
    for (Colony* colony : colonies) colony->set_parallel(false);
    // Past the time limit (some walks may have been cut short) the iteration keeps its best walk
    // and ends the run: no band search, no learning.
    const bool out_of_time = deadline.passed();
    if (!out_of_time)
      for (std::size_t c = 0; c < searching; ++c) colonies[c]->search_band(ants[c]);

    int arrived = 0;
    const auto walked_before = static_cast<std::ptrdiff_t>(result.corridors.size());
    for (std::size_t c = 0; c < searching; ++c) {
      // A walk's key is a pass over it: the ants' side by side, and a walk that retraces the
      // colony's best path (most of them, once it converged) takes the best path's key.
      const Ant* best = colonies[c]->best();
      if (corridor_keys && best && best->length != keyed_best[c].first)
        keyed_best[c] = {best->length, corridor_keys->key(graph, best->nodes)};
      if (corridor_keys)
        aco::parallel_for(
            tbb::blocked_range<std::size_t>(0, ants[c].size()), [&](const tbb::blocked_range<std::size_t>& range) {
              for (std::size_t k = range.begin(); k != range.end(); ++k) {
                const Ant& ant = ants[c][k];
                if (!ant.arrived) continue;
                const bool retraces = best && ant.length == best->length && ant.nodes == best->nodes;
                walk_corridors[c][k] = retraces ? keyed_best[c].second : corridor_keys->key(graph, ant.nodes);
              }
            });
      for (std::size_t k = 0; k < ants[c].size(); ++k) {
        if (!ants[c][k].arrived) continue;
        ++arrived;
        if (corridor_keys) result.corridors.push_back(walk_corridors[c][k]);
      }
    }
    if (corridor_keys) {  // each corridor once, so that the list stays as short as the corridors are few
      const auto fresh = result.corridors.begin() + walked_before;
      std::sort(fresh, result.corridors.end());
      std::inplace_merge(result.corridors.begin(), fresh, result.corridors.end());
      result.corridors.erase(std::unique(result.corridors.begin(), result.corridors.end()), result.corridors.end());
    }
    double iteration_best = ColonyResult::none;
    for (std::size_t c = 0; c < colonies.size(); ++c) {
      const double length =
          out_of_time ? colonies[c]->keep_best(ants[c])
                      : colonies[c]->learn(ants[c], c < searching ? std::span<const std::uint64_t>(walk_corridors[c])
                                                                  : std::span<const std::uint64_t>());
      if (c < searching) iteration_best = std::min(iteration_best, length);
    }
    if (islands && corridor_keys && !out_of_time && (it + 1) % s.exchange_every == 0) exchange_corridors(colonies);
    if (iteration_best != ColonyResult::none && (!result.solved || iteration_best < result.length)) {
      result.solved = true;
      result.length = iteration_best;
      result.best_iteration = it + 1;
      last_improvement = it + 1;
    }
    result.iteration_best.push_back(iteration_best);
    result.best_so_far.push_back(result.length);
    result.arrived.push_back(arrived);
    result.iterations = it + 1;
    clock.record(result, static_cast<std::uint64_t>(result.iterations) * walks_per_iteration);

    if (s.stagnation > 0 && it + 1 - last_improvement >= s.stagnation) {
      result.stopped_by = StopReason::stagnation;
      break;
    }
    if (s.same_path_stop && largest_same_path(ants[0]) >= s.same_path_fraction * s.ants) {
      result.stopped_by = StopReason::same_path;
      break;
    }
    if (deadline.passed() && it + 1 < s.iterations) {  // cut short, or passed while it learned
      result.stopped_by = StopReason::time;
      break;
    }
    if (s.between_iterations && it + 1 < s.iterations) s.between_iterations();
  }
  for (Colony* colony : colonies) colony->check_final_pheromone();
  // The colony holding the shortest path (the first of equals); its pheromone is the picture's.
  std::size_t winner = 0;
  for (std::size_t c = 1; c < searching; ++c)
    if (colonies[c]->best() &&
        (!colonies[winner]->best() || colonies[c]->best()->length < colonies[winner]->best()->length))
      winner = c;
  if (result.solved) result.path = colonies[winner]->best()->nodes;
  for (Colony* colony : colonies) result.restarts += colony->restarts();
  result.pheromone = colonies[winner]->take_pheromone();
  return result;
}

ColonyResult run_single(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& pipeline,
                        const ColonySettings& s, bool check_every_hook, const Deadline& deadline) {
  Colony colony(graph, start, goal, pipeline, s, check_every_hook, deadline);
  std::vector<std::vector<Ant>> ants(1, std::vector<Ant>(s.ants));
  std::vector<std::uint64_t> steps(s.ants, 0);
  Colony* colonies[] = {&colony};
  return iterate(graph, s, deadline, colonies, ants, false, [&](int it) {
    aco::parallel_for(tbb::blocked_range<int>(0, s.ants), [&](const tbb::blocked_range<int>& range) {
      Scratch& local = colony.local_scratch();
      for (int k = range.begin(); k != range.end(); ++k) {
        Rng rng = walk_stream(s, it, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(s.ants));
        steps[k] = colony.construct(ants[0][k], local, rng, colony.explorer(k));
      }
    });
    return std::accumulate(steps.begin(), steps.end(), std::uint64_t{0});
  });
}

ColonyResult run_bidirectional(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& forward_pipeline,
                               const ColonyStrategies& backward_pipeline, const ColonySettings& s,
                               bool check_every_hook, const Deadline& deadline) {
  Colony forward(graph, start, goal, forward_pipeline, s, check_every_hook, deadline);
  Colony backward(graph, goal, start, backward_pipeline, s, check_every_hook, deadline);
  std::vector<std::vector<Ant>> ants(2, std::vector<Ant>(s.ants));
  std::vector<std::uint64_t> steps(s.ants, 0);
  Colony* colonies[] = {&forward, &backward};
  return iterate(graph, s, deadline, colonies, ants, false, [&](int it) {
    aco::parallel_for(tbb::blocked_range<int>(0, s.ants), [&](const tbb::blocked_range<int>& range) {
      Scratch& fs = forward.local_scratch();
      Scratch& bs = backward.local_scratch();
      for (int k = range.begin(); k != range.end(); ++k) {
        const auto a = 2 * static_cast<std::uint64_t>(k), pairs = 2 * static_cast<std::uint64_t>(s.ants);
        Rng frng = walk_stream(s, it, a, pairs), brng = walk_stream(s, it, a + 1, pairs);
        steps[k] =
            construct_pair(graph, forward, backward, ants[0][k], ants[1][k], fs, bs, frng, brng, forward.explorer(k));
      }
    });
    return std::accumulate(steps.begin(), steps.end(), std::uint64_t{0});
  });
}

// Islands: colony c walks ants [first[c], first[c + 1]) of each iteration, with the random
// streams those ants have in a single colony.
ColonyResult run_islands(const Graph& graph, NodeId start, NodeId goal, std::span<const ColonyStrategies> pipelines,
                         const ColonySettings& s, bool check_every_hook, const Deadline& deadline) {
  const int count = s.colonies;
  std::vector<std::unique_ptr<Colony>> owned;
  std::vector<Colony*> colonies;
  std::vector<std::vector<Ant>> ants;
  std::vector<int> first{0};
  for (int c = 0; c < count; ++c) {
    ColonySettings own = s;
    own.ants = s.ants / count + (c < s.ants % count ? 1 : 0);
    owned.push_back(std::make_unique<Colony>(graph, start, goal, pipelines[static_cast<std::size_t>(c)], own,
                                             check_every_hook, deadline));
    colonies.push_back(owned.back().get());
    ants.emplace_back(static_cast<std::size_t>(own.ants));
    first.push_back(first.back() + own.ants);
  }
  std::vector<std::uint64_t> steps(s.ants, 0);
  return iterate(graph, s, deadline, colonies, ants, true, [&](int it) {
    aco::parallel_for(tbb::blocked_range<int>(0, s.ants), [&](const tbb::blocked_range<int>& range) {
      for (int k = range.begin(); k != range.end(); ++k) {
        const auto c = static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), k) - first.begin() - 1);
        Rng rng = walk_stream(s, it, static_cast<std::uint64_t>(k), static_cast<std::uint64_t>(s.ants));
        steps[k] = colonies[c]->construct(ants[c][static_cast<std::size_t>(k - first[c])], colonies[c]->local_scratch(),
                                          rng, colonies[c]->explorer(k - first[c]));
      }
    });
    return std::accumulate(steps.begin(), steps.end(), std::uint64_t{0});
  });
}

void check_inputs(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& p, const ColonySettings& s) {
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
  if (!(s.time_limit >= 0 && std::isfinite(s.time_limit))) throw Error("time-limit must be finite and >= 0");
  if (!(s.same_path_fraction > 0 && s.same_path_fraction <= 1)) throw Error("same-path-fraction must be in (0, 1]");
  if (!(s.q0 >= 0 && s.q0 <= 1)) throw Error("q0 must be in [0, 1]");
  if (s.restart_after < 0) throw Error("restart-after must be >= 0");
  if (!(s.corridor_derate >= 0 && std::isfinite(s.corridor_derate)))
    throw Error("corridor-derate must be finite and >= 0");
  if (s.colonies < 1 || s.colonies > s.ants)
    throw Error("colonies must be between 1 and the number of ants (" + std::to_string(s.ants) + ")");
  if (s.exchange_every < 1) throw Error("exchange-every must be at least 1");
  if (s.colonies > 1 && s.bidirectional) throw Error("colonies > 1 works with the single search only (search single)");
  if (s.colonies > 1 && s.same_path_stop)
    throw Error("same-path-stop works with one colony only: the islands' ants walk apart on purpose");
}

struct FineLevel {
  ColonySettings settings;  // with the coarse colony's corridor, if it leaves one
  std::shared_ptr<const ColonyResult> coarse;
  std::shared_ptr<const Graph> corridor_graph;  // the corridor's edges only, if it leaves one
};

// ColonySettings::coarse_to_fine: the coarse colony's run (its figures not recorded: they are the
// run's on the map itself), and the settings for the map itself, with the corridor it leaves.
FineLevel coarse_to_fine(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& pipeline,
                         const ColonySettings& settings, Clock::time_point started, const ColonyStrategies* backward,
                         std::span<const ColonyStrategies> islands) {
  FineLevel fine{settings, nullptr, nullptr};
  const int block = settings.coarse_to_fine;
  if (block <= 1 || settings.closed || !coarsens(graph, block)) return fine;
  const std::optional<CoarseProblem> coarse =
      coarse_problem(*graph.map, graph.options, graph.cell(start), graph.cell(goal), block);
  if (!coarse) return fine;
  // The run's settings, coarse_to_fine included: a coarse map still large is planned coarse to
  // fine in turn.
  ColonySettings level = settings;
  level.search_began = started;
  level.time_limit = settings.time_limit / 2;
  level.explorers = settings.coarse_explorers;
  const auto quiet = [](ColonyStrategies strategies) {
    strategies.figures = nullptr;
    return strategies;
  };
  std::optional<ColonyStrategies> quiet_backward;
  if (backward) quiet_backward = quiet(*backward);
  std::vector<ColonyStrategies> quiet_islands;
  for (const ColonyStrategies& island : islands) quiet_islands.push_back(quiet(island));
  auto result =
      std::make_shared<ColonyResult>(run_colony(coarse->graph, coarse->start, coarse->goal, quiet(pipeline), level,
                                                quiet_backward ? &*quiet_backward : nullptr, quiet_islands));
  if (result->solved) {
    auto closed =
        std::make_shared<std::vector<std::uint8_t>>(coarse_corridor(*graph.map, coarse->graph, result->path, block));
    if (reachable(graph, start, goal, *closed)) {
      // The ants walk the corridor's graph: per-edge fields for its edges only, not the map's.
      fine.corridor_graph = std::make_shared<const Graph>(subgraph(graph, *closed));
      fine.settings.closed = std::move(closed);
    }
  }
  // Its path is what the level below uses: its fields' memory goes now.
  result->pheromone = {};
  result->pheromone_edges = {};
  fine.coarse = std::move(result);
  return fine;
}

}  // namespace

ColonyResult run_colony(const Graph& graph, NodeId start, NodeId goal, const ColonyStrategies& pipeline,
                        const ColonySettings& settings, const ColonyStrategies* backward,
                        std::span<const ColonyStrategies> islands) {
  check_inputs(graph, start, goal, pipeline, settings);
  if (start == goal) {
    ColonyResult trivial;
    trivial.solved = true;
    trivial.path = {start};
    trivial.length = 0.0;
    return trivial;
  }
  if (settings.bidirectional) {
    if (backward == nullptr || !backward->init || !backward->heuristic || !backward->update || !backward->deadlock)
      throw Error("the bidirectional search needs a second, complete set of strategy objects for its backward colony");
    if (backward->init == pipeline.init || backward->update == pipeline.update)
      throw Error("the bidirectional search's two colonies must not share strategy objects (they keep per-run state)");
  }
  std::vector<ColonyStrategies> island_pipelines{pipeline};
  if (settings.colonies > 1) {
    if (islands.size() + 1 != static_cast<std::size_t>(settings.colonies))
      throw Error("colonies = " + std::to_string(settings.colonies) + " needs " +
                  std::to_string(settings.colonies - 1) + " more sets of strategy objects, one per further colony");
    for (const ColonyStrategies& more : islands) {
      if (!more.init || !more.heuristic || !more.update || !more.deadlock)
        throw Error("every colony of the islands needs an init, a heuristic, an update and a deadlock strategy");
      for (const ColonyStrategies& other : island_pipelines)
        if (more.init == other.init || more.update == other.update || more.deadlock == other.deadlock)
          throw Error("the islands' colonies must not share strategy objects (they keep per-run state)");
      island_pipelines.push_back(more);
    }
  }
  // A time limit counts from here, or from the host's start of the search: the colony's setup (its
  // per-edge fields, dead-end filling) too.
  const Clock::time_point started = settings.search_began.value_or(Clock::now());
  const FineLevel fine = coarse_to_fine(graph, start, goal, pipeline, settings, started, backward, islands);
  const Graph& walked = fine.corridor_graph ? *fine.corridor_graph : graph;
  const auto run = [&](const ColonySettings& s, bool check_every_hook) {
    const Deadline deadline(started, s.time_limit);
    if (s.bidirectional)
      return run_bidirectional(walked, start, goal, pipeline, *backward, s, check_every_hook, deadline);
    if (s.colonies > 1) return run_islands(walked, start, goal, island_pipelines, s, check_every_hook, deadline);
    return run_single(walked, start, goal, pipeline, s, check_every_hook, deadline);
  };
  try {
    ColonyResult result = run(fine.settings, false);
    result.coarse = fine.coarse;
    if (fine.corridor_graph) {
      result.walked_coarse_corridor = true;
      result.pheromone_edges = edges_in(graph, *fine.corridor_graph);
    }
    return result;
  } catch (const PheromoneFoundBad& found) {
    // Strategies start every run afresh (begin_run(), strategies.hpp), so the repeat makes the
    // same writes and its check after every hook throws the Error that names the plugin, the hook
    // and the iteration.
    // Up to the iteration that found the value, with no time limit to stop the repeat earlier.
    ColonySettings repeat = fine.settings;
    repeat.iterations = found.iteration + 1;
    repeat.time_limit = 0.0;
    try {
      run(repeat, true);
    } catch (const PheromoneFoundBad&) {}
    const NodeId from = walked.source(static_cast<EdgeId>(found.edge));
    throw InvalidValueError(
        "the pheromone of edge " + to_string(walked.cell(from)) + " -> " +
        to_string(walked.cell(walked.targets[found.edge])) + " was " + to_string(ParamValue(found.value)) + " " +
        found.where + " in iteration " + std::to_string(found.iteration) +
        " (0-based, as Context::iteration), but not when the run was repeated with a check after every hook: "
        "the init, update or deadlock plugin is not deterministic (aco-plugin-check tells which); it must be "
        "finite and >= 0");
  }
}

}  // namespace aco
