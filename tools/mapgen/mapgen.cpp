// aco_mapgen OUTDIR [TERRAIN_OUTDIR]: writes the look-alike maps of the papers' 20x20 experiments
// (and paper 003's 15x15 figure) into OUTDIR, and paper 004's into TERRAIN_OUTDIR if given, as
// Moving AI .map files, each with a one-line .scen whose optimal length is exact A* on the
// 8-neighbourhood without corner cutting.
//
// aco_mapgen --ros OUTDIR writes data/maps/ros's office, a ROS map_server YAML + PGM map.
//
// aco_mapgen --benchmark OUTDIR writes the generated validation maps of data/maps/generated
// (random, room, maze, cave and hall maps, 20 scenarios each; see write_benchmark); --large the
// same families at 1024 and 2048 cells a side. A FAMILY list after the seed writes only those, and
// the building families (office, 8room, doors: tools/mapgen/families.hpp) only when named.
//
// aco_mapgen --upsample MAP FACTOR OUTDIR [COUNT] draws a Moving AI map FACTOR times larger, with
// COUNT scenarios: a large map of a real map's shape.
//
// aco_mapgen --voxel KIND WxHxD SEED OUTDIR [COUNT] writes a voxel world (city, forest or caves)
// as a Moving AI .3dmap with COUNT scenarios in its .3dmap.3dscen (see write_voxel_world).
//
// The papers' maps exist only as figures; these maps imitate them (obstacle kinds, placement,
// random density), they are not the originals. See data/maps/papers/README.md.
//
// Deterministic: fixed seeds, aco::Rng only (no std:: distributions, no clock), so two runs write
// byte-identical files.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "aco/astar.hpp"
#include "aco/best_first.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/rng.hpp"
#include "aco/voxel.hpp"
#include "families.hpp"
#include "files.hpp"
#include "shapes.hpp"
#include "voxel_worlds.hpp"

