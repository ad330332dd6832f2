#pragma once
// acoplan's outputs: the readable summary and the --json object.
#include <nlohmann/json.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/path.hpp"
#include "aco/pipeline.hpp"
#include "command_line.hpp"

namespace acoplan {

struct Outcome {
  std::uint64_t seed = 0;
  bool solved = false;
  std::string reason;  // why not solved
  aco::NodeId start = 0;
  aco::NodeId goal = 0;
  std::vector<aco::NodeId> grid_path;
  double grid_length = 0.0;
  aco::Waypoints path;  // after the smoother
  double length = 0.0;
  int turns = 0;
  int iterations = 0;
  int best_iteration = 0;
  double time_ms = 0.0;
  std::uint64_t ant_steps = 0;
  std::uint64_t evaluations = 0;  // candidate solutions decoded by a baseline planner (ifwa, pso)
  std::string stopped_by;  // which rule ended the colony run
  std::vector<double> best_so_far;
  std::vector<double> iteration_best;
  std::vector<double> pheromone;
  std::optional<double> optimal_length;  // exact A* reference on the same graph
  std::map<std::string, aco::ParameterValues> resolved;  // slot -> every plugin parameter
};

// One run: its result and the full configuration.
nlohmann::json to_json(const Request& request, const aco::Graph& graph, const Outcome& outcome);
std::string summary(const Request& request, const aco::Graph& graph, const Outcome& outcome);

// Several seeds of one configuration (--repeat): every run, and mean, standard deviation, min
// and max of each measure over the solved runs.
nlohmann::json to_json(const Request& request, const aco::Graph& graph, const std::vector<Outcome>& runs);
std::string summary(const Request& request, const aco::Graph& graph, const std::vector<Outcome>& runs);

}  // namespace acoplan
