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
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <numeric>
#include <optional>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/map_io.hpp"
#include "aco/rng.hpp"
#include "aco/voxel.hpp"
#include "families.hpp"
#include "shapes.hpp"

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

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw aco::Error(file.string() + ": cannot open for writing");
  out << text;
  if (!out.flush()) throw aco::Error(file.string() + ": write failed");
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
  std::vector<double> d(graph.num_nodes(), std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, aco::NodeId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  d[from] = 0.0;
  open.push({0.0, from});
  while (!open.empty()) {
    const auto [dist, n] = open.top();
    open.pop();
    if (dist > d[n]) continue;
    for (aco::EdgeId e = graph.edges_begin(n); e != graph.edges_end(n); ++e) {
      const aco::NodeId m = graph.targets[e];
      if (dist + graph.cost(e) < d[m]) {
        d[m] = dist + graph.cost(e);
        open.push({d[m], m});
      }
    }
  }
  return d;
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

// ---------------------------------------------------------------------------------------------
// Voxel worlds (--voxel): Moving AI .3dmap files of a city, a forest or caves, each with a
// .3dmap.3dscen whose optimal lengths are exact for the Moving AI voxel benchmarks' moves
// (data/maps/voxel/README.md): 26 neighbours, costs 1, sqrt 2, sqrt 3, no corner cutting.
// z is the layer from the ground up.

struct VoxelSize {
  int width = 0, height = 0, depth = 0;
};

VoxelSize parse_voxel_size(const std::string& text) {
  VoxelSize s;
  char x1 = 0, x2 = 0;
  std::istringstream in(text);
  std::string rest;
  if (!(in >> s.width >> x1 >> s.height >> x2 >> s.depth) || x1 != 'x' || x2 != 'x' || (in >> rest) || s.width < 8 ||
      s.height < 8 || s.depth < 8 || s.width > 1024 || s.height > 1024 || s.depth > 1024)
    throw aco::Error("--voxel: SIZE must be WxHxD with each side 8 to 1024 voxels (e.g. 64x64x32), not '" + text + "'");
  // The generators keep a few bytes per voxel and every scenario a full distance array.
  if (std::int64_t{s.width} * s.height * s.depth > (std::int64_t{1} << 24))
    throw aco::Error("--voxel: SIZE " + text + " has more than 16777216 voxels (256x256x256)");
  return s;
}

void fill_box(aco::VoxelMap& m, int x0, int y0, int z0, int x1, int y1, int z1) {
  for (int z = std::max(z0, 0); z <= std::min(z1, m.depth() - 1); ++z)
    for (int y = std::max(y0, 0); y <= std::min(y1, m.height() - 1); ++y)
      for (int x = std::max(x0, 0); x <= std::min(x1, m.width() - 1); ++x) m.set_blocked({x, y, z}, true);
}

int random_between(aco::Rng& rng, int low, int high) {  // both ends included
  return low + static_cast<int>(rng.below(static_cast<std::uint64_t>(high - low + 1)));
}

// A city: a street grid of blocks 10 to 16 voxels a side between streets 3 or 4 wide, each block
// split into one to four lots; a lot is a building (a box from the ground, set back one voxel from
// its neighbours, of a random height up to 3/4 of the world's) or, one time in six, an empty
// square. The top quarter stays free: the streets and the sky join everything.
aco::VoxelMap city_world(VoxelSize s, aco::Rng& rng, const std::string& name) {
  aco::VoxelMap m(s.width, s.height, s.depth, name);
  const int max_height = std::max(1, s.depth * 3 / 4);
  auto blocks = [&](int extent) {  // [begin, end) of the blocks along one axis
    std::vector<std::pair<int, int>> spans;
    for (int at = random_between(rng, 1, 3); at < extent;) {
      const int size = random_between(rng, 10, 16);
      spans.push_back({at, std::min(at + size, extent)});
      at += size + random_between(rng, 3, 4);
    }
    return spans;
  };
  const auto xs = blocks(s.width);
  const auto ys = blocks(s.height);
  for (const auto& [bx0, bx1] : xs)
    for (const auto& [by0, by1] : ys) {
      // One cut across x and one across y, each with probability 1/2: one to four lots.
      const int cx = bx1 - bx0 >= 8 && rng.below(2) ? random_between(rng, bx0 + 4, bx1 - 4) : bx1;
      const int cy = by1 - by0 >= 8 && rng.below(2) ? random_between(rng, by0 + 4, by1 - 4) : by1;
      for (const auto& [lx0, lx1] : {std::pair{bx0, cx}, std::pair{cx, bx1}})
        for (const auto& [ly0, ly1] : {std::pair{by0, cy}, std::pair{cy, by1}}) {
          if (lx1 - lx0 < 2 || ly1 - ly0 < 2) continue;
          if (rng.below(6) == 0) continue;  // a square
          const int top = random_between(rng, std::max(1, max_height / 4), max_height) - 1;
          fill_box(m, lx0, ly0, 0, lx1 - 2, ly1 - 2, top);
        }
    }
  return m;
}

// A forest: trees on a jittered grid 6 to 10 voxels apart, each a trunk one or two voxels wide and
// a crown, a ball of radius 2 to 4 at its top; heights up to 4/5 of the world's.
aco::VoxelMap forest_world(VoxelSize s, aco::Rng& rng, const std::string& name) {
  aco::VoxelMap m(s.width, s.height, s.depth, name);
  const int spacing = random_between(rng, 6, 10);
  for (int gy = 0; gy < s.height; gy += spacing)
    for (int gx = 0; gx < s.width; gx += spacing) {
      if (rng.below(5) == 0) continue;  // a clearing
      const int x = gx + random_between(rng, 0, spacing - 1), y = gy + random_between(rng, 0, spacing - 1);
      const int trunk = random_between(rng, 1, 2);
      const int height = random_between(rng, std::max(3, s.depth / 4), std::max(3, s.depth * 4 / 5));
      const int radius = random_between(rng, 2, 4);
      fill_box(m, x, y, 0, x + trunk - 1, y + trunk - 1, height - 1);
      const double cx = x + (trunk - 1) / 2.0, cy = y + (trunk - 1) / 2.0, cz = height - 1;
      for (int z = static_cast<int>(cz) - radius; z <= static_cast<int>(cz) + radius; ++z)
        for (int yy = y - radius; yy <= y + trunk - 1 + radius; ++yy)
          for (int xx = x - radius; xx <= x + trunk - 1 + radius; ++xx) {
            const double dx = xx - cx, dy = yy - cy, dz = z - cz;
            if (dx * dx + dy * dy + dz * dz <= radius * radius + 0.5 && m.contains({xx, yy, z}))
              m.set_blocked({xx, yy, z}, true);
          }
    }
  return m;
}

// Free voxels of `m` joined by face steps, which is how far the benchmarks' moves reach: a
// diagonal step needs its whole box free, so a face path runs beside every one. Each part as
// a list of voxel indices (x fastest, then y, then z), largest first, ties by first voxel.
std::vector<std::vector<std::int64_t>> voxel_parts(const aco::VoxelMap& m) {
  const std::int64_t w = m.width(), h = m.height(), d = m.depth();
  std::vector<char> seen(static_cast<std::size_t>(w * h * d), 0);
  std::vector<std::vector<std::int64_t>> parts;
  for (std::int64_t first = 0; first < w * h * d; ++first) {
    const aco::Cell c{int(first % w), int(first / w % h), int(first / (w * h))};
    if (seen[first] || m.blocked(c)) continue;
    std::vector<std::int64_t> part{first};
    seen[first] = 1;
    for (std::size_t i = 0; i < part.size(); ++i) {
      const std::int64_t v = part[i];
      const int x = int(v % w), y = int(v / w % h), z = int(v / (w * h));
      const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      for (const auto& s : step) {
        const aco::Cell n{x + s[0], y + s[1], z + s[2]};
        if (!m.contains(n) || m.blocked(n)) continue;
        const std::int64_t u = (std::int64_t{n.z} * h + n.y) * w + n.x;
        if (!seen[u]) seen[u] = 1, part.push_back(u);
      }
    }
    parts.push_back(std::move(part));
  }
  std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return parts;
}

// Caves: a 3D cellular automaton. Voxels blocked with probability 0.5 (the outer shell always),
// then five rounds of "blocked iff at least 14 of the 26 neighbours are, free iff at most 12,
// else unchanged" (outside counts as blocked); every cave but the largest is filled, so one
// connected system remains.
aco::VoxelMap cave_world(VoxelSize s, aco::Rng& rng, const std::string& name) {
  const int w = s.width, h = s.height, d = s.depth;
  auto at = [&](int x, int y, int z) { return (static_cast<std::size_t>(z) * h + y) * w + x; };
  std::vector<char> rock(static_cast<std::size_t>(w) * h * d);
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool shell = x == 0 || y == 0 || z == 0 || x == w - 1 || y == h - 1 || z == d - 1;
        rock[at(x, y, z)] = shell || rng.uniform() < 0.5;
      }
  for (int round = 0; round < 5; ++round) {
    std::vector<char> next = rock;
    for (int z = 0; z < d; ++z)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          int walls = 0;
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                if (!dx && !dy && !dz) continue;
                const int nx = x + dx, ny = y + dy, nz = z + dz;
                walls += nx < 0 || ny < 0 || nz < 0 || nx >= w || ny >= h || nz >= d || rock[at(nx, ny, nz)];
              }
          if (walls >= 14)
            next[at(x, y, z)] = 1;
          else if (walls <= 12)
            next[at(x, y, z)] = 0;
        }
    rock.swap(next);
  }
  aco::VoxelMap m(w, h, d, name);
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) m.set_blocked({x, y, z}, rock[at(x, y, z)] != 0);
  const auto parts = voxel_parts(m);
  for (std::size_t p = 1; p < parts.size(); ++p)
    for (const std::int64_t v : parts[p])
      m.set_blocked({int(v % w), int(v / w % h), int(v / (std::int64_t{w} * h))}, true);
  return m;
}