namespace {

using aco::Cell;
using aco::OccupancyGrid;
using mapgen::blocked_cells;
using mapgen::draw_parabola;
using mapgen::fill_ellipse;
using mapgen::fill_rect;
using mapgen::format_density;
using mapgen::near;
using mapgen::scatter;
using mapgen::scatter_isolated;
using mapgen::write_file;
using mapgen::write_voxel_world;

struct PaperMap {
  std::string name;  // file stem: <name>.map, <name>.map.scen
  OccupancyGrid grid;
  Cell start;
  Cell goal;
  int margin = 0;  // cells within this Chebyshev distance of start and goal must be free
  std::string seed_note;  // how the random part was drawn, for the summary line
};

// ---------------------------------------------------------------------------------------------
// Checks and lengths.

std::optional<double> optimal_length(const OccupancyGrid& g, Cell start, Cell goal, aco::GraphOptions options) {
  const aco::Graph graph = aco::build_graph(g, options);
  const auto path = aco::astar(graph, graph.node(start), graph.node(goal));
  if (!path) return std::nullopt;
  return path->length;
}

constexpr aco::GraphOptions kScenarioGraph{aco::Neighbourhood::eight, false};

// Empty string if the map is usable, otherwise what is wrong with it.
std::string problem(const PaperMap& m) {
  const auto& g = m.grid;
  for (const auto& [what, c] : {std::pair{"start", m.start}, std::pair{"goal", m.goal}}) {
    if (!g.contains(c)) return std::string(what) + " " + aco::to_string(c) + " is outside the map";
    for (int y = c.y - m.margin; y <= c.y + m.margin; ++y)
      for (int x = c.x - m.margin; x <= c.x + m.margin; ++x)
        if (g.contains({x, y}) && g.blocked({x, y}))
          return std::string(what) + " " + aco::to_string(c) + ": cell " + aco::to_string({x, y}) +
                 " within the free margin " + std::to_string(m.margin) + " is blocked";
  }
  if (!optimal_length(g, m.start, m.goal, kScenarioGraph))
    return "goal " + aco::to_string(m.goal) + " is unreachable from start " + aco::to_string(m.start) +
           " (8-neighbourhood, no corner cutting)";
  return {};
}

// ---------------------------------------------------------------------------------------------
// The maps.

// Paper 001 (fig. 1/2): 20x20, a filled ellipse, a filled rectangle and a parabola, every other
// cell an obstacle with probability 15 %. The paper drops its three shapes at random places; here
// they have fixed places so that the parabola always sits across the way. Start (0,20) and goal (20,0) of the paper (y
// up) are the bottom-left and top-right cells. The parabola is a cup open downwards, towards the start's side, across
// the start-goal diagonal: ants heading straight for the goal walk into it and have to turn back. If a seed gives an
// invalid map (start or goal cut off), the next seed is tried.
PaperMap paper001() {
  constexpr std::uint64_t kFirstSeed = 1;
  constexpr int kAttempts = 1000;
  constexpr double kDensity = 0.15;
  for (std::uint64_t seed = kFirstSeed; seed < kFirstSeed + kAttempts; ++seed) {
    PaperMap m{"paper001", OccupancyGrid(20, 20, "paper001"), {0, 19}, {19, 0}, 1, ""};
    fill_ellipse(m.grid, 4.5, 3.5, 3.6, 2.6);  // upper left, rows 1-6
    fill_rect(m.grid, 14, 15, 17, 17);  // lower right, 4x3
    draw_parabola(m.grid, {12.0, 5.0}, {0.0, 1.0}, 0.4, 4.5);  // y = 5 + 0.4 (x-12)^2, |x-12| <= 4.5
    const int shape_cells = blocked_cells(m.grid);
    aco::Rng rng(seed);
    const auto in_margin = [&](Cell c) { return near(c, m.start, m.margin) || near(c, m.goal, m.margin); };
    scatter(m.grid, rng, kDensity, in_margin);
    if (problem(m).empty()) {
      const int random_cells = blocked_cells(m.grid) - shape_cells;
      m.seed_note = std::to_string(shape_cells) + " shape cells + " + std::to_string(random_cells) +
                    " random (density " + format_density(kDensity) + ", seed " + std::to_string(seed) +
                    ", the first valid seed from " + std::to_string(kFirstSeed) + ")";
      return m;
    }
  }
  throw aco::Error("paper001: no valid map among seeds " + std::to_string(kFirstSeed) + ".." +
                   std::to_string(kFirstSeed + kAttempts - 1));
}

// Paper 002 (fig. 1): a 20x20 warehouse. Shelf rows (long, 1-2 cells thick) with aisles, a
// conveyor along the right side with one gap, barriers (isolation belts) and 2x2 picking
// stations. No random cells.
PaperMap paper002() {
  PaperMap m{"paper002", OccupancyGrid(20, 20, "paper002"), {1, 1}, {18, 18}, 1, "no random cells"};
  auto& g = m.grid;
  // Shelf rows, two cells thick, cross aisles staggered so the way down zigzags.
  fill_rect(g, 0, 3, 10, 4);
  fill_rect(g, 12, 3, 15, 4);
  fill_rect(g, 3, 7, 15, 8);
  fill_rect(g, 0, 11, 5, 12);
  fill_rect(g, 7, 11, 13, 12);
  // Single-thickness shelf row at the bottom.
  fill_rect(g, 3, 15, 13, 15);
  // Conveyor along the right side with a gap.
  fill_rect(g, 17, 0, 17, 9);
  fill_rect(g, 17, 12, 17, 16);
  // Barriers.
  fill_rect(g, 15, 11, 16, 11);
  fill_rect(g, 1, 17, 1, 19);
  // Picking stations beside the conveyor.
  fill_rect(g, 18, 4, 19, 5);
  fill_rect(g, 15, 18, 16, 19);
  return m;
}

// Paper 003 (fig. 1, 15x15, and the 20x20 comparison maps): rectangles of different sizes, an L,
// and a few isolated cells (placed with a fixed seed). Start top-left, goal bottom-right.
PaperMap paper003_20() {
  constexpr std::uint64_t kSeed = 3;
  constexpr int kIsolated = 8;
  PaperMap m{"paper003_20",
             OccupancyGrid(20, 20, "paper003_20"),
             {0, 0},
             {19, 19},
             1,
             std::to_string(kIsolated) + " isolated cells drawn with seed " + std::to_string(kSeed)};
  auto& g = m.grid;
  fill_rect(g, 3, 2, 5, 4);  // 3x3
  fill_rect(g, 9, 1, 10, 6);  // 2x6 column
  fill_rect(g, 14, 3, 17, 4);  // 4x2
  fill_rect(g, 2, 8, 7, 9);  // 6x2 bar
  fill_rect(g, 12, 8, 13, 13);  // L: vertical leg
  fill_rect(g, 12, 12, 17, 13);  //    horizontal leg
  fill_rect(g, 4, 13, 8, 16);  // 5x4 block
  fill_rect(g, 15, 16, 16, 17);  // 2x2
  fill_rect(g, 10, 17, 11, 19);  // 2x3 from the bottom edge
  aco::Rng rng(kSeed);
  scatter_isolated(g, rng, kIsolated, m.start, m.goal, 2);
  return m;
}

PaperMap paper003_15() {
  constexpr std::uint64_t kSeed = 4;
  constexpr int kIsolated = 5;
  PaperMap m{"paper003_15",
             OccupancyGrid(15, 15, "paper003_15"),
             {0, 0},
             {14, 14},
             1,
             std::to_string(kIsolated) + " isolated cells drawn with seed " + std::to_string(kSeed)};
  auto& g = m.grid;
  fill_rect(g, 2, 2, 4, 3);  // 3x2
  fill_rect(g, 7, 1, 8, 4);  // 2x4 column
  fill_rect(g, 3, 6, 6, 8);  // 4x3 block
  fill_rect(g, 9, 6, 9, 10);  // L: vertical leg
  fill_rect(g, 9, 10, 12, 10);  //    horizontal leg
  fill_rect(g, 1, 11, 4, 12);  // 4x2
  fill_rect(g, 12, 2, 13, 3);  // 2x2
  fill_rect(g, 6, 12, 7, 14);  // 2x3 from the bottom edge
  aco::Rng rng(kSeed);
  scatter_isolated(g, rng, kIsolated, m.start, m.goal, 2);
  return m;
}

// Paper 004 (section 2, fig. 2-4): a 20x20 map "with criss-crossing obstacles", horizontal and
// vertical bars that cross or meet in pluses, Ts and Ls, with gaps between them. No random cells.
// Start top left, goal bottom right.
PaperMap paper004() {
  PaperMap m{"paper004", OccupancyGrid(20, 20, "paper004"), {0, 0}, {19, 19}, 1, "no random cells"};
  auto& g = m.grid;
  fill_rect(g, 2, 4, 9, 4);  // plus, upper left: horizontal bar
  fill_rect(g, 6, 1, 6, 8);  //                    vertical bar
  fill_rect(g, 10, 0, 10, 3);  // stub from the top edge
  fill_rect(g, 14, 3, 18, 3);  // T, upper right: top bar
  fill_rect(g, 16, 3, 16, 8);  //                 stem
  fill_rect(g, 8, 10, 16, 10);  // plus, centre: horizontal bar
  fill_rect(g, 12, 6, 12, 14);  //               vertical bar
  fill_rect(g, 0, 8, 3, 8);  // bar from the left edge
  fill_rect(g, 4, 11, 4, 17);  // plus, lower left: vertical bar
  fill_rect(g, 1, 14, 8, 14);  //                   horizontal bar
  fill_rect(g, 8, 17, 13, 17);  // L, bottom: horizontal leg
  fill_rect(g, 8, 15, 8, 17);  //            vertical leg
  fill_rect(g, 15, 14, 19, 14);  // bar into the right edge
  fill_rect(g, 16, 16, 16, 18);  // short post above the goal's corner
  return m;
}

// ---------------------------------------------------------------------------------------------
// Output.

std::string format_length(double length) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.8g", length);
  return buffer;
}

