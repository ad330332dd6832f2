#include "acoplan.hpp"

#include <algorithm>
#include <charconv>
#include <memory>
#include <numeric>

#include "aco/error.hpp"
#include "aco/host_options.hpp"
#include "aco/irace_parameters.hpp"
#include "aco/memory_limit.hpp"
#include "aco/output_file.hpp"
#include "aco/plan_report.hpp"
#include "aco/plugin_catalog.hpp"
#include "aco/svg.hpp"
#include "aco/thread_limit.hpp"
#include "aco/version.hpp"
#include "aco/voxel_html.hpp"
#include "aco/voxel_svg.hpp"

namespace acoplan {
namespace {

// A voxel world's run as its pictures show it. The pheromone (--svg-pheromone): per voxel the
// strongest edge into it, for the voxels above the median (most voxels keep the initial value, and
// a world has millions), the strongest few thousand of them.
aco::VoxelWorldView voxel_view(const acoplan::Request& r, const aco::Graph& graph, const aco::PlanRun& o) {
  aco::VoxelWorldView view(*graph.map);
  view.title = aco::run_title(graph.map->name(), o.solved(), o.length, o.seed);
  view.path = o.path;
  for (aco::NodeId n : o.search.path) view.grid_path.push_back(graph.cell(n));
  view.start = graph.cell(o.start);
  view.goal = graph.cell(o.goal);
  if (!r.host.svg_pheromone || o.pheromone.empty()) return view;
  std::vector<double> into(graph.num_nodes(), 0.0);
  for (aco::EdgeId e = 0; e < graph.num_edges(); ++e)
    into[graph.targets[e]] = std::max(into[graph.targets[e]], o.pheromone[e]);
  std::vector<aco::NodeId> nodes;
  for (aco::NodeId n = 0; n < graph.num_nodes(); ++n)
    if (graph.degree(n) > 0) nodes.push_back(n);
  if (nodes.empty()) return view;
  const auto stronger = [&](aco::NodeId a, aco::NodeId b) { return into[a] != into[b] ? into[a] > into[b] : a < b; };
  const auto middle = nodes.begin() + static_cast<std::ptrdiff_t>(nodes.size() / 2);
  std::nth_element(nodes.begin(), middle, nodes.end(), stronger);
  const double median = into[*middle];
  constexpr std::size_t kStrongest = 5000;
  const auto kept = nodes.begin() + static_cast<std::ptrdiff_t>(std::min(kStrongest, nodes.size() / 2));
  std::partial_sort(nodes.begin(), kept, middle, stronger);  // ties by node id: the same picture every run
  for (auto n = nodes.begin(); n != kept && into[*n] > median; ++n)
    view.pheromone.emplace_back(graph.cell(*n), into[*n]);
  return view;
}

void write_picture(const acoplan::Request& r, const aco::Graph& graph, const aco::PlanRun& o) {
  if (graph.volumetric) {
    aco::VoxelSvgStyle style;
    style.slices = aco::spread_layers(graph.depth, 4);
    aco::write_voxel_svg(*r.svg, voxel_view(r, graph, o), style);
    return;
  }
  aco::RunPicture picture;
  picture.title = aco::run_title(graph.map->name(), o.solved(), o.length, o.seed);
  picture.start = o.start;
  picture.goal = o.goal;
  picture.grid_path = o.search.path;
  picture.path = o.path;
  if (r.host.svg_pheromone) picture.pheromone = o.pheromone;
  picture.best_so_far = o.search.best_so_far;
  picture.iteration_best = o.iteration_best;
  picture.optimal_length = o.optimal_length.value_or(0.0);
  aco::write_svg(*r.svg, graph, picture);
}

// --irace: the mean cost over the runs, an unsolved run counting as kIraceUnsolvedCost, in the
// shortest text that reads back as the same double (so a length equals --json's length).
std::string irace_cost(const std::vector<aco::PlanRun>& runs, OutputSettings::IraceCost kind, double effort_weight) {
  using Cost = OutputSettings::IraceCost;
  const bool any_angle = kind == Cost::any_angle_gap || kind == Cost::any_angle_gap_penalised;
  const auto quality = [&](const aco::PlanRun& o) {
    if (kind == Cost::length) return o.length;
    double gap = 0.0;
    if (any_angle) {
      if (!o.any_angle_length)
        throw aco::Error("--irace-cost any-angle-gap: the map has no exact any-angle optimum (2D grid maps only)");
      gap = 100.0 * (o.length / *o.any_angle_length - 1.0);
    } else {
      if (!o.optimal_length) throw aco::Error("--irace-cost gap: A* found no path where the colony found one");
      if (o.search.path.empty())  // a continuous planner (ompl)
        throw aco::Error(
            "--irace-cost gap: the planner's path is continuous, with no grid path to compare with A*'s "
            "(use --irace-cost length or any-angle-gap)");
      gap = 100.0 * (o.search.length / *o.optimal_length - 1.0);
    }
    // A path as long as the optimum may differ from it in the last bits (another order of the sums).
    if (gap < 1e-9) return 0.0;
    return kind == Cost::gap || kind == Cost::any_angle_gap ? gap : gap * (1.0 + gap);
  };
  // The ants' moves per walk over the optimal path's length: about 1 for walks as long as it.
  const auto effort = [](const aco::PlanRun& o) {
    const double walks = o.search.walks.empty() ? 0.0 : static_cast<double>(o.search.walks.back());
    if (walks == 0.0 || !o.optimal_length || *o.optimal_length <= 0.0) return 0.0;
    return static_cast<double>(o.count("ant_steps")) / walks / *o.optimal_length;
  };
  const auto cost = [&](const aco::PlanRun& o) {
    if (!o.solved()) return kIraceUnsolvedCost;
    return effort_weight > 0.0 ? quality(o) + effort_weight * effort(o) : quality(o);
  };
  const double total =
      std::accumulate(runs.begin(), runs.end(), 0.0, [&](double sum, const aco::PlanRun& o) { return sum + cost(o); });
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, total / static_cast<double>(runs.size())).ptr;
  return std::string(text, end);
}

void dump_irace_params(acoplan::Request& r, std::ostream& out) {
  const std::string table = r.irace_plugin.empty() ? aco::irace_parameters(*r.registry, r.irace_slots)
                                                   : aco::irace_plugin_parameters(*r.registry, r.irace_plugin);
  if (r.irace_params_file == "-") {
    out << table;
    return;
  }
  aco::write_output_file(r.irace_params_file, table, "irace parameter");
}

int plan(const acoplan::Request& r, std::ostream& out) {
  const aco::MemoryLimit memory(r.max_memory);
  const aco::LoadedProblem problem = aco::load_problem(r.run.problem, r.registry.get());
  const aco::Graph graph = aco::build_graph(*problem.map, r.run.graph);
  const aco::ThreadLimit threads(r.host.threads);

  // --repeat N: the same problem with seeds seed, seed+1, ..., seed+N-1.
  const std::vector<aco::PlanRun> runs =
      aco::plan_runs(*r.registry, graph, graph.node(problem.start), graph.node(problem.goal), r.run, r.host.repeat);
  const aco::PlanReport report{r.run, *r.registry, graph, r.pipeline_source};

  if (r.output.irace) {
    // irace reads the last line of stdout; an unsolved run has its cost, so it is no failure.
    out << irace_cost(runs, r.output.irace_cost, r.output.irace_effort) << "\n";
  } else if (runs.size() == 1) {
    out << (r.output.json ? aco::to_json(report, runs[0]) + "\n" : aco::summary(report, runs[0]));
  } else {
    out << (r.output.json ? aco::to_json(report, runs) + "\n" : aco::summary(report, runs));
  }
  // The picture shows the best run: the shortest solved one, else the first.
  const auto best = std::min_element(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
    return a.solved() != b.solved() ? a.solved() : a.length < b.length;
  });
  if (r.svg) write_picture(r, graph, *best);
  if (r.html) {
    if (!graph.volumetric)
      throw aco::Error("--html draws voxel worlds in 3D; " + graph.map->name() + " is a 2D map (use --svg)");
    aco::write_voxel_html(*r.html, voxel_view(r, graph, *best));
  }
  const bool all_solved = std::all_of(runs.begin(), runs.end(), [](const auto& o) { return o.solved(); });
  return all_solved || r.output.irace ? aco::kExitOk : aco::kExitNoPath;
}

}  // namespace

int run(Request& request, std::ostream& out) {
  switch (request.action) {
    case Request::Action::help:
      out << request.help;
      break;
    case Request::Action::version:
      out << aco::version_text("acoplan") << "\n";
      break;
    case Request::Action::list_plugins:
      out << aco::list_plugins(*request.registry);
      break;
    case Request::Action::list_presets:
      out << list_presets();
      break;
    case Request::Action::describe:
      out << aco::describe_plugin(*request.registry, request.describe);
      break;
    case Request::Action::print_config:
      out << request.config;
      break;
    case Request::Action::dump_irace_params:
      dump_irace_params(request, out);
      break;
    case Request::Action::plan:
      return plan(request, out);
  }
  return aco::kExitOk;
}

}  // namespace acoplan