// The 3D octile distance, the heuristic the .3dscen ratio column divides by.
double voxel_octile(aco::Cell a, aco::Cell b) {
  int d[3] = {std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)};
  std::sort(d, d + 3);
  return std::sqrt(3.0) * d[0] + std::sqrt(2.0) * (d[1] - d[0]) + (d[2] - d[1]);
}

// `count` problems in the largest connected part, start and goal distinct and drawn uniformly
// from it, in Moving AI's .3dscen layout.
std::string voxel_scenarios(const aco::VoxelMap& m, const std::string& map_file, int count, aco::Rng& rng) {
  const auto parts = voxel_parts(m);
  std::string text = "version 1\n" + map_file + "\n";
  if (parts.empty() || parts.front().size() < 2) throw aco::Error(m.name() + ": fewer than two connected free voxels");
  const auto& part = parts.front();
  const std::int64_t w = m.width(), h = m.height();
  auto cell = [&](std::int64_t v) { return aco::Cell{int(v % w), int(v / w % h), int(v / (w * h))}; };
  // The benchmarks' moves: 26 neighbours, every voxel of a move's box free (no corner cutting).
  const aco::Graph graph = aco::build_graph(m, {aco::Neighbourhood::twenty_six, false});
  for (int k = 0; k < count; ++k) {
    // As Moving AI's generator does, problems a straight line solves are redrawn: up to 8 times,
    // so that an open world still gets its scenarios.
    aco::Cell start, goal;
    std::optional<double> length;
    for (int draw = 0; draw < 8; ++draw) {
      start = cell(part[rng.below(part.size())]);
      goal = start;
      while (goal == start) goal = cell(part[rng.below(part.size())]);
      const auto found = aco::astar(graph, graph.node(start), graph.node(goal));
      length = found ? std::optional<double>(found->length) : std::nullopt;
      if (!length) throw aco::Error(m.name() + ": a voxel of the largest part is unreachable (a bug)");
      if (*length > voxel_octile(start, goal) + 1e-9) break;
    }
    char line[160];
    std::snprintf(line, sizeof line, "%d %d %d %d %d %d %.8f %.3f\n", start.x, start.y, start.z, goal.x, goal.y, goal.z,
                  *length, *length / voxel_octile(start, goal));
    text += line;
  }
  return text;
}

