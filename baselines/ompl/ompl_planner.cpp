#include "ompl/ompl_planner.hpp"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>

#include "aco/error.hpp"
#include "aco/settings_table.hpp"

namespace aco {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

// The planners by name: how to make one, and whether it takes a range (the RRTs' step length).
struct OmplPlanner {
  const char* name;
  bool has_range;
  std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&, double range)> make;
};

template <class P>
ob::PlannerPtr with_range(const ob::SpaceInformationPtr& si, double range) {
  auto planner = std::make_shared<P>(si);
  if (range > 0.0) planner->setRange(range);
  return planner;
}

template <class P>
ob::PlannerPtr plain(const ob::SpaceInformationPtr& si, double) {
  return std::make_shared<P>(si);
}

const std::vector<OmplPlanner>& ompl_planners() {
  static const std::vector<OmplPlanner> planners = {
      {"rrtconnect", true, with_range<og::RRTConnect>},
      {"rrtstar", true, with_range<og::RRTstar>},
      {"informedrrtstar", true, with_range<og::InformedRRTstar>},
      {"bitstar", false, plain<og::BITstar>},
      {"prmstar", false, plain<og::PRMstar>},
      {"aitstar", false, plain<og::AITstar>},
  };
  return planners;
}

const OmplPlanner& find_ompl_planner(const std::string& name) {
  for (const OmplPlanner& p : ompl_planners())
    if (name == p.name) return p;
  throw Error("ompl.planner: '" + name + "' is not one of OMPL's planners here");  // the table's range refuses it first
}

const SettingsTable<OmplSettings>& ompl_table() {
  using S = OmplSettings;
  static const SettingsTable<S> table({
      field("planner", &S::planner, "rrtconnect,rrtstar,informedrrtstar,bitstar,prmstar,aitstar",
            "OMPL's planner: RRT-Connect (stops at its first solution), or an optimizing one that runs for the whole "
            "time limit: RRT*, Informed RRT*, BIT*, PRM*, AIT*"),
      field("time_limit", &S::time_limit, "(0:86400]",
            "seconds OMPL's solve() may take (the simplification comes on top)"),
      field("simplify", &S::simplify, "",
            "shorten the solution with OMPL's PathSimplifier (SimpleSetup::simplifySolution)"),
      field(
          "range", &S::range, "[0:1e6]",
          "longest motion the RRTs (rrtconnect, rrtstar, informedrrtstar) add in one step, in cells; 0: OMPL's default "
          "(a fifth of the map's diagonal)"),
  });
  return table;
}

Eigen::Vector2d point_of(const ob::State* state) {
  const auto* s = state->as<ob::RealVectorStateSpace::StateType>();
  return {s->values[0], s->values[1]};
}

// A state is valid where segment_free() takes the point itself: a passable cell holds it.
class CellValidity : public ob::StateValidityChecker {
 public:
  CellValidity(const ob::SpaceInformationPtr& si, const Map& map, bool corner_cutting)
      : ob::StateValidityChecker(si), map_(map), corner_cutting_(corner_cutting) {}
  bool isValid(const ob::State* state) const override {
    const Eigen::Vector2d p = point_of(state);
    return segment_free(map_, p, p, corner_cutting_);
  }

 private:
  const Map& map_;
  bool corner_cutting_;
};

// The exact motion check: segment_free() on the whole segment, no sampling resolution.
class SegmentValidator : public ob::MotionValidator {
 public:
  SegmentValidator(const ob::SpaceInformationPtr& si, const Map& map, bool corner_cutting)
      : ob::MotionValidator(si), map_(map), corner_cutting_(corner_cutting) {}

  bool checkMotion(const ob::State* from, const ob::State* to) const override {
    const bool free = segment_free(map_, point_of(from), point_of(to), corner_cutting_);
    ++(free ? valid_ : invalid_);
    return free;
  }

  // The last free point by bisection on the fraction (a prefix of a free segment is free).
  bool checkMotion(const ob::State* from, const ob::State* to,
                   std::pair<ob::State*, double>& last_valid) const override {
    const Eigen::Vector2d a = point_of(from), b = point_of(to);
    if (checkMotion(from, to)) return true;
    double low = 0.0, high = 1.0;
    for (int step = 0; step < 60 && low < high; ++step) {
      const double middle = 0.5 * (low + high);
      (segment_free(map_, a, a + middle * (b - a), corner_cutting_) ? low : high) = middle;
    }
    last_valid.second = low;
    if (last_valid.first) si_->getStateSpace()->interpolate(from, to, low, last_valid.first);
    return false;
  }

 private:
  const Map& map_;
  bool corner_cutting_;
};

// OMPL seeds every random generator it makes from one process-global generator; a run reseeds
// it and then makes all of its own, so runs are serialised.
std::mutex& ompl_mutex() {
  static std::mutex mutex;
  return mutex;
}

// OMPL takes a seed in [1, 2^32 - 1] (0 it replaces or ignores).
std::uint32_t ompl_seed(std::uint64_t seed) { return static_cast<std::uint32_t>(seed % 0xFFFFFFFFull) + 1; }

void check_plane(const Graph& graph) {
  for (NodeId n = 0; n < graph.num_nodes(); ++n) {
    const Cell c = graph.cell(n);
    if (graph.position(n) != Eigen::Vector3d(c.x, c.y, 0.0))
      throw Error("ompl: plans in the plane over cells of unit size; " + graph.map->name() + " places cell " +
                  to_string(c) + " elsewhere (a terrain's heights or cell size)");
  }
}

