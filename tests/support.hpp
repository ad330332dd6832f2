#pragma once
#include <sys/types.h>
// Helpers shared by the tests: data locations, tiny hand-made maps, loaded plugins, running acoplan.
#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "aco/engine/colony.hpp"
#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/planning/run_spec.hpp"

namespace test {

std::filesystem::path data_dir();  // the project's data/

// data/maps/classic20/map<n>.txt, the 20x20 maps of the papers' MATLAB code.
aco::OccupancyGrid classic_map(int n);
// acoplan's arguments for a short run on classic map 1 with the plugins of `plugin_dir`, then `more`.
std::vector<std::string> map1_acoplan_args(const std::string& plugin_dir, const std::vector<std::string>& more);

// A map from rows of text: '#' blocked, anything else free. Row 0 is the top.
aco::OccupancyGrid grid(const std::vector<std::string>& rows);

// A map's graph with the given neighbourhood and corner rule.
aco::Graph build(const aco::Map& map, aco::Neighbourhood n, bool corner_cutting = false);
// Whether the graph has an edge from cell a to cell b.
bool has_edge(const aco::Graph& g, aco::Cell a, aco::Cell b);
// The rows of a w x h map with no obstacle, for grid().
std::vector<std::string> open_grid(int w, int h);

// The build tree's plugins (a process-wide registry).
aco::PluginRegistry& plugins();

// One plugin instantiated with its defaults overridden by `params`.
template <class Interface>
std::unique_ptr<Interface> make(const std::string& slot, const std::string& name,
                                const std::map<std::string, std::string>& params = {}) {
  const auto& descriptor = plugins().load(slot, name);
  return plugins().create<Interface>(slot, name, aco::resolve(descriptor.parameters(), params, slot + "."));
}

// A w x h map whose cells are blocked with a density drawn uniformly from [0, 0.4).
aco::OccupancyGrid random_grid(std::mt19937& rng, int w, int h);

// A random_grid of a size drawn from [min_size, max_size] each way, with a start and a goal drawn
// on it and made free.
struct RandomProblem {
  aco::OccupancyGrid map;
  aco::Cell start, goal;
};
RandomProblem random_problem(std::mt19937& rng, int min_size, int max_size);

// An independent statement of the segment rule of aco::line_of_sight, for checking it and the
// paths smoothers produce: the cells whose interior the segment between the centres of a and b
// meets, the side cells of every grid vertex it passes through, and whether it is free.
std::set<std::pair<int, int>> reference_cells_entered(aco::Cell a, aco::Cell b);
std::vector<std::pair<aco::Cell, aco::Cell>> reference_vertex_sides(aco::Cell a, aco::Cell b);
bool reference_segment_clear(const aco::Map& map, aco::Cell a, aco::Cell b, bool corner_cutting);

// The <text> elements of an SVG picture that reach outside its viewBox (or width and height), each
// described with its box: a text's width is aco::text_width's estimate at its font-size (12 unless
// set on it or the root), its height 0.8 font sizes above the baseline and 0.25 below; x, y, dy,
// text-anchor, rotate(a cx cy) on the text and translate(x,y) on enclosing groups are applied.
// Layouts reserve room with the same estimate, so an empty answer means nothing is cut off.
std::vector<std::string> texts_outside_view_box(const std::string& svg);

// The group <g id="ID"> of an SVG picture, up to its first "</g>" (the pictures' groups hold no
// groups); a picture without it fails the test.
std::string svg_group(const std::string& svg, const std::string& id);

// A Context for calling a strategy directly.
aco::Context context(const aco::Graph& graph, aco::Cell start, aco::Cell goal, int iteration = 0,
                     int max_iterations = 100);

// Checks (Catch CHECKs) that two colony runs are the same bit for bit: path, length, curves,
// arrivals, ant steps, walks, final pheromone, corridors walked and restarts, every double compared
// exactly (the times aside).
void check_same_run(const aco::ColonyResult& a, const aco::ColonyResult& b);

// Checks the anytime curves of a search: as long as its iterations, the time since the search
// began never decreasing, the walks built growing every iteration, ending at `total_walks`.
void check_anytime_curves(const aco::SearchResult& r, std::uint64_t total_walks);

// Runs the colony with 1, 2 and 4 threads, each run with fresh plugins (init, heuristic, update,
// deadlock; the update plugin with `update_params`), checks that the runs are the same bit for bit
// and returns the first.
aco::ColonyResult run_on_thread_counts(const aco::Graph& graph, aco::NodeId start, aco::NodeId goal,
                                       const aco::ColonySettings& settings, const std::array<std::string, 4>& plugins,
                                       const std::map<std::string, std::string>& update_params = {});

// An arrived ant following the given cells (consecutive cells must be neighbours).
aco::Ant ant(const aco::Graph& graph, const std::vector<aco::Cell>& cells);

// A pipeline from run keys ({{"update", "acs"}, {"update.rho", "0.2"}}), other slots at their defaults.
aco::PipelineSpec pipeline(const aco::Keys& keys);

// The baseline strategies (uniform, distance, ant_system, discard) as one pipeline.
struct Baseline {
  std::unique_ptr<aco::PheromoneInit> init = make<aco::PheromoneInit>("init", "uniform");
  std::unique_ptr<aco::Heuristic> heuristic = make<aco::Heuristic>("heuristic", "distance");
  std::unique_ptr<aco::PheromoneUpdate> update = make<aco::PheromoneUpdate>("update", "ant_system");
  std::unique_ptr<aco::DeadlockPolicy> deadlock = make<aco::DeadlockPolicy>("deadlock", "discard");
  aco::ColonyStrategies pipeline() { return {init.get(), heuristic.get(), update.get(), deadlock.get()}; }
};

// Wraps a real update rule and keeps a copy of every iteration's ants for inspection.
class RecordingUpdate final : public aco::PheromoneUpdate {
 public:
  explicit RecordingUpdate(aco::PheromoneUpdate& inner) : inner_(inner) {}
  void begin_run(const aco::Context& c) override { inner_.begin_run(c); }
  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    ants.emplace_back(it.ants.begin(), it.ants.end());
    inner_.update(c, it, tau);
  }
  std::vector<std::vector<aco::Ant>> ants;