std::string movingai_map_text(const OccupancyGrid& g) {
  std::string map =
      "type octile\nheight " + std::to_string(g.height()) + "\nwidth " + std::to_string(g.width()) + "\nmap\n";
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) map += g.blocked({x, y}) ? '@' : '.';
    map += '\n';
  }
  return map;
}

// One .scen line (without the "version 1" header): bucket, map file, size, start, goal, length.
std::string scenario_line(int bucket, const std::string& map_name, const OccupancyGrid& g, Cell start, Cell goal,
                          double length) {
  return std::to_string(bucket) + "\t" + map_name + ".map\t" + std::to_string(g.width()) + "\t" +
         std::to_string(g.height()) + "\t" + std::to_string(start.x) + "\t" + std::to_string(start.y) + "\t" +
         std::to_string(goal.x) + "\t" + std::to_string(goal.y) + "\t" + format_length(length) + "\n";
}

void write_map(const PaperMap& m, const std::filesystem::path& dir) {
  if (const auto why = problem(m); !why.empty()) throw aco::Error(m.name + ": " + why);
  const auto& g = m.grid;
  const double length = *optimal_length(g, m.start, m.goal, kScenarioGraph);
  write_file(dir / (m.name + ".map"), movingai_map_text(g));
  write_file(dir / (m.name + ".map.scen"), "version 1\n" + scenario_line(0, m.name, g, m.start, m.goal, length));

  const double cut = *optimal_length(g, m.start, m.goal, {aco::Neighbourhood::eight, true});
  const double four = *optimal_length(g, m.start, m.goal, {aco::Neighbourhood::four, false});
  std::cout << m.name << ": " << g.width() << "x" << g.height() << ", start " << aco::to_string(m.start) << ", goal "
            << aco::to_string(m.goal) << ", " << blocked_cells(g) << " blocked, " << m.seed_note
            << "\n  optimal length: 8-conn no corner cutting " << format_length(length) << ", 8-conn corner cutting "
            << format_length(cut) << ", 4-conn " << format_length(four) << "\n";
}