Eigen::Vector3d waypoint(const ob::State* state) {
  const Eigen::Vector2d p = point_of(state);
  return {p.x(), p.y(), 0.0};
}

}  // namespace

std::span<const ParamSpec> ompl_parameters() { return ompl_table().parameters(); }

OmplSettings ompl_settings(const ParameterValues& values) {
  OmplSettings s = ompl_table().read(values);
  if (s.range > 0.0 && !find_ompl_planner(s.planner).has_range)
    throw Error("ompl.range applies to rrtconnect, rrtstar and informedrrtstar, not to " + s.planner +
                " (leave it at 0)");
  return s;
}

OmplResult run_ompl(const Graph& graph, NodeId start, NodeId goal, const OmplSettings& settings) {
  check_endpoints(graph, start, goal, "ompl");
  check_plane(graph);
  if (!(settings.time_limit > 0.0) || !std::isfinite(settings.time_limit))
    throw Error("ompl: time_limit must be a positive number of seconds");
  const OmplPlanner& kind = find_ompl_planner(settings.planner);
  const Map& map = *graph.map;
  const bool corner_cutting = graph.options.corner_cutting;
  const Eigen::Vector3d from = graph.position(start), to = graph.position(goal);

  OmplResult r;
  if (start == goal) {  // no planner needed, and some of OMPL's do not expect it
    r.solved = true;
    r.path = {from};
    r.length = 0.0;
    r.best_so_far = {0.0};
    r.elapsed_s = {0.0};
    r.walks = {1};
    r.status = "start is the goal";
    return r;
  }

  const std::lock_guard lock(ompl_mutex());
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(ompl_seed(settings.seed));  // before the run makes any random generator

  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, -0.5);
  bounds.setHigh(0, graph.width - 0.5);
  bounds.setLow(1, -0.5);
  bounds.setHigh(1, graph.height - 0.5);
  space->setBounds(bounds);
  og::SimpleSetup setup(space);
  const ob::SpaceInformationPtr si = setup.getSpaceInformation();
  setup.setStateValidityChecker(std::make_shared<CellValidity>(si, map, corner_cutting));
  si->setMotionValidator(std::make_shared<SegmentValidator>(si, map, corner_cutting));
  ob::ScopedState<> start_state(space), goal_state(space);
  start_state[0] = from.x();
  start_state[1] = from.y();
  goal_state[0] = to.x();
  goal_state[1] = to.y();
  setup.setStartAndGoalStates(start_state, goal_state);
  setup.setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si));
  setup.setPlanner(kind.make(si, settings.range));

  const auto began = std::chrono::steady_clock::now();
  const auto seconds = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count(); };
  // The optimizing planners report each improved solution (its cost is its length).
  setup.getProblemDefinition()->setIntermediateSolutionCallback(
      [&](const ob::Planner*, const std::vector<const ob::State*>&, const ob::Cost cost) {
        if (!r.best_so_far.empty() && !(cost.value() < r.best_so_far.back())) return;
        r.best_so_far.push_back(cost.value());
        r.elapsed_s.push_back(seconds());
        r.walks.push_back(r.walks.size() + 1);
      });
  const ob::PlannerStatus status = setup.solve(settings.time_limit);
  r.status = status.asString();
  r.solve_time_s = setup.getLastPlanComputationTime();
  {
    ob::PlannerData data(si);
    setup.getPlannerData(data);
    r.graph_states = static_cast<std::int64_t>(data.numVertices());
  }
  r.motion_checks = static_cast<std::int64_t>(si->getMotionValidator()->getValidMotionCount() +
                                              si->getMotionValidator()->getInvalidMotionCount());
  if (status != ob::PlannerStatus::EXACT_SOLUTION || !setup.haveExactSolutionPath()) {
    r.best_so_far.clear();
    r.elapsed_s.clear();
    r.walks.clear();
    r.reason = "OMPL's " + settings.planner + " found no exact solution in " +
               to_string(ParamValue(settings.time_limit)) + " s (" + r.status +
               "; try a longer ompl.time_limit or another ompl.planner)";
    return r;
  }
  const auto record = [&](double length) {
    // The solution as found ends the curve, unless the planner already reported it.
    if (!r.best_so_far.empty() && std::abs(r.best_so_far.back() - length) <= 1e-9 * length) {
      r.best_so_far.back() = length;
      return;
    }
    r.best_so_far.push_back(length);
    r.elapsed_s.push_back(seconds());
    r.walks.push_back(r.walks.size() + 1);
  };
  const auto path_of = [&] {
    Waypoints path;
    for (const ob::State* state : setup.getSolutionPath().getStates()) path.push_back(waypoint(state));
    // The ends are the start and goal states themselves (the goal region's radius is machine epsilon).
    path.front() = from;
    path.back() = to;
    return path;
  };
  record(polyline_length(path_of()));
  if (settings.simplify) {
    setup.simplifySolution();
    r.simplification_time_s = setup.getLastSimplificationTime();
    record(polyline_length(path_of()));
  }
  r.path = path_of();
  r.length = polyline_length(r.path);
  // Every motion was checked by segment_free(); the ends, snapped, are checked again.
  for (std::size_t i = 1; i < r.path.size(); ++i)
    if (!segment_free(map, r.path[i - 1].head<2>(), r.path[i].head<2>(), corner_cutting))
      throw Error("ompl: the solution's segment " + std::to_string(i) + " crosses a blocked cell");
  r.solved = true;
  return r;
}

}  // namespace aco
