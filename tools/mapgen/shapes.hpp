// Drawing on an occupancy grid, for aco_mapgen's maps. All clip to the grid; coordinates are cells
// (x = column, y = row from the top).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "aco/map.hpp"
#include "aco/rng.hpp"

namespace mapgen {

void block(aco::OccupancyGrid& g, aco::Cell c);

// Filled rectangle, corners inclusive.
void fill_rect(aco::OccupancyGrid& g, int x0, int y0, int x1, int y1);

// Filled axis-aligned ellipse: every cell whose centre lies inside it.
void fill_ellipse(aco::OccupancyGrid& g, double cx, double cy, double rx, double ry);

// The cells a curve passes through, given as densely sampled points (consecutive samples less
// than one cell apart). Consecutive cells are joined 4-connected: where the curve steps
// diagonally, the cell beside the step is blocked too, so the wall is sealed even for a planner
// that cuts corners.
void draw_curve(aco::OccupancyGrid& g, const std::vector<Eigen::Vector2d>& points);

// Parabola u = k v^2 in the frame of its vertex: u along the axis (the side it opens to),
// v across it, |v| <= half_width. axis need not be normalised.
void draw_parabola(aco::OccupancyGrid& g, Eigen::Vector2d vertex, Eigen::Vector2d axis, double k, double half_width);

int blocked_cells(const aco::OccupancyGrid& g);

std::string format_density(double p);

// Chebyshev distance of a and b at most radius.
bool near(aco::Cell a, aco::Cell b, int radius);

// Blocks each free cell with probability p, except where keep_free says no. One draw per cell in
// row-major order whatever the cell holds, so the pattern does not shift when a shape moves.
void scatter(aco::OccupancyGrid& g, aco::Rng& rng, double p, const std::function<bool(aco::Cell)>& keep_free);

// `count` isolated single cells: free, all 8 neighbours free and in the grid, not within `margin`
// of start or goal. Drawn uniformly from the cells that qualify at each draw.
void scatter_isolated(aco::OccupancyGrid& g, aco::Rng& rng, int count, aco::Cell start, aco::Cell goal, int margin);

}  // namespace mapgen
