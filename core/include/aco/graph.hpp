#pragma once
// The compact graph the colony runs on: CSR neighbour arrays with Euclidean step costs.
// Node id = (z * height + y) * width + x for every cell (z = 0 but in voxel worlds); blocked
// cells simply have no edges.
#include <Eigen/Core>
#include <array>
#include <boost/config.hpp>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "aco/map.hpp"

namespace aco {

using NodeId = std::int32_t;
using EdgeId = std::int32_t;

// 4, 8, 16: grids and terrains. 6 (faces), 18 (and edges), 26 (and corners): voxel worlds.
enum class Neighbourhood { four = 4, eight = 8, sixteen = 16, six = 6, eighteen = 18, twenty_six = 26 };

// Whether the neighbourhood moves in 3D (6, 18, 26).
constexpr bool volumetric(Neighbourhood n) {
  return n == Neighbourhood::six || n == Neighbourhood::eighteen || n == Neighbourhood::twenty_six;
}

struct GraphOptions {
  Neighbourhood neighbourhood = Neighbourhood::eight;
  // Off: a diagonal step needs both side cells free (Moving AI rule); in a voxel world, every
  // voxel of the box the step spans (Moving AI's voxel benchmarks).
  // On: only the target cell must be free (the rule of the papers' MATLAB code).
  bool corner_cutting = false;
};

std::string describe(const GraphOptions& options);  // "8-neighbourhood, no corner cutting"

struct Move {
  int dx;
  int dy;
  int dz = 0;
};

// The moves of a neighbourhood in the graph's move order: straight, then diagonal, then knight;
// in 3D the 6 faces, then the 12 edges, then the 8 corners.
std::span<const Move> moves(Neighbourhood neighbourhood);

// Memory goes per cell, not per edge: on a 2048x2048 map the graph has 30 million edges. So an
// edge stores only its target and its move (5 bytes); its step length and its reverse edge are
// computed from the move (cost(), reverse_edge()), and a node's position from its cell
// (position()). Only a map whose cell centres are not at their coordinates (a terrain's heights
// and cell size) stores positions and step lengths: terrain_positions and terrain_costs, empty
// on every other map.
struct BOOST_SYMBOL_VISIBLE Graph {
  const Map* map = nullptr;
  GraphOptions options;
  int width = 0;
  int height = 0;
  int depth = 1;  // layers: more than 1 in a voxel world only
  bool volumetric = false;  // a voxel world's graph (6-, 18- or 26-neighbourhood)
  std::vector<EdgeId> offsets;  // edges of node n: [offsets[n], offsets[n+1])
  std::vector<NodeId> targets;  // per edge
  std::vector<std::uint8_t> edge_moves;  // per edge: its index in moves()
  std::vector<std::uint32_t> move_mask;  // per node: which moves (in the graph's move order) have an edge
  std::vector<Eigen::Vector3d> terrain_positions;  // per node on a terrain (Map::position()); else empty
  std::vector<double> terrain_costs;  // per edge on a terrain: the distance between its ends; else empty
  std::array<double, 26> move_lengths{};  // per move in moves(): its Euclidean length

  int num_nodes() const { return width * height * depth; }
  int num_edges() const { return static_cast<int>(targets.size()); }
  EdgeId edges_begin(NodeId n) const { return offsets[n]; }
  EdgeId edges_end(NodeId n) const { return offsets[n + 1]; }
  int degree(NodeId n) const { return offsets[n + 1] - offsets[n]; }
  // The step's Euclidean length (every move here is reversible).
  double cost(EdgeId e) const { return terrain_costs.empty() ? move_lengths[edge_moves[e]] : terrain_costs[e]; }
  // The edge target->source (every move here is reversible).
  EdgeId reverse_edge(EdgeId e) const;
  NodeId source(EdgeId e) const { return targets[reverse_edge(e)]; }
  // The position of the node's cell centre: Map::position() of its cell.
  Eigen::Vector3d position(NodeId n) const {
    if (!terrain_positions.empty()) return terrain_positions[n];
    const Cell c = cell(n);
    return {double(c.x), double(c.y), double(c.z)};
  }

  NodeId node(Cell c) const { return (c.z * height + c.y) * width + c.x; }
  Cell cell(NodeId n) const {
    if (depth == 1) return {n % width, n / width, 0};
    const int layer = width * height, in_layer = n % layer;
    return {in_layer % width, in_layer / width, n / layer};
  }
  bool passable(NodeId n) const { return map->passable(cell(n)); }