// Exact distances from `from` over the graph (Dijkstra); infinity where unreachable. Used only to
// choose goals at given distances, never by a planner.
std::vector<double> distances_from(const aco::Graph& graph, aco::NodeId from) {
  return aco::search_edges(graph, from, -1, [](aco::NodeId) { return 0.0; }).take_costs();
}

// The nodes of the largest connected part of the map (8-neighbourhood, no corner cutting).
std::vector<aco::NodeId> largest_component(const aco::Graph& graph) {
  std::vector<int> label(graph.num_nodes(), -1);
  std::vector<aco::NodeId> best, current, queue;
  for (aco::NodeId s = 0; s < graph.num_nodes(); ++s) {
    if (label[s] >= 0 || !graph.passable(s)) continue;
    current.clear();
    queue.assign(1, s);
    label[s] = s;
    while (!queue.empty()) {
      const aco::NodeId n = queue.back();
      queue.pop_back();
      current.push_back(n);
      for (aco::EdgeId e = graph.edges_begin(n); e != graph.edges_end(n); ++e)
        if (label[graph.targets[e]] < 0) {
          label[graph.targets[e]] = s;
          queue.push_back(graph.targets[e]);
        }
    }
    if (current.size() > best.size()) best = current;
  }
  std::sort(best.begin(), best.end());
  return best;
}

// `count` scenarios in the largest connected part: the k-th from a random start to the node whose
// distance is closest to a random fraction in [k/count, (k+1)/count) of that start's farthest
// distance, so short and long problems are equally represented. Bucket = floor(length / 4) as in
// Moving AI's files; lengths are exact A* on the scenario graph.
std::string scenarios(const OccupancyGrid& g, int count, aco::Rng& rng) {
  const aco::Graph graph = aco::build_graph(g, kScenarioGraph);
  const std::vector<aco::NodeId> part = largest_component(graph);
  if (part.size() < 2) throw aco::Error(g.name() + ": no two connected free cells");
  std::string text = "version 1\n";
  for (int k = 0; k < count; ++k) {
    const aco::NodeId start = part[rng.below(part.size())];
    const std::vector<double> d = distances_from(graph, start);
    double farthest = 0.0;
    for (aco::NodeId n : part) farthest = std::max(farthest, d[n]);
    const double target = (k + rng.uniform()) / count * farthest;
    aco::NodeId goal = -1;
    for (aco::NodeId n : part)
      if (n != start && (goal < 0 || std::abs(d[n] - target) < std::abs(d[goal] - target))) goal = n;
    const double length = *optimal_length(g, graph.cell(start), graph.cell(goal), kScenarioGraph);
    text += scenario_line(static_cast<int>(length / 4.0), g.name(), g, graph.cell(start), graph.cell(goal), length);
  }
  return text;
}

