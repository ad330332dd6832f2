#include "aco/memory_limit.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <limits>
#include <sstream>

#include "aco/error.hpp"
#include "aco/machine.hpp"

namespace aco {
namespace {

// Peak resident memory of acoplan (GNU time; 10 ants, 3 iterations, 2 threads) on obstacle-free
// maps, where every edge is present, grew by 129, 212 and 333 bytes per cell from 512x512 to
// 2048x2048 with the 4-, 8- and 16-neighbourhood: 46 bytes per cell and 21 per edge. Per edge the
// graph's target and move (4 + 1; aco/graph.hpp says why) and the colony's pheromone and float
// heuristic (8 + 4); per cell the grid, the graph's offsets and move mask (1 + 4 + 4) and the
// searches' per-node arrays. Rounded up to 48 and 24. A terrain adds per cell its height, slope
// and reason (17 bytes) and the position the graph keeps (24), and per edge the step's length (8).
// The estimate counts every edge present.
constexpr std::uint64_t kBytesPerCell = 48;
constexpr std::uint64_t kBytesPerEdge = 24;
constexpr std::uint64_t kTerrainBytesPerCell = 48;
constexpr std::uint64_t kTerrainBytesPerEdge = 8;
// A voxel world: 4 + 1 bytes per edge in the graph, 8 + 4 in the colony, rounded up; per voxel
// the world and the graph's offsets and move mask (1 + 4 + 4), a corridor's mask and a search's
// marks, rounded up: the colony's per-node tables cost only the pages its walks write
// (aco/engine/zero_pages.hpp). Measured (GNU time, acoplan with the voxel preset): Warframe's
// Complex on one level, 7.8 million voxels and 198 million edges, peaked at 3.25 GiB (17 bytes
// per edge and 24 per voxel, process included); DB1 in a corridor, 49 million voxels, at 0.56 GiB.
constexpr std::uint64_t kBytesPerVoxel = 16;
constexpr std::uint64_t kBytesPerVoxelEdge = 20;
constexpr std::uint64_t kFallbackLimit = std::uint64_t(4) << 30;

std::atomic<std::uint64_t> g_limit{0};  // 0: the default
std::atomic<const KeySpelling*> g_spelling{nullptr};  // how the host names max-memory; none: "--max-memory"

std::string limit_origin() {
  const KeySpelling* spelling = g_spelling.load();
  const std::string option = spelling ? spelling->to_give("max-memory") : "--max-memory";
  return g_limit.load() ? "set by " + option : "the default, 3/4 of the available memory; change it with " + option;
}

std::uint64_t estimate(std::int64_t width, std::int64_t height, std::int64_t depth, Neighbourhood neighbourhood,
                       bool terrain) {
  if (width <= 0 || height <= 0 || depth <= 0) return 0;
  constexpr auto kMax = std::numeric_limits<std::uint64_t>::max();
  // int by int fits in 62 bits; times a depth or the bytes per cell it may not, so saturate.
  std::uint64_t cells = std::uint64_t(width) * std::uint64_t(height);
  if (cells > kMax / std::uint64_t(depth)) return kMax;
  cells *= std::uint64_t(depth);
  const bool world = volumetric(neighbourhood);
  const std::uint64_t per_edge = world ? kBytesPerVoxelEdge : kBytesPerEdge + (terrain ? kTerrainBytesPerEdge : 0);
  const std::uint64_t per_cell = (world ? kBytesPerVoxel : kBytesPerCell + (terrain ? kTerrainBytesPerCell : 0)) +
                                 per_edge * static_cast<std::uint64_t>(neighbourhood);
  if (cells > kMax / per_cell) return kMax;
  return cells * per_cell;
}

void refuse_above_limit(std::uint64_t estimate, std::int64_t width, std::int64_t height, std::int64_t depth,
                        Neighbourhood neighbourhood, const std::string& name) {
  const std::uint64_t limit = memory_limit();
  if (estimate <= limit) return;
  const bool world = depth > 1 || volumetric(neighbourhood);
  const std::string size = std::to_string(width) + "x" + std::to_string(height) +
                           (world ? std::string("x") + std::to_string(depth) + " voxel world" : " map");
  throw Error(name + ": a " + size + " needs about " + format_bytes(estimate) + " to plan on (estimate with the " +
              std::to_string(static_cast<int>(neighbourhood)) + "-neighbourhood), more than the memory limit of " +
              format_bytes(limit) + " (" + limit_origin() + "): refused");
}

}  // namespace

std::uint64_t planning_memory_estimate(std::int64_t width, std::int64_t height, Neighbourhood neighbourhood,
                                       bool terrain) {
  return estimate(width, height, 1, neighbourhood, terrain);
}

std::uint64_t planning_memory_estimate(std::int64_t width, std::int64_t height, std::int64_t depth,
                                       Neighbourhood neighbourhood) {
  return estimate(width, height, depth, neighbourhood, false);
}

std::uint64_t default_memory_limit() {
  static const std::uint64_t limit = [] {
    std::uint64_t memory = available_memory();
    if (memory == 0) memory = physical_memory();
    return memory == 0 ? kFallbackLimit : memory / 4 * 3;
  }();
  return limit;
}

std::uint64_t memory_limit() {
  const std::uint64_t set = g_limit.load();
  return set ? set : default_memory_limit();
}

void check_planning_memory(std::int64_t width, std::int64_t height, Neighbourhood neighbourhood,
                           const std::string& name, bool terrain) {
  refuse_above_limit(estimate(width, height, 1, neighbourhood, terrain), width, height, 1, neighbourhood, name);
}

void check_planning_memory(std::int64_t width, std::int64_t height, std::int64_t depth, Neighbourhood neighbourhood,
                           const std::string& name) {
  refuse_above_limit(estimate(width, height, depth, neighbourhood, false), width, height, depth, neighbourhood, name);
}

void check_voxel_world_memory(std::int64_t width, std::int64_t height, std::int64_t depth, const std::string& name) {
  const std::uint64_t voxels = std::uint64_t(std::max<std::int64_t>(width, 0)) *
                               std::uint64_t(std::max<std::int64_t>(height, 0)) *
                               std::uint64_t(std::max<std::int64_t>(depth, 0));  // each at most 100000: no overflow
  const std::uint64_t estimate = voxels * kBytesPerVoxel, limit = memory_limit();
  if (estimate <= limit) return;
  throw Error(name + ": a " + std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(depth) +
              " voxel world needs about " + format_bytes(estimate) + " to plan on (" + std::to_string(kBytesPerVoxel) +
              " bytes per voxel, before its edges), more than the memory limit of " + format_bytes(limit) + " (" +
              limit_origin() + "): refused");
}

void check_voxel_graph_memory(std::int64_t voxels, std::int64_t edges, const std::string& name) {
  const std::uint64_t estimate = std::uint64_t(std::max<std::int64_t>(voxels, 0)) * kBytesPerVoxel +
                                 std::uint64_t(std::max<std::int64_t>(edges, 0)) * kBytesPerVoxelEdge;
  const std::uint64_t limit = memory_limit();
  if (estimate <= limit) return;
  const std::string edge_count = edges > 0 ? " with " + std::to_string(edges) + " edges" : std::string();
  throw Error(name + ": " + std::to_string(voxels) + " voxels" + edge_count + " need about " + format_bytes(estimate) +
              " to plan on, more than the memory limit of " + format_bytes(limit) + " (" + limit_origin() +
              "): refused");
}

std::string format_bytes(std::uint64_t bytes) {
  static const char* const kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  double value = static_cast<double>(bytes);
  int unit = -1;
  while (value >= 1024 && unit < 5) value /= 1024, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, value < 10 ? "%.1f %s" : "%.0f %s", value, kUnits[unit]);
  return text;
}

MemoryLimit::MemoryLimit(std::optional<std::uint64_t> bytes, KeySpelling spelling)
    : previous_(g_limit.load()), spelling_(std::move(spelling)), previous_spelling_(g_spelling.load()) {
  if (bytes) g_limit.store(*bytes);
  g_spelling.store(&spelling_);
}

MemoryLimit::~MemoryLimit() {
  g_limit.store(previous_);
  g_spelling.store(previous_spelling_);
}

}  // namespace aco