  // Edge from a to b, or -1 if they are not neighbours.
  EdgeId find_edge(NodeId a, NodeId b) const;
  // Edge leaving `from` by the move (dx, dy, dz), or -1; O(1), no division.
  EdgeId edge_by_move(NodeId from, int dx, int dy, int dz = 0) const;
  double distance(NodeId a, NodeId b) const { return (position(a) - position(b)).norm(); }
};

// Builds the graph of a map. A voxel world (Map::volumetric()) takes the 6-, 18- or
// 26-neighbourhood and every other map the 4-, 8- or 16-; the other kind is an Error. Knight moves (16-neighbourhood)
// need the two cells their segment crosses to be free, with or without corner cutting: the segment passes through the
// middle of the edge those two cells share, never through a corner. The 16-neighbourhood on a map with no room for a
// knight move (2x2, 1xN) is an Error.
Graph build_graph(const Map& map, const GraphOptions& options);
// The same graph without the nodes marked in `closed` (per node): subgraph(build_graph(map, options),
// closed) without the whole graph ever built, for a world whose graph would not fit in memory
// (the corridor of a voxel world planned coarse to fine).
Graph build_graph(const Map& map, const GraphOptions& options, std::span<const std::uint8_t> closed);

// The graph without the nodes marked in `closed` (per node): their edges, in and out, are gone, and
// node ids, move order and every other edge stay as they are. Per-edge fields on it cost the
// open part's edges only: coarse to fine's ants walk a corridor of a large map.
Graph subgraph(const Graph& graph, std::span<const std::uint8_t> closed);
// Per edge of `part`, a subgraph() of `graph`: its id in `graph`.
std::vector<EdgeId> edges_in(const Graph& graph, const Graph& part);
// Values per edge of `graph`, given at some of its edges (`edges`, with `values` alike): 0 elsewhere.
std::vector<double> per_edge(const Graph& graph, std::span<const EdgeId> edges, std::span<const double> values);

// Whether goal can be reached from start at all, through no node marked in `closed` (if given).
bool reachable(const Graph& graph, NodeId start, NodeId goal, std::span<const std::uint8_t> closed = {});

// Breadth-first search for a path that avoids some nodes. One object serves many searches on a
// graph without clearing per-node arrays in between (stamps), as a plugin searching once per
// dead ant needs.
class BOOST_SYMBOL_VISIBLE BreadthFirstSearch {
 public:
  // A shortest-in-steps path from `from` to `to` entering no node n with blocked[n] != 0 (an
  // empty span blocks none) and not `avoid` (-1: none). Gives up after taking `limit` nodes from
  // the queue. On success path() is the path, from first.
  bool find(const Graph& graph, NodeId from, NodeId to, std::span<const std::uint8_t> blocked = {}, NodeId avoid = -1,
            std::size_t limit = static_cast<std::size_t>(-1));
  const std::vector<NodeId>& path() const { return path_; }

 private:
  std::vector<std::uint32_t> seen_;  // per node: the stamp of the last search that queued it
  std::uint32_t stamp_ = 0;
  std::vector<NodeId> parent_;  // per node: its predecessor, valid where seen_ is current
  std::vector<NodeId> queue_;
  std::vector<NodeId> path_;
};

// Length of a node path (sum of step costs); throws if two consecutive nodes are not neighbours.
double path_length(const Graph& graph, std::span<const NodeId> path);

// Whether the straight segment between the centres of cells a and b is free. Cells are unit
// squares centred on integer (x, y). Every cell whose interior the segment passes through must
// be passable (map.passable, false outside the map). Where the segment passes exactly through a
// grid vertex, from one cell into its diagonal neighbour, the two side cells touching that
// vertex obey the corner rule: without corner cutting both must be passable (the segment may
// not even touch a blocked cell); with corner cutting they must not both be blocked (grazing
// one blocked corner is fine, squeezing between two is not). a == b is free iff a is passable.
// Exact integer traversal, no floating point. On a map with a step rule (a terrain's slope
// limit), every step between consecutive cells the segment enters, including the diagonal step
// through a vertex, must also be Map::step_allowed; on flat maps this adds nothing.
// Note: with corner cutting this is stricter than the move rule for a single diagonal step,
// which may squeeze between two blocked cells.
// In a voxel world the same in 3D: every voxel whose interior the segment between the voxel
// centres passes through must be free; where it passes through an edge or a corner shared by
// several voxels, the box those voxels span obeys the move rule (without corner cutting every
// voxel of it free, with corner cutting not all of the ones beside the segment blocked).
bool line_of_sight(const Map& map, Cell a, Cell b, bool corner_cutting);

// line_of_sight for any two points in the plane (x = column, y = row, in cells; cell (x, y) is the
// unit square centred on (x, y)), as a continuous planner checks its motions. Exact: a few
// orientation tests per grid line crossed, in doubles with a proven error bound and in exact
// rationals where that bound cannot decide, never sampled. On cell centres it is line_of_sight.
// Without corner cutting the closed segment may not touch a blocked cell (nor leave the map)
// anywhere: not in its interior, along its edge or at its corner, its ends included. With corner
// cutting, every cell whose interior the segment meets must be passable; where it runs along a
// cell edge, the two cells beside that edge must not both be blocked; where it passes through a
// grid vertex (not at its ends), neither diagonal pair of the four cells around it may be blocked
// (no squeezing between two blocked cells); a = b is free iff a passable cell touches the point.
// With corner cutting this is the any-angle yardstick's rule (aco/any_angle.hpp).
// Map::step_allowed is not consulted (the plane: a terrain's slope rule has no steps here); a
// non-finite coordinate is not free.
bool segment_free(const Map& map, const Eigen::Vector2d& a, const Eigen::Vector2d& b, bool corner_cutting);

}  // namespace aco