// The validation set: random, room and maze maps at 32x32, 64x64 and 512x512, and open maps (caves,
// halls: large regions, few narrow passages) at 256x256 and 512x512; three seeds for the 32 and
// 64 maps and two for the others, 20 scenarios each. The tuning maps were Moving AI's random512-10,
// 8room/64room, maze512-1 (perfect, corridor 1), so the parameters here differ: 25 % and 20 %
// obstacles, 32-cell rooms, corridors 2 and 4 cells wide with loops.
// first_seed shifts every seed, for a tuning set disjoint from the shipped one.
// With `large`, all five families at 1024x1024 and 2048x2048 instead, one seed and 10 scenarios
// each: the scale measurements' maps.
// `families`: only those families' maps, comma-separated ("" = the five above). The building
// families are written only when named, so that the shipped set stays what it is: office plans
// (256 and 512), 8room (512x512 with 8-cell rooms, as Moving AI's 8room maps) and doors (rooms of
// 32 to 64 cells, doors of 1 to 6 cells, at 256 and 512).
void write_benchmark(const std::filesystem::path& dir, int first_seed, bool large, const std::string& families) {
  const int kScenarios = large ? 10 : 20;
  struct Spec {
    std::string family;
    int size;
  };
  const std::vector<Spec> specs =
      large ? std::vector<Spec>{{"random", 1024}, {"random", 2048}, {"room", 1024}, {"room", 2048}, {"maze", 1024},
                                {"maze", 2048},   {"cave", 1024},   {"cave", 2048}, {"hall", 1024}, {"hall", 2048}}
            : std::vector<Spec>{{"random", 32}, {"random", 64}, {"random", 512}, {"room", 32},  {"room", 64},
                                {"room", 512},  {"maze", 32},   {"maze", 64},    {"maze", 512}, {"cave", 256},
                                {"cave", 512},  {"hall", 256},  {"hall", 512}};
  const std::vector<Spec> buildings =
      large ? std::vector<Spec>{{"office", 1024}, {"office", 2048}}
            : std::vector<Spec>{{"office", 256}, {"office", 512}, {"8room", 512}, {"doors", 256}, {"doors", 512}};
  std::vector<Spec> chosen;
  std::stringstream list(families);
  for (std::string family; std::getline(list, family, ',');) {
    const std::size_t before = chosen.size();
    for (const auto& known : {specs, buildings})
      std::copy_if(known.begin(), known.end(), std::back_inserter(chosen),
                   [&](const Spec& spec) { return spec.family == family; });
    if (chosen.size() == before)
      throw aco::Error("no map family '" + family + "' (random, room, maze, cave, hall" +
                       (large ? ", office)" : ", office, 8room, doors)"));
  }
  if (families.empty()) chosen = specs;
  for (const auto& spec : chosen) {
    const int seeds = spec.size <= 64 ? 3 : spec.size <= 512 ? 2 : 1;
    for (int seed = first_seed; seed < first_seed + seeds; ++seed) {
      aco::Rng rng(static_cast<std::uint64_t>(spec.size) * 1000 + seed);
      std::string name;
      std::optional<OccupancyGrid> grid;
      if (spec.family == "random") {
        const double density = spec.size <= 64 ? 0.25 : 0.20;
        name = "random" + std::to_string(spec.size) + "-" + std::to_string(static_cast<int>(density * 100)) + "-s" +
               std::to_string(seed);
        grid = mapgen::random_map(spec.size, density, rng, name);
      } else if (spec.family == "room") {
        const int room = spec.size <= 64 ? 8 : 32;
        name = "room" + std::to_string(spec.size) + "-" + std::to_string(room) + "-s" + std::to_string(seed);
        grid = mapgen::room_map(spec.size, room, 0.3, rng, name);
      } else if (spec.family == "8room") {
        name = "8room" + std::to_string(spec.size) + "-s" + std::to_string(seed);
        grid = mapgen::room_map(spec.size, 8, 0.5, rng, name);
      } else if (spec.family == "cave") {
        const int scale = spec.size <= 256 ? 4 : spec.size <= 1024 ? 8 : 16;
        name = "cave" + std::to_string(spec.size) + "-" + std::to_string(scale) + "-s" + std::to_string(seed);
        grid = mapgen::cave_map(spec.size, scale, 0.3, rng, name);
      } else if (spec.family == "hall" || spec.family == "doors") {
        const bool doors = spec.family == "doors";
        const int room = spec.size / (doors ? 16 : 8);
        name = spec.family + std::to_string(spec.size) + "-" + std::to_string(room) + "-s" + std::to_string(seed);
        grid = mapgen::hall_map(spec.size, room, doors ? 0.3 : 0.2, doors ? 6 : 3, rng, name);
      } else if (spec.family == "office") {
        const int room = spec.size / 20;
        name = "office" + std::to_string(spec.size) + "-" + std::to_string(room) + "-s" + std::to_string(seed);
        grid = mapgen::office_map(spec.size, room, 0.3, rng, name);
      } else {
        const int corridor = spec.size <= 32 ? 1 : spec.size <= 64 ? 2 : 4;
        name = "maze" + std::to_string(spec.size) + "-" + std::to_string(corridor) + "-s" + std::to_string(seed);
        grid = mapgen::maze_map(spec.size, corridor, 0.05, rng, name);
      }
      write_file(dir / (name + ".map"), movingai_map_text(*grid));
      write_file(dir / (name + ".map.scen"), scenarios(*grid, kScenarios, rng));
      std::cout << name << ": " << spec.size << "x" << spec.size << ", " << mapgen::blocked_cells(*grid) << " blocked, "
                << kScenarios << " scenarios\n";
    }
  }
}

