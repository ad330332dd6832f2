#pragma once
// Which corridor a path runs through: two paths between the same ends run through the same one
// when they pass every obstacle on the same side, that is when the closed loop "a, then b
// backwards" winds around no obstacle (the paths' h-signatures agree: Bhattacharya, Kumar,
// Likhachev, "Search-based path planning with homotopy class constraints", AAAI 2010). A path
// taking the wrong corridor is a failure of the search, which no smoothing repairs; one in the
// optimal path's corridor can be smoothed to the optimum.
//
// Obstacles are the 8-connected groups of blocked cells (diagonal neighbours touch at a corner, which
// no valid path passes between: aco/any_angle.hpp's rule). A group touching the map's edge joins
// the outside and cannot be gone around. Winding numbers tell homology classes, which are
// homotopy classes for paths that do not circle an obstacle and come back: loop-free paths, as
// every smoothed or optimal path is.
#include <Eigen/Core>
#include <boost/config.hpp>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/map.hpp"

namespace aco {

class BOOST_SYMBOL_VISIBLE CorridorTest {
 public:
  // The obstacles of the map's passable cells, in cell units (a flat grid's positions).
  explicit CorridorTest(const Map& map);
  // Whether polylines a and b (x, y in cell units; z ignored) go round every obstacle on the same
  // side. Their ends need not coincide: the loop closes with straight segments, so give paths
  // between the same start and goal.
  bool same(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b) const;
  std::size_t obstacles() const { return points_.size(); }

 private:
  std::vector<Eigen::Vector2d> points_;  // one point inside each obstacle that can be gone around, by y
};

// A problem's yardstick for continuous paths: the exact any-angle optimum (aco/any_angle.hpp) and
// its corridor. Flat grids only (the optimum knows no heights): on other maps nothing is known.
class BOOST_SYMBOL_VISIBLE OptimalCorridor {
 public:
  OptimalCorridor(const Map& map, Cell start, Cell goal);
  // The optimum; none when the map is not a flat grid or no path joins start and goal.
  const std::optional<AnyAnglePath>& optimum() const { return optimum_; }
  // Whether a path from start to goal runs through the optimum's corridor; none when there is no
  // optimum or no path.
  std::optional<bool> contains(std::span<const Eigen::Vector3d> path) const;

 private:
  std::optional<AnyAnglePath> optimum_;
  std::optional<CorridorTest> test_;
};

}  // namespace aco
