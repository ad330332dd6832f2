#include "aco/planning/run_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace aco {
namespace {

nlohmann::json point(const Eigen::Vector3d& p, bool three_d) {
  return three_d ? nlohmann::json::array({p.x(), p.y(), p.z()}) : nlohmann::json::array({p.x(), p.y()});
}

nlohmann::json cell(const aco::Graph& g, aco::NodeId n) {
  const aco::Cell c = g.cell(n);
  return g.volumetric ? nlohmann::json::array({c.x, c.y, c.z}) : nlohmann::json::array({c.x, c.y});
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string cell_text(const aco::Graph& g, aco::NodeId n) { return g.map->describe(g.cell(n)); }

// " (x,y)", or " (x,y,z)" in a voxel world, to two decimals.
std::string waypoint_text(const aco::Graph& g, const Eigen::Vector3d& p) {
  std::ostringstream text;
  text.precision(2);
  text << std::fixed << " (" << p.x() << "," << p.y();
  if (g.volumetric) text << "," << p.z();
  text << ")";
  return text.str();
}

std::string map_line(const aco::Graph& graph) {
  const std::string layers = graph.volumetric ? std::string("x") + std::to_string(graph.depth) + " voxels" : "";
  return "map:      " + graph.map->name() + " (" + std::to_string(graph.width) + "x" + std::to_string(graph.height) +
         layers + "), " + aco::describe(graph.options) + "\n";
}

// Whether the summary's other lines show `key`: the map line the graph's, the colony line its
// settings, the pipeline or planner line the plugins and the planner's parameters. A planner
// other than the colony uses no colony setting and no plugin but the smoother.
bool shown_elsewhere(const std::string& key, const aco::RunSpec& run) {
  static const std::set<std::string> lines = {"neighbourhood", "corner-cutting", "planner", "ants",
                                              "iterations",    "alpha",          "beta",    "seed"};
  const std::string owner = key.substr(0, key.find('.'));
  const bool slot_key = std::find(aco::kSlots.begin(), aco::kSlots.end(), owner) != aco::kSlots.end();
  if (lines.count(key) || (slot_key && owner == key)) return true;
  if (run.planner == "aco") return false;
  const auto colony = aco::colony_parameters();
  return owner == run.planner || (slot_key && owner != "smoother") ||
         std::any_of(colony.begin(), colony.end(), [&](const aco::ParamSpec& p) { return key == p.name; });
}

// What else makes this run differ from another of the same pipeline (q0, search, fill-dead-ends,
// a plugin's parameters...): the keys that differ from the engine's defaults.
std::string settings_line(const PlanReport& report) {
  std::string changed;
  for (const auto& [key, value] : aco::changed_values(report.run, report.registry))
    if (!shown_elsewhere(key, report.run)) changed += " " + key + "=" + aco::to_string(value);
  return "settings:" +
         (changed.empty() ? std::string(" the engine defaults") : changed + " (changed from the engine defaults)") +
         ", as --help and --describe SLOT/NAME list them\n";
}

std::string pipeline_lines(const PlanReport& report) {
  const aco::RunSpec& run = report.run;
  std::ostringstream out;
  if (run.planner != "aco") {
    out << "planner:  " << run.planner;
    if (aco::find_planner(run.planner).continuous)
      out << " (a continuous path: no grid path, no smoother)";
    else
      out << ", smoother=" << run.pipeline.at("smoother").plugin;
    if (!run.planner_parameters.all().empty()) {
      for (const auto& [name, v] : run.planner_parameters.all())
        out << " " << run.planner << "." << name << "=" << aco::to_string(v);
      out << ", seed " << run.colony.seed;
    }
    out << "\n" << settings_line(report);
    return out.str();
  }
  out << "colony:   " << run.colony.ants << " ants x " << run.colony.iterations << " iterations, alpha "
      << aco::to_string(run.colony.alpha) << ", beta " << aco::to_string(run.colony.beta) << ", seed "
      << run.colony.seed << "\n";
  if (!report.pipeline_source.empty()) out << "preset:   " << report.pipeline_source << "\n";
  out << "pipeline:";
  for (const char* slot : aco::kSlots) out << " " << slot << "=" << run.pipeline.at(slot).plugin;
  out << "\n" << settings_line(report);
  return out.str();
}

// The measures of one run.
nlohmann::json run_json(const aco::Graph& graph, const PlanRun& o) {
  bool three_d = graph.volumetric;
  for (const auto& p : graph.terrain_positions) three_d = three_d || p.z() != 0.0;
  nlohmann::json j;
  j["solved"] = o.solved();
  j["length"] = o.solved() ? nlohmann::json(o.length) : nlohmann::json(nullptr);
  j["path"] = nlohmann::json::array();
  for (const auto& p : o.path) j["path"].push_back(point(p, three_d));
  j["grid_length"] = o.solved() ? number_or_null(o.search.length) : nlohmann::json(nullptr);  // NaN: no grid path
  j["grid_path"] = nlohmann::json::array();
  for (aco::NodeId n : o.search.path) j["grid_path"].push_back(cell(graph, n));
  j["turns"] = o.turns;
  j["iterations"] = o.search.iterations;
  j["best_iteration"] = o.search.best_iteration;
  j["time_ms"] = o.time_ms;
  j["seed"] = o.seed;
  if (!o.solved()) j["reason"] = o.reason;
  for (const auto& [name, value] : o.properties)
    j[name] = std::visit([](const auto& v) { return nlohmann::json(v); }, value);
  j["optimal_length"] = o.optimal_length ? nlohmann::json(*o.optimal_length) : nlohmann::json(nullptr);
  j["any_angle_length"] = o.any_angle_length ? nlohmann::json(*o.any_angle_length) : nlohmann::json(nullptr);
  j["optimal_corridor"] = o.optimal_corridor ? nlohmann::json(*o.optimal_corridor) : nlohmann::json(nullptr);
  j["convergence"] = nlohmann::json::array();
  for (double v : o.search.best_so_far) j["convergence"].push_back(number_or_null(v));
  j["convergence_time_s"] = o.search.elapsed_s;
  j["convergence_walks"] = o.search.walks;
  return j;
}

// The configuration shared by all runs (the run's keys, as acobench's database stores them),
// and the problem as loaded.
nlohmann::json config_json(const PlanReport& report, const PlanRun& o) {
  const aco::Graph& graph = report.graph;
  nlohmann::json j;
  j["config"] = nlohmann::ordered_json::parse(aco::to_json(report.run));
  j["plugins"] = nlohmann::ordered_json::parse(aco::plugins_json(report.run, report.registry));
  j["map"] = graph.map->name();
  j["width"] = graph.width;
  j["height"] = graph.height;
  if (graph.volumetric) j["depth"] = graph.depth;
  j["start"] = cell(graph, o.start);
  j["goal"] = cell(graph, o.goal);
  return j;
}

struct Stats {
  double mean = 0, sd = 0, min = 0, max = 0;
  std::size_t n = 0;
};

// Sample statistics (standard deviation with n - 1).
Stats stats(const std::vector<double>& v) {
  Stats s;
  s.n = v.size();
  if (v.empty()) return s;
  s.min = *std::min_element(v.begin(), v.end());
  s.max = *std::max_element(v.begin(), v.end());
  for (double x : v) s.mean += x / double(v.size());
  for (double x : v) s.sd += (x - s.mean) * (x - s.mean);
  s.sd = v.size() > 1 ? std::sqrt(s.sd / double(v.size() - 1)) : 0.0;
  return s;
}

// A plugin's figure (Context::record(), add()): "<slot>/<plugin>.<name>", or "plugin.<name>".
bool plugin_figure(const std::string& property) {
  return property.find('/') != std::string::npos || property.rfind("plugin.", 0) == 0;
}

// The run's numeric properties: the planner's counts and the plugins' figures.
std::map<std::string, double> numeric_properties(const PlanOutcome& o) {
  std::map<std::string, double> numbers;
  for (const auto& [name, value] : o.properties) {
    if (const auto* count = std::get_if<std::int64_t>(&value))
      numbers[name] = static_cast<double>(*count);
    else if (const auto* real = std::get_if<double>(&value))
      numbers[name] = *real;
  }
  return numbers;
}

// Each measure over the solved runs (time and the runs' numeric properties over all runs).
std::vector<std::pair<std::string, Stats>> measures(const std::vector<PlanRun>& runs) {
  std::map<std::string, std::vector<double>> v, properties;
  for (const auto& o : runs) {
    for (const auto& [name, value] : numeric_properties(o)) properties[name].push_back(value);
    v["time_ms"].push_back(o.time_ms);
    if (!o.solved()) continue;
    v["length"].push_back(o.length);
    if (!o.search.path.empty()) {  // a continuous planner has no grid path
      v["grid_length"].push_back(o.search.length);
      v["cells"].push_back(double(o.search.path.size()));
    }
    if (o.any_angle_length && *o.any_angle_length > 0)
      v["over_any_angle_pct"].push_back(gap_percent(o.length, *o.any_angle_length));
    if (o.optimal_corridor) v["optimal_corridor"].push_back(*o.optimal_corridor ? 1.0 : 0.0);
    v["turns"].push_back(o.turns);
    v["best_iteration"].push_back(o.search.best_iteration);
    v["iterations"].push_back(o.search.iterations);
  }
  std::vector<std::pair<std::string, Stats>> result;
  for (const char* name : {"length", "grid_length", "over_any_angle_pct", "optimal_corridor", "cells", "turns",
                           "best_iteration", "iterations", "time_ms"})
    result.emplace_back(name, stats(v[name]));
  for (const auto& [name, values] : properties) result.emplace_back(name, stats(values));
  return result;
}

}  // namespace

nlohmann::json run_record(const PlanReport& report, const PlanRun& o) {
  nlohmann::json j = run_json(report.graph, o);
  j.update(config_json(report, o));
  return j;
}

std::string to_json(const PlanReport& report, const PlanRun& o) { return run_record(report, o).dump(); }

std::string to_json(const PlanReport& report, const std::vector<PlanRun>& runs) {
  const aco::Graph& graph = report.graph;
  nlohmann::json j = config_json(report, runs.front());
  j["runs"] = nlohmann::json::array();
  int solved = 0;
  for (const auto& o : runs) {
    j["runs"].push_back(run_json(graph, o));
    solved += o.solved();
  }
  nlohmann::json& s = j["summary"];
  s["runs"] = runs.size();
  s["solved"] = solved;
  s["optimal_length"] =
      runs.front().optimal_length ? nlohmann::json(*runs.front().optimal_length) : nlohmann::json(nullptr);
  for (const auto& [name, st] : measures(runs)) {
    if (st.n == 0)
      s[name] = nullptr;
    else
      s[name] = {{"mean", st.mean}, {"sd", st.sd}, {"min", st.min}, {"max", st.max}};
  }
  return j.dump();
}

std::string summary(const PlanReport& report, const std::vector<PlanRun>& runs) {
  const aco::Graph& graph = report.graph;
  std::ostringstream out;
  const PlanRun& first = runs.front();
  out << map_line(graph);
  out << "problem:  start " << cell_text(graph, first.start) << " -> goal " << cell_text(graph, first.goal);
  if (first.optimal_length) out << ", optimum " << std::fixed << std::setprecision(4) << *first.optimal_length;
  out << "\n";
  out << pipeline_lines(report);
  int solved = 0;
  for (const auto& o : runs) solved += o.solved();
  out << "runs:     " << runs.size() << " seeds (" << first.seed << ".." << runs.back().seed << "), " << solved
      << " solved\n";
  out << std::fixed;
  for (const auto& [name, st] : measures(runs)) {
    out << "  " << std::left << std::setw(15) << name << std::right << (name.size() >= 15 ? " " : "");
    if (st.n == 0) {
      out << "-\n";
      continue;
    }
    const int digits = name == "length" || name == "grid_length"         ? 4
                       : name == "time_ms" || name == "optimal_corridor" ? 2
                                                                         : 1;
    out << std::setprecision(digits) << "mean " << st.mean << "  sd " << st.sd << "  min " << st.min << "  max "
        << st.max << "\n";
  }
  return out.str();
}

std::string summary(const PlanReport& report, const PlanRun& o) {
  const aco::Graph& graph = report.graph;
  std::ostringstream out;
  out << std::fixed << std::setprecision(4);
  out << map_line(graph);
  out << "problem:  start " << cell_text(graph, o.start) << " -> goal " << cell_text(graph, o.goal) << "\n";
  out << pipeline_lines(report);
  const std::string planner = report.run.planner;
  if (!o.solved()) {
    out << "result:   NOT SOLVED: " << o.reason << "\n";
    return out.str();
  }
  const bool grid_path = !o.search.path.empty();  // none from a continuous planner
  out << "result:   length " << o.length;
  if (grid_path)
    out << " (grid path " << o.search.length << ")";
  else
    out << " (a continuous path)";
  out << ", " << o.turns << " turns, " << o.path.size() << " waypoints\n";
  if (o.optimal_length) {
    // A continuous path may cut across the graph's moves: shorter than the graph's optimum.
    const double length = grid_path ? o.search.length : o.length;
    out << "optimum:  " << *o.optimal_length << " (A* on the same graph), gap " << std::setprecision(2)
        << gap_percent(length, *o.optimal_length)
        << (grid_path ? " % for the grid path\n"
                      : " % for the continuous path (it need not follow the graph's moves)\n")
        << std::setprecision(4);
  }
  if (o.any_angle_length) {
    out << "any-angle: " << *o.any_angle_length << " (the exact optimum at any angle), final path "
        << std::setprecision(2) << gap_percent(o.length, *o.any_angle_length) << " % longer";
    if (o.optimal_corridor)
      out << ", " << (*o.optimal_corridor ? "in its corridor" : "in ANOTHER corridor than the optimum's");
    const auto walked = o.properties.find("optimal_corridor_walked");
    if (o.optimal_corridor == false && walked != o.properties.end())
      out << (std::get<std::int64_t>(walked->second) ? " (its walks took the optimum's corridor, then left it)"
                                                     : " (no walk took the optimum's corridor)");
    out << "\n" << std::setprecision(4);
  }
  if (planner == "aco") {
    out << "search:   best found after " << o.search.best_iteration << " of " << o.search.iterations
        << " iterations (stopped by " << o.text("stopped_by") << "), " << o.count("ant_steps") << " ant steps, ";
    if (o.properties.count("corridors"))
      out << o.count("corridors") << (o.count("corridors") == 1 ? " corridor" : " corridors") << " walked, ";
    out << std::setprecision(2) << o.time_ms << " ms";
    if (o.count("ant_steps") > 0)
      out << " (" << std::setprecision(1) << o.time_ms * 1e6 / double(o.count("ant_steps")) << " ns per ant step)";
    out << "\n";
  } else if (aco::find_planner(planner).continuous) {
    // Its curve is one entry per solution it reported (the simplified path the last).
    out << "search:   best found after " << o.search.best_iteration << " of " << o.search.iterations << " solutions";
    for (const auto& [name, value] : o.properties)
      if (name.rfind(planner + ".", 0) == 0) out << ", " << name << " " << aco::to_string(value);
    out << ", " << std::setprecision(2) << o.time_ms << " ms\n";
  } else if (o.count("evaluations") > 0) {
    out << "search:   best found after " << o.search.best_iteration << " of " << o.search.iterations << " iterations, "
        << o.count("evaluations") << " evaluations, " << std::setprecision(2) << o.time_ms << " ms\n";
  } else {
    out << "search:   " << std::setprecision(2) << o.time_ms << " ms\n";
  }
  std::string figures;
  for (const auto& [name, value] : o.properties)
    if (plugin_figure(name)) figures += (figures.empty() ? " " : ", ") + name + " " + aco::to_string(value);
  if (!figures.empty()) out << "figures: " << figures << "\n";
  out << "path:    ";
  for (aco::NodeId n : o.search.path) out << " " << cell_text(graph, n);
  if (!grid_path)
    for (const auto& p : o.path) out << waypoint_text(graph, p);
  out << "\n";
  if (grid_path && o.path != aco::to_waypoints(graph, o.search.path)) {
    out << "smoothed:";
    for (const auto& p : o.path) out << waypoint_text(graph, p);
    out << "\n";
  }
  return out.str();
}

}  // namespace aco
