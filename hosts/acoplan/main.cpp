// acoplan: one planning run, composed from runtime plugins on the command line.
#include <tbb/global_control.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <numeric>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/map_io.hpp"
#include "aco/svg.hpp"
#include "command_line.hpp"
#include "irace.hpp"
#include "report.hpp"

namespace {

constexpr int kExitError = 1;
constexpr int kExitUnsolved = 3;

struct Problem {
  std::unique_ptr<aco::Map> map;
  aco::Cell start;
  aco::Cell goal;
};

aco::Cell parse_cell(const std::string& text, const char* option) {
  aco::Cell c;
  const auto comma = text.find(',');
  auto whole = [](std::string_view s, int& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
  };
  if (comma == std::string::npos || !whole(std::string_view(text).substr(0, comma), c.x) ||
      !whole(std::string_view(text).substr(comma + 1), c.y))
    throw aco::Error(std::string(option) + ": '" + text + "' is not a cell; expected X,Y such as 3,7");
  return c;
}

void check_cell(const aco::Map& map, aco::Cell c, const char* what) {
  if (!map.contains(c))
    throw aco::Error(std::string(what) + " " + aco::to_string(c) + " is outside the " + std::to_string(map.width()) + "x" +
                     std::to_string(map.height()) + " map " + map.name());
  if (!map.passable(c))
    throw aco::Error(std::string(what) + " " + aco::to_string(c) + " is blocked: " + map.blocked_reason(c) + " (" +
                     map.name() + ")");
}

Problem load_problem(const acoplan::Request& r) {
  Problem p;
  aco::TerrainOptions terrain;
  terrain.max_slope_deg = r.run.real("max-slope");
  terrain.height_scale = r.run.real("height-scale");
  terrain.cell_size = r.run.real("cell-size");
  if (r.scen) {
    const auto scenarios = aco::load_scenarios(*r.scen);
    const auto index = r.run.integer("scen-index");
    if (index >= static_cast<std::int64_t>(scenarios.size()))
      throw aco::Error("--scen-index " + std::to_string(index) + " is out of range: " + r.scen->string() + " has " +
                       std::to_string(scenarios.size()) + " scenarios");
    const aco::Scenario& s = scenarios[index];
    p.map = aco::load_map(r.map ? *r.map : aco::scenario_map_file(*r.scen), terrain);
    if (p.map->width() != s.width || p.map->height() != s.height)
      throw aco::Error(r.scen->string() + ": scenario " + std::to_string(index) + " is for a " + std::to_string(s.width) +
                       "x" + std::to_string(s.height) + " map, but " + p.map->name() + " is " +
                       std::to_string(p.map->width()) + "x" + std::to_string(p.map->height()));
    p.start = s.start;
    p.goal = s.goal;
  } else {
    p.map = aco::load_map(*r.map, terrain);
    p.start = parse_cell(*r.start, "--start");
    p.goal = parse_cell(*r.goal, "--goal");
  }
  check_cell(*p.map, p.start, "start");
  check_cell(*p.map, p.goal, "goal");
  return p;
}

// One planning run: the colony (or a reference planner), then the smoother.
acoplan::Outcome plan_once(const acoplan::Request& r, const aco::Graph& graph, const Problem& problem,
                           const aco::ColonySettings& settings) {
  aco::PlanRequest request;
  request.planner = r.run.text("planner");
  request.pipeline = r.pipeline;
  request.colony = settings;
  if (const auto baseline = r.baselines.find(request.planner); baseline != r.baselines.end())
    request.planner_parameters = baseline->second;
  acoplan::Outcome o;
  static_cast<aco::PlanOutcome&>(o) =
      aco::plan(*r.registry, graph, graph.node(problem.start), graph.node(problem.goal), request);
  return o;
}

void write_picture(const acoplan::Request& r, const aco::Graph& graph, const acoplan::Outcome& o) {
  aco::RunPicture picture;
  picture.title = graph.map->name() + ": " + (o.solved ? "length " + std::to_string(o.length) : "not solved") +
                  ", seed " + std::to_string(o.seed);
  picture.start = o.start;
  picture.goal = o.goal;
  picture.grid_path = o.grid_path;
  picture.path = o.path;
  if (r.run.boolean("svg-pheromone")) picture.pheromone = o.pheromone;
  picture.best_so_far = o.best_so_far;
  picture.iteration_best = o.iteration_best;
  picture.optimal_length = o.optimal_length.value_or(0.0);
  aco::write_svg(*r.svg, graph, picture);
}

// --irace: the mean length over the runs, an unsolved run counting as kIraceUnsolvedCost, in
// the shortest text that reads back as the same double (so it equals --json's length).
std::string irace_cost(const std::vector<acoplan::Outcome>& runs) {
  const double total = std::accumulate(runs.begin(), runs.end(), 0.0, [](double sum, const acoplan::Outcome& o) {
    return sum + (o.solved ? o.length : acoplan::kIraceUnsolvedCost);
  });
  char text[64];
  const auto end = std::to_chars(text, text + sizeof text, total / static_cast<double>(runs.size())).ptr;
  return std::string(text, end);
}

void dump_irace_params(acoplan::Request& r) {
  const std::string table = acoplan::irace_parameters(*r.registry, r.irace_slots);
  if (r.irace_params_file == "-") {
    std::cout << table;
    return;
  }
  std::ofstream out(r.irace_params_file);
  if (!(out << table) || !out.flush()) throw aco::Error("--dump-irace-params: cannot write '" + r.irace_params_file + "'");
}

int plan(const acoplan::Request& r) {
  const Problem problem = load_problem(r);
  aco::GraphOptions options;
  options.neighbourhood = static_cast<aco::Neighbourhood>(std::stoi(r.run.text("neighbourhood")));
  options.corner_cutting = r.run.boolean("corner-cutting");
  const aco::Graph graph = aco::build_graph(*problem.map, options);
  std::unique_ptr<tbb::global_control> threads;
  if (const auto n = r.run.integer("threads"); n > 0)
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);