// --voxel KIND SIZE SEED OUTDIR [COUNT]: OUTDIR/<kind><W>x<H>x<D>-s<SEED>.3dmap and, with COUNT
// above 0, its .3dmap.3dscen.
void write_voxel_world(const std::string& kind, const std::string& size_text, const std::string& seed_text,
                       const std::filesystem::path& dir, int count) {
  const VoxelSize s = parse_voxel_size(size_text);
  std::uint64_t seed = 0;
  if (seed_text.empty() || seed_text.find_first_not_of("0123456789") != std::string::npos || seed_text.size() > 18)
    throw aco::Error("--voxel: SEED must be a whole number, not '" + seed_text + "'");
  seed = std::stoull(seed_text);
  if (count < 0 || count > 100000) throw aco::Error("--voxel: COUNT must be 0 to 100000, not " + std::to_string(count));
  const std::string name = kind + std::to_string(s.width) + "x" + std::to_string(s.height) + "x" +
                           std::to_string(s.depth) + "-s" + seed_text;
  const std::vector<std::string> kinds = {"city", "forest", "caves"};
  const auto known = std::find(kinds.begin(), kinds.end(), kind);
  if (known == kinds.end()) throw aco::Error("--voxel: KIND must be city, forest or caves, not '" + kind + "'");
  // The kind joins the seed so that a city and a forest of one seed draw different numbers.
  aco::Rng rng(aco::splitmix64(seed) + static_cast<std::uint64_t>(known - kinds.begin()));
  const std::string file = name + ".3dmap";
  std::optional<aco::VoxelMap> world;
  if (kind == "city")
    world.emplace(city_world(s, rng, file));
  else if (kind == "forest")
    world.emplace(forest_world(s, rng, file));
  else
    world.emplace(cave_world(s, rng, file));
  std::ostringstream map_text;
  aco::write_movingai_voxels(*world, map_text);
  std::filesystem::create_directories(dir);
  write_file(dir / file, map_text.str());
  if (count > 0) write_file(dir / (file + ".3dscen"), voxel_scenarios(*world, file, count, rng));
  std::cout << file << ": " << s.width << "x" << s.height << "x" << s.depth << ", " << world->blocked_count()
            << " blocked, " << count << " scenarios\n";
}

}  // namespace

int main(int argc, char** argv) {
  if ((argc == 6 || argc == 7) && std::string(argv[1]) == "--voxel") {
    try {
      write_voxel_world(argv[2], argv[3], argv[4], argv[5], argc == 7 ? std::stoi(argv[6]) : 10);
      return 0;
    } catch (const std::exception& e) {
      std::cerr << "aco_mapgen: " << e.what() << "\n";
      return 1;
    }
  }
  if ((argc == 5 || argc == 6) && std::string(argv[1]) == "--upsample") {
    try {
      std::filesystem::create_directories(argv[4]);
      write_upsampled(argv[2], std::stoi(argv[3]), argv[4], argc == 6 ? std::stoi(argv[5]) : 10);
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
      write_benchmark(argv[2], argc >= 4 ? std::stoi(argv[3]) : 1, large, argc == 5 ? argv[4] : "");
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