// --upsample: a Moving AI map drawn FACTOR times larger (every cell a FACTOR x FACTOR block), as
// a large map with a real map's shape, with `count` scenarios spread over the path lengths in its
// largest connected part (the longest last).
void write_upsampled(const std::filesystem::path& file, int factor, const std::filesystem::path& dir, int count) {
  if (factor < 1 || factor > 64) throw aco::Error("--upsample: FACTOR must be 1 to 64, not " + std::to_string(factor));
  const OccupancyGrid small = aco::load_movingai_map(file);
  const std::string name = file.stem().string() + "-x" + std::to_string(factor);
  OccupancyGrid g(small.width() * factor, small.height() * factor, name);
  for (int y = 0; y < g.height(); ++y)
    for (int x = 0; x < g.width(); ++x) g.set_blocked({x, y}, small.blocked({x / factor, y / factor}));
  aco::Rng rng(static_cast<std::uint64_t>(factor) * 1000 + static_cast<std::uint64_t>(count));
  write_file(dir / (name + ".map"), movingai_map_text(g));
  write_file(dir / (name + ".map.scen"), scenarios(g, count, rng));
  std::cout << name << ": " << g.width() << "x" << g.height() << ", " << blocked_cells(g) << " blocked, " << count
            << " scenarios\n";
}

// A ROS map_server map (--ros): a 10 m x 7 m office at 0.1 m per cell, as a robot's scan would
// leave it: walls, three rooms above a corridor and two below, each with a door, desks, and
// unknown space (grey 205) around the outer walls. Drawn by hand, no randomness.
struct Rect {
  int x0, y0, x1, y1;  // cells, both ends included
};

void write_ros_office(const std::filesystem::path& dir) {
  constexpr int kWidth = 100, kHeight = 70;
  constexpr unsigned char kFree = 254, kOccupied = 0, kUnknown = 205;  // map_saver's trinary values
  std::vector<unsigned char> pixels(static_cast<std::size_t>(kWidth) * kHeight, kUnknown);
  auto fill = [&](Rect r, unsigned char value) {
    for (int y = r.y0; y <= r.y1; ++y)
      for (int x = r.x0; x <= r.x1; ++x) pixels[static_cast<std::size_t>(y) * kWidth + x] = value;
  };
  fill({4, 4, 95, 65}, kOccupied);  // the outer walls, two cells thick, and the floor inside
  fill({6, 6, 93, 63}, kFree);
  for (const Rect wall : {Rect{6, 28, 93, 29}, Rect{6, 40, 93, 41},  // the corridor's walls
                          Rect{35, 6, 36, 27}, Rect{65, 6, 66, 27}, Rect{50, 42, 51, 63}})  // between rooms
    fill(wall, kOccupied);
  for (const Rect door : {Rect{22, 28, 29, 29}, Rect{48, 28, 55, 29}, Rect{78, 28, 85, 29},  // 0.8 m doors
                          Rect{12, 40, 19, 41}, Rect{70, 40, 77, 41}})
    fill(door, kFree);
  for (const Rect desk : {Rect{10, 10, 24, 14}, Rect{10, 20, 16, 24}, Rect{42, 12, 58, 16}, Rect{72, 9, 76, 22},
                          Rect{84, 9, 88, 22}, Rect{20, 50, 40, 54}, Rect{60, 48, 64, 60}, Rect{76, 52, 88, 56},
                          Rect{60, 33, 61, 35}})  // and a pillar in the corridor
    fill(desk, kOccupied);
  std::string pgm = "P5\n" + std::to_string(kWidth) + " " + std::to_string(kHeight) + "\n255\n";
  pgm.append(pixels.begin(), pixels.end());
  write_file(dir / "office.pgm", pgm);
  write_file(dir / "office.yaml",
             "image: office.pgm\nresolution: 0.1\norigin: [-0.6, -0.6, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n"
             "free_thresh: 0.196\nmode: trinary\n");
  std::cout << "office.yaml, office.pgm: " << kWidth << "x" << kHeight << " cells at 0.1 m\n";
}

