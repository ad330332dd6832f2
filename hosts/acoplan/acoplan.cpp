#include "acoplan.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>

#include "aco/error.hpp"
#include "aco/hosts/host_options.hpp"
#include "aco/planning/irace_parameters.hpp"
#include "aco/process/output_file.hpp"
#include "aco/planning/plan_request.hpp"
#include "aco/planning/run_pictures.hpp"
#include "aco/planning/plugin_catalog.hpp"
#include "aco/drawing/svg.hpp"
#include "aco/process/version.hpp"
#include "aco/drawing/voxel_html.hpp"
#include "aco/drawing/voxel_svg.hpp"

namespace acoplan {
namespace {

void write_pictures(const acoplan::Request& r, const aco::PlannedRuns& planned) {
  const aco::Graph& graph = planned.graph;
  const aco::PlanRun& best = planned.best();
  const bool pheromone = r.host.svg_pheromone;
  if (r.svg && graph.volumetric) {
    aco::VoxelSvgStyle style;
    style.slices = aco::spread_layers(graph.depth, 4);
    aco::write_voxel_svg(*r.svg, aco::run_view(graph, best, pheromone), style);
  } else if (r.svg) {
    aco::write_svg(*r.svg, graph, aco::run_picture(graph, best, pheromone));
  }
  if (r.html) {
    if (!graph.volumetric)
      throw aco::Error("--html draws voxel worlds in 3D; " + graph.map->name() + " is a 2D map (use --svg)");
    aco::write_voxel_html(*r.html, aco::run_view(graph, best, pheromone));
  }
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
      gap = aco::gap_percent(o.length, *o.any_angle_length);
    } else {
      if (!o.optimal_length) throw aco::Error("--irace-cost gap: A* found no path where the colony found one");
      if (o.search.path.empty())  // a continuous planner (ompl)
        throw aco::Error(
            "--irace-cost gap: the planner's path is continuous, with no grid path to compare with A*'s "
            "(use --irace-cost length or any-angle-gap)");
      gap = aco::gap_percent(o.search.length, *o.optimal_length);
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
  aco::PlanRequest request;
  request.run = r.run;
  request.pipeline_source = r.pipeline_source;
  request.threads = r.host.threads;
  request.max_memory = r.max_memory;
  request.repeat = r.host.repeat;  // --repeat N: seeds seed, seed+1, ..., seed+N-1
  const aco::PlannedRuns planned = aco::plan(request, *r.registry);
  if (r.output.irace)  // irace reads the last line of stdout; an unsolved run has its cost, so it is no failure
    out << irace_cost(planned.runs, r.output.irace_cost, r.output.irace_effort) << "\n";
  else
    out << (r.output.json ? planned.json() + "\n" : planned.summary());
  write_pictures(r, planned);  // the best run: the shortest solved one, else the first
  return planned.all_solved() || r.output.irace ? aco::kExitOk : aco::kExitNoPath;
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
