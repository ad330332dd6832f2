#include "planner_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <regex>
#include <stdexcept>

#include "aco/engine/plugin_registry.hpp"
#include "aco/error.hpp"
#include "aco/planning/plan_request.hpp"
#include "aco/planning/presets.hpp"
#include "aco/planning/run_pictures.hpp"

namespace aco_ros {
namespace {

constexpr double kDefaultClearance = 0.25;  // cells

// The inverse of run_key(), for messages: "~update.rho" as the user sets it, "~update/rho".
std::string ros_name(const std::string& key) {
  const auto dot = key.find('.');
  std::string top = key.substr(0, dot);
  std::replace(top.begin(), top.end(), '-', '_');
  return dot == std::string::npos ? top : top + "/" + key.substr(dot + 1);
}

// An aco message (its keys spelled "~key") with the keys as ROS parameters.
std::string in_ros_names(const std::string& message) {
  static const std::regex key("~([A-Za-z][A-Za-z0-9_.-]*[A-Za-z0-9_])");
  std::string out;
  auto last = message.cbegin();
  for (std::sregex_iterator it(message.begin(), message.end(), key), end; it != end; ++it) {
    out.append(last, message.cbegin() + it->position(0));
    out += "~" + ros_name((*it)[1].str());
    last = message.cbegin() + it->position(0) + it->length(0);
  }
  return out.append(last, message.cend());
}

std::string metres(Point p) {
  char text[64];
  std::snprintf(text, sizeof text, "(%.3f, %.3f) m", p.x, p.y);
  return text;
}

// The cell at a point of the map's frame: x the column, y the row from the top (aco's convention;
// the map's rows go up from the origin). None outside the map.
std::optional<aco::Cell> cell_at(const GridMap& map, Point p) {
  const double column = std::floor((p.x - map.origin_x) / map.resolution);
  const double row = std::floor((p.y - map.origin_y) / map.resolution);
  if (!(column >= 0 && row >= 0 && column < map.width && row < map.height)) return std::nullopt;
  return aco::Cell{static_cast<int>(column), static_cast<int>(map.height) - 1 - static_cast<int>(row)};
}

// A point of the plan (in cells, aco's rows) in the map's frame.
Point in_frame(const GridMap& map, const Eigen::Vector3d& p) {
  return {map.origin_x + (p.x() + 0.5) * map.resolution,
          map.origin_y + (static_cast<double>(map.height) - 1.0 - p.y() + 0.5) * map.resolution};
}

std::shared_ptr<aco::OccupancyGrid> grid_of(const GridMap& map, const Settings& s) {
  const int width = static_cast<int>(map.width), height = static_cast<int>(map.height);
  auto grid = std::make_shared<aco::OccupancyGrid>(width, height, "the map of frame '" + map.frame + "'");
  for (int row = 0; row < height; ++row)
    for (int x = 0; x < width; ++x) {
      const int occupancy = map.occupancy[static_cast<std::size_t>(row) * width + x];
      grid->set_blocked({x, height - 1 - row},
                        occupancy >= s.occupied_threshold || (occupancy < 0 && !s.allow_unknown));
    }
  return grid;
}

// The goal's cell, or the free cell nearest to it within `tolerance` metres (GetPlan's: how far
// the goal may move where it is obstructed); ties go to the first in row order.
std::optional<aco::Cell> free_cell_near(const aco::OccupancyGrid& grid, aco::Cell goal, double tolerance,
                                        double resolution) {
  if (grid.passable(goal)) return goal;
  const int reach = static_cast<int>(std::floor(std::max(tolerance, 0.0) / resolution));
  std::optional<aco::Cell> best;
  long best_distance = std::numeric_limits<long>::max();
  for (int y = goal.y - reach; y <= goal.y + reach; ++y)
    for (int x = goal.x - reach; x <= goal.x + reach; ++x) {
      const long distance = long(x - goal.x) * (x - goal.x) + long(y - goal.y) * (y - goal.y);
      if (distance <= long(reach) * reach && distance < best_distance && grid.passable({x, y})) {
        best = aco::Cell{x, y};
        best_distance = distance;
      }
    }
  return best;
}

// Per cell the strongest pheromone into it, 0-100, rows as the map's.
std::vector<std::int8_t> pheromone_field(const aco::PlannedRuns& planned) {
  const aco::Graph& graph = planned.graph;
  const std::vector<double> per_cell =
      aco::strongest_into(graph, aco::run_picture(graph, planned.best(), true).pheromone);
  const double strongest = *std::max_element(per_cell.begin(), per_cell.end());
  std::vector<std::int8_t> field(per_cell.size(), 0);
  for (aco::NodeId n = 0; n < graph.num_nodes(); ++n) {
    const aco::Cell c = graph.cell(n);
    const double share = strongest > 0 ? per_cell[static_cast<std::size_t>(n)] / strongest : 0.0;
    field[static_cast<std::size_t>(graph.height - 1 - c.y) * graph.width + c.x] =
        static_cast<std::int8_t>(std::lround(100 * share));
  }
  return field;
}

}  // namespace

std::string run_key(const std::string& name) {
  const auto slash = name.find('/');
  std::string top = name.substr(0, slash);
  std::replace(top.begin(), top.end(), '_', '-');
  return slash == std::string::npos ? top : top + "." + name.substr(slash + 1);
}

struct Planner::Impl {
  aco::PluginRegistry registry{aco::PluginRegistry::default_search_dirs({})};
};

Planner::Planner() : impl_(std::make_unique<Impl>()) {}
Planner::~Planner() = default;

Plan Planner::plan(const GridMap& map, Point start, Point goal, double tolerance, const Settings& settings) {
  try {
    const std::optional<aco::Cell> from = cell_at(map, start), to = cell_at(map, goal);
    if (!from) throw aco::Error("the start " + metres(start) + " is outside the map");
    if (!to) throw aco::Error("the goal " + metres(goal) + " is outside the map");
    const auto grid = grid_of(map, settings);
    if (!grid->passable(*from)) throw aco::Error("the start " + metres(start) + " is in an occupied or unknown cell");
    const std::optional<aco::Cell> target = free_cell_near(*grid, *to, tolerance, map.resolution);
    if (!target)
      throw aco::Error("the goal " + metres(goal) + " is in an occupied or unknown cell, with no free cell within " +
                       std::to_string(tolerance) + " m (the request's tolerance)");

    const aco::KeySpelling spelling("~");
    const auto source = aco::PipelineSource::choose(settings.preset, settings.config, aco::MapKind::grid, spelling);
    aco::KeyedValues changes;
    changes.keys = settings.keys;
    aco::PlanRequest request;
    request.spelling = spelling;
    request.run = aco::resolve_run(aco::over_pipeline_file(source.keys(), changes).keys, impl_->registry, spelling);
    // The node's one default of its own (README.md): a path off the occupied cells' corners,
    // where a robot's costmap or a checker sampling the path would see it touch them.
    aco::SlotSpec& smoother = request.run.pipeline.at("smoother");
    if (!settings.keys.count("smoother.clearance") && smoother.parameters.contains("clearance"))
      smoother.parameters.set("clearance", kDefaultClearance);
    request.run.problem.start = *from;
    request.run.problem.goal = *target;
    request.map = grid;
    request.threads = settings.threads;
    request.pipeline_source = source.description(spelling);
    const aco::PlannedRuns planned = aco::plan(request, impl_->registry);
    const aco::PlanRun& run = planned.best();
    if (!run.solved()) throw aco::Error("no path: " + run.reason);
    Plan plan;
    for (const Eigen::Vector3d& p : run.path) plan.points.push_back(in_frame(map, p));
    plan.length = run.length * map.resolution;
    plan.time_ms = run.time_ms;
    if (settings.publish_pheromone) plan.pheromone = pheromone_field(planned);
    return plan;
  } catch (const std::exception& error) {
    throw std::runtime_error(in_ros_names(error.what()));
  }
}

}  // namespace aco_ros