// A whole-number argument, or an Error naming it (std::stoi says only "stoi").
int whole_number(const std::string& text, const std::string& what) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    throw aco::Error(what + " must be a whole number from " + std::to_string(std::numeric_limits<int>::min()) + " to " +
                     std::to_string(std::numeric_limits<int>::max()) + ", not '" + text + "'");
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  if ((argc == 6 || argc == 7) && std::string(argv[1]) == "--voxel") {
    try {
      write_voxel_world(argv[2], argv[3], argv[4], argv[5], argc == 7 ? whole_number(argv[6], "--voxel: COUNT") : 10);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "aco_mapgen: " << e.what() << "\n";
      return 1;
    }
  }
  if ((argc == 5 || argc == 6) && std::string(argv[1]) == "--upsample") {
    try {
      std::filesystem::create_directories(argv[4]);
      write_upsampled(argv[2], whole_number(argv[3], "--upsample: FACTOR"), argv[4],
                      argc == 6 ? whole_number(argv[5], "--upsample: COUNT") : 10);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "aco_mapgen: " << e.what() << "\n";
      return 1;
    }
  }
  if (argc == 3 && std::string(argv[1]) == "--ros") {
    try {
      std::filesystem::create_directories(argv[2]);
      write_ros_office(argv[2]);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "aco_mapgen: " << e.what() << "\n";
      return 1;
    }
  }
  const bool large = argc > 1 && std::string(argv[1]) == "--large";
  const bool benchmark = (argc >= 3 && argc <= 5) && (std::string(argv[1]) == "--benchmark" || large);
  // Any other option (--help) is not a folder to fill with maps.
  const bool option = argc > 1 && !benchmark && argv[1][0] == '-';
  if (option || (!benchmark && argc != 2 && argc != 3)) {
    std::cerr
        << "usage: aco_mapgen OUTDIR [TERRAIN_OUTDIR]\n"
           "       aco_mapgen --benchmark OUTDIR [FIRST_SEED [FAMILY]]\n"
           "       aco_mapgen --large OUTDIR [FIRST_SEED [FAMILY]]\n"
           "       aco_mapgen --ros OUTDIR   (a ROS map_server office, office.yaml + office.pgm: data/maps/ros)\n"
           "       aco_mapgen --upsample MAP FACTOR OUTDIR [COUNT]   (a Moving AI map FACTOR times larger, COUNT\n"
           "                 scenarios, default 10: OUTDIR/<stem>-x<FACTOR>.map and .map.scen)\n"
           "       aco_mapgen --voxel KIND WxHxD SEED OUTDIR [COUNT]   (a voxel world, KIND city, forest or caves,\n"
           "                 as OUTDIR/<KIND><W>x<H>x<D>-s<SEED>.3dmap with COUNT scenarios, default 10, in\n"
           "                 its .3dmap.3dscen; 0: none)\n"
           "writes paper001, paper002, paper003_20 and paper003_15 (.map and .map.scen) into OUTDIR,\n"
           "and paper004 into TERRAIN_OUTDIR if given (data/terrain); with --benchmark, the generated\n"
           "random, room, maze, cave and hall validation maps with 20 scenarios each (data/maps/generated);\n"
           "with --large, the same families at 1024x1024 and 2048x2048 with 10 scenarios each; FAMILY: only\n"
           "those families' maps, comma-separated (random, room, maze, cave, hall; and the building families,\n"
           "written only when named: office, 8room, doors)\n";
    return 1;
  }
  try {
    if (benchmark) {
      std::filesystem::create_directories(argv[2]);
      write_benchmark(argv[2], argc >= 4 ? whole_number(argv[3], std::string(argv[1]) + ": FIRST_SEED") : 1, large,
                      argc == 5 ? argv[4] : "");
      return 0;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    for (const auto& make : {paper001, paper002, paper003_20, paper003_15}) write_map(make(), dir);
    if (argc == 3) {
      const std::filesystem::path terrain_dir = argv[2];
      std::filesystem::create_directories(terrain_dir);
      write_map(paper004(), terrain_dir);
    }
  } catch (const std::exception& e) {
    std::cerr << "aco_mapgen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