  // --repeat N: the same problem with seeds seed, seed+1, ..., seed+N-1.
  aco::ColonySettings settings = aco::colony_settings(r.colony);
  std::vector<acoplan::Outcome> runs;
  for (std::int64_t i = 0; i < r.run.integer("repeat"); ++i, ++settings.seed) runs.push_back(plan_once(r, graph, problem, settings));
  const auto optimal = aco::astar(graph, graph.node(problem.start), graph.node(problem.goal));
  for (auto& o : runs)
    if (optimal) o.optimal_length = optimal->length;

  if (r.irace) {
    // irace reads the last line of stdout; an unsolved run has its cost, so it is no failure.
    std::cout << irace_cost(runs) << "\n";
  } else if (runs.size() == 1) {
    if (r.json) std::cout << acoplan::to_json(r, graph, runs[0]).dump() << "\n";
    else std::cout << acoplan::summary(r, graph, runs[0]);
  } else {
    if (r.json) std::cout << acoplan::to_json(r, graph, runs).dump() << "\n";
    else std::cout << acoplan::summary(r, graph, runs);
  }
  // The picture shows the best run: the shortest solved one, else the first.
  const auto best = std::min_element(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
    return a.solved != b.solved ? a.solved : a.length < b.length;
  });
  if (r.svg) write_picture(r, graph, *best);
  const bool all_solved = std::all_of(runs.begin(), runs.end(), [](const auto& o) { return o.solved; });
  return all_solved || r.irace ? 0 : kExitUnsolved;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    acoplan::Request request = acoplan::parse_command_line(argc, argv);
    switch (request.action) {
      case acoplan::Request::Action::help: std::cout << request.help; return 0;
      case acoplan::Request::Action::list_plugins: std::cout << acoplan::list_plugins(*request.registry); return 0;
      case acoplan::Request::Action::describe:
        std::cout << acoplan::describe_plugin(*request.registry, request.describe);
        return 0;
      case acoplan::Request::Action::print_config: std::cout << request.config; return 0;
      case acoplan::Request::Action::dump_irace_params: dump_irace_params(request); return 0;
      case acoplan::Request::Action::plan: return plan(request);
    }
  } catch (const std::exception& e) {
    std::cerr << "acoplan: error: " << e.what() << "\n";
  }
  return kExitError;
}
