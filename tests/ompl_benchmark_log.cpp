// Writes the log of a real OMPL benchmark (ompl::tools::Benchmark) of two planners on a classic
// map, for the test that appends it to an acobench database with OMPL's own script
// (tests/ompl_tools_test.sh).
//   ompl_benchmark_log MAP.txt START_X START_Y GOAL_X GOAL_Y LOG
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

#include "aco/engine/map_io.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;

int main(int argc, char** argv) {
  if (argc != 7) {
    std::cerr << "usage: ompl_benchmark_log MAP.txt START_X START_Y GOAL_X GOAL_Y LOG\n";
    return 2;
  }
  ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
  ompl::RNG::setSeed(1);
  const aco::OccupancyGrid map = aco::load_matrix_map(argv[1]);
  // Cells are unit squares centred on integer coordinates.
  auto space = std::make_shared<ob::RealVectorStateSpace>(2);
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, -0.5);
  bounds.setHigh(0, map.width() - 0.5);
  bounds.setLow(1, -0.5);
  bounds.setHigh(1, map.height() - 0.5);
  space->setBounds(bounds);
  og::SimpleSetup setup(space);
  setup.setStateValidityChecker([&map](const ob::State* state) {
    const double* v = state->as<ob::RealVectorStateSpace::StateType>()->values;
    return map.passable({static_cast<int>(std::lround(v[0])), static_cast<int>(std::lround(v[1]))});
  });
  setup.getSpaceInformation()->setStateValidityCheckingResolution(0.1 / space->getMaximumExtent());
  ob::ScopedState<> start(space), goal(space);
  start[0] = std::atof(argv[2]);
  start[1] = std::atof(argv[3]);
  goal[0] = std::atof(argv[4]);
  goal[1] = std::atof(argv[5]);
  setup.setStartAndGoalStates(start, goal);
  ompl::tools::Benchmark benchmark(setup, "classic map1");
  benchmark.addPlanner(std::make_shared<og::RRTConnect>(setup.getSpaceInformation()));
  benchmark.addPlanner(std::make_shared<og::PRMstar>(setup.getSpaceInformation()));
  ompl::tools::Benchmark::Request request(0.2, 512.0, 3);
  request.displayProgress = false;
  benchmark.benchmark(request);
  return benchmark.saveResultsToFile(argv[6]) ? 0 : 1;
}
