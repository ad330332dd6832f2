#pragma once
// acoplan's outputs: the readable summary and the --json object.
#include <nlohmann/json.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/planning.hpp"
#include "command_line.hpp"

namespace acoplan {

struct Outcome : aco::PlanOutcome {
  std::optional<double> optimal_length;  // exact A* reference on the same graph
};

// One run: its result and the full configuration.
nlohmann::json to_json(const Request& request, const aco::Graph& graph, const Outcome& outcome);
std::string summary(const Request& request, const aco::Graph& graph, const Outcome& outcome);

// Several seeds of one configuration (--repeat): every run, and mean, standard deviation, min
// and max of each measure over the solved runs.
nlohmann::json to_json(const Request& request, const aco::Graph& graph, const std::vector<Outcome>& runs);
std::string summary(const Request& request, const aco::Graph& graph, const std::vector<Outcome>& runs);

}  // namespace acoplan
