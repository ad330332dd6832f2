#include "report.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace acoplan {
namespace {

nlohmann::json point(const Eigen::Vector3d& p, bool three_d) {
  return three_d ? nlohmann::json::array({p.x(), p.y(), p.z()}) : nlohmann::json::array({p.x(), p.y()});
}

nlohmann::json cell(const aco::Graph& g, aco::NodeId n) {
  const aco::Cell c = g.cell(n);
  return nlohmann::json::array({c.x, c.y});
}

nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json value(const aco::ParamValue& v) {
  return std::visit([](const auto& x) { return nlohmann::json(x); }, v);
}

nlohmann::json values(const aco::ParameterValues& p) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [name, v] : p.all()) object[name] = value(v);
  return object;
}

std::string cell_text(const aco::Graph& g, aco::NodeId n) { return aco::to_string(g.cell(n)); }

}  // namespace

nlohmann::json to_json(const Request& request, const aco::Graph& graph, const aco::LoadedPipeline& pipeline,
                       const Outcome& o) {
  bool three_d = false;
  for (const auto& p : graph.positions) three_d = three_d || p.z() != 0.0;
  nlohmann::json j;
  j["solved"] = o.solved;
  j["length"] = o.solved ? nlohmann::json(o.length) : nlohmann::json(nullptr);
  j["path"] = nlohmann::json::array();
  for (const auto& p : o.path) j["path"].push_back(point(p, three_d));
  j["grid_length"] = o.solved ? nlohmann::json(o.grid_length) : nlohmann::json(nullptr);
  j["grid_path"] = nlohmann::json::array();
  for (aco::NodeId n : o.grid_path) j["grid_path"].push_back(cell(graph, n));
  j["turns"] = o.turns;
  j["iterations"] = o.iterations;
  j["best_iteration"] = o.best_iteration;
  j["time_ms"] = o.time_ms;
  j["seed"] = request.colony.integer("seed");
  if (!o.solved) j["reason"] = o.reason;
  j["planner"] = request.run.text("planner");
  j["map"] = graph.map->name();
  j["width"] = graph.width;
  j["height"] = graph.height;
  j["start"] = cell(graph, o.start);
  j["goal"] = cell(graph, o.goal);
  j["neighbourhood"] = static_cast<int>(graph.options.neighbourhood);
  j["corner_cutting"] = graph.options.corner_cutting;
  j["colony"] = values(request.colony);
  for (const auto& [slot, params] : pipeline.resolved)
    j["pipeline"][slot] = {{"plugin", request.pipeline.slots.at(slot).plugin}, {"params", values(params)}};
  j["ant_steps"] = o.ant_steps;
  j["optimal_length"] = o.optimal_length ? nlohmann::json(*o.optimal_length) : nlohmann::json(nullptr);
  j["convergence"] = nlohmann::json::array();
  for (double v : o.best_so_far) j["convergence"].push_back(number_or_null(v));
  return j;
}

std::string summary(const Request& request, const aco::Graph& graph, const Outcome& o) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(4);
  out << "map:      " << graph.map->name() << " (" << graph.width << "x" << graph.height << "), "
      << aco::describe(graph.options) << "\n";
  out << "problem:  start " << cell_text(graph, o.start) << " -> goal " << cell_text(graph, o.goal) << "\n";
  const std::string planner = request.run.text("planner");
  if (planner == "aco") {
    out << "colony:   " << request.colony.integer("ants") << " ants x " << request.colony.integer("iterations")
        << " iterations, alpha " << aco::to_string(request.colony.all().at("alpha")) << ", beta "
        << aco::to_string(request.colony.all().at("beta")) << ", seed " << request.colony.integer("seed") << "\n";
    out << "pipeline:";
    for (const char* slot : aco::kSlots) out << " " << slot << "=" << request.pipeline.slots.at(slot).plugin;
    out << "\n";
  } else {
    out << "planner:  " << planner << ", smoother=" << request.pipeline.slots.at("smoother").plugin << "\n";
  }
  if (!o.solved) {
    out << "result:   NOT SOLVED: " << o.reason << "\n";
    return out.str();
  }
  out << "result:   length " << o.length << " (grid path " << o.grid_length << "), " << o.turns << " turns, "
      << o.path.size() << " waypoints\n";
  if (o.optimal_length) {
    out << "optimum:  " << *o.optimal_length << " (A* on the same graph), gap " << std::setprecision(2)
        << 100.0 * (o.grid_length - *o.optimal_length) / *o.optimal_length << " % for the grid path\n"
        << std::setprecision(4);
  }
  if (planner == "aco") {
    out << "search:   best found at iteration " << o.best_iteration << " of " << o.iterations << ", " << o.ant_steps
        << " ant steps, " << std::setprecision(2) << o.time_ms << " ms";
    if (o.ant_steps > 0) out << " (" << std::setprecision(1) << o.time_ms * 1e6 / double(o.ant_steps) << " ns per ant step)";
    out << "\n";
  } else {
    out << "search:   " << std::setprecision(2) << o.time_ms << " ms\n";
  }
  out << "path:    ";
  for (aco::NodeId n : o.grid_path) out << " " << cell_text(graph, n);
  out << "\n";
  if (o.path != aco::to_waypoints(graph, o.grid_path)) {
    out << "smoothed:" << std::setprecision(2);
    for (const auto& p : o.path) out << " (" << p.x() << "," << p.y() << ")";
    out << "\n";
  }
  return out.str();
}

}  // namespace acoplan
