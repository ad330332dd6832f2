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
#include <algorithm>
#include <boost/config.hpp>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "aco/any_angle.hpp"
#include "aco/graph.hpp"
#include "aco/map.hpp"

namespace aco {

// The obstacles that can be gone around, one cell of each: the first, in row-major order, of every
// 8-connected group of blocked cells that does not touch the map's edge.
std::vector<Cell> obstacles_inside(const Map& map);

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

// A corridor as a number, for telling many walks' corridors apart at one look-up per step: the
// h-signature of a path (Bhattacharya, Kumar, Likhachev, AAAI 2010, as teb_local_planner uses it).
// Each obstacle of obstacles_inside() gets a random 64-bit key and a ray from its cell's centre
// towards +x, just above the centre row (y - epsilon: rows grow downwards, so towards the row
// before); a path's key is the sum of the keys of the rays it crosses, plus when it crosses
// towards larger y and minus towards smaller y, modulo 2^64. Two paths between the same ends have
// the same key exactly when they go round every obstacle on the same side (CorridorTest::same(),
// up to a chance of 2^-64 per pair). The key of a path on its own means nothing: only equal or not.
// Costs 4 bytes per row and 12 per obstacle.
class BOOST_SYMBOL_VISIBLE CorridorKeys {
 public:
  explicit CorridorKeys(const Map& map);
  // x, y in cell units (a flat grid's positions); z ignored.
  std::uint64_t key(std::span<const Eigen::Vector3d> path) const;
  // A walk on a graph of the map: its cells' x and y.
  std::uint64_t key(const Graph& graph, std::span<const NodeId> walk) const;
  std::size_t obstacles() const { return obstacles_; }

 private:
  std::uint64_t crossing(double ax, double ay, double bx, double by) const;
  // The sum of the keys of the row's obstacles at or left of x: the keys a crossing of the row at x
  // counts. A short row (most are) is scanned, a long one (a random map's) searched.
  std::uint64_t keys_up_to(int row, int x) const {
    const std::uint32_t first = row_begin_[static_cast<std::size_t>(row)];
    const std::uint32_t last = row_begin_[static_cast<std::size_t>(row) + 1];
    std::uint32_t after = first;
    if (last - first <= 8)
      while (after < last && ray_x_[after] <= x) ++after;
    else
      after = static_cast<std::uint32_t>(std::upper_bound(ray_x_.begin() + first, ray_x_.begin() + last, x) -
                                         ray_x_.begin());
    return after == first ? 0 : up_to_[after - 1];
  }
  int width_ = 0, height_ = 0;
  // The obstacles' rays row by row, by x: row r's are [row_begin_[r], row_begin_[r + 1]), each
  // with its x and the sum of the keys of its row's rays up to and including it.
  std::vector<std::uint32_t> row_begin_;
  std::vector<std::int32_t> ray_x_;
  std::vector<std::uint64_t> up_to_;
  std::size_t obstacles_ = 0;
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
  // Whether any of a search's walks went through the optimum's corridor, given the keys of the
  // corridors they took (CorridorKeys on the same map; ColonyResult::corridors); none when there
  // is no optimum.
  std::optional<bool> among(std::span<const std::uint64_t> corridor_keys) const;

 private:
  std::optional<AnyAnglePath> optimum_;
  std::optional<CorridorTest> test_;
  std::uint64_t optimum_key_ = 0;
};

}  // namespace aco