 private:
  aco::PheromoneUpdate& inner_;
};

// What is wrong with an ant's walk from `start`, or "" if nothing: its edges must chain its
// nodes, no node may repeat, it has arrived exactly when it ends at `goal`, and then its length
// is the sum of its step costs.
std::string walk_problem(const aco::Graph& graph, const aco::Ant& ant, aco::NodeId start, aco::NodeId goal);

// Voxel worlds' move rule written out apart from aco::Graph (and from aco_mapgen): b = a + (dx, dy,
// dz) free and, without corner cutting, every voxel of the box the move spans, as Moving AI's voxel
// benchmarks define it.
bool reference_voxel_move(const aco::Map& map, aco::Cell a, int dx, int dy, int dz, bool corner_cutting);
// The exact shortest length from start to goal over those moves without corner cutting, costs 1,
// sqrt 2 and sqrt 3 (neighbourhood 6, 18 or 26), by a Dijkstra of its own; nullopt if unreachable.
std::optional<double> reference_voxel_distance(const aco::Map& map, aco::Cell start, aco::Cell goal,
                                               int neighbourhood = 26);

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};
// Runs a program with arguments (no shell), capturing stdout and stderr.
CommandResult run(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});
CommandResult acoplan(const std::vector<std::string>& args, const std::vector<std::string>& env = {});
// Starts a program in the background, its stdout and stderr into `log`; its pid (waitpid it).
pid_t start(const std::vector<std::string>& argv, const std::filesystem::path& log,
            const std::vector<std::string>& env = {});

// A file in a fresh temporary folder, with the given content.
std::filesystem::path temp_file(const std::string& name, const std::string& content);

}  // namespace test
