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

// Peak resident memory of acoplan (/usr/bin/time -v; 10 ants, 3 iterations, 2 threads) on
// random Moving AI maps with 20 % obstacles grew by 130, 182 and 287 bytes per cell from
// 512x512 to 2048x2048 with the 4-, 8- and 16-neighbourhood. With the edges those maps have
// (about 2.6, 4.2 and 7.5 per cell) that is 48 bytes per cell plus 32 per edge: per edge the
// graph's target, cost and reverse (4 + 8 + 4) and the colony's pheromone and heuristic (8 + 8);
// per cell the grid, the graph's offsets, move mask and position (1 + 4 + 2 + 24) and the
// searches' per-node arrays. A terrain map adds 17 bytes per cell (height, slope, reason); on an
// obstacle-free map (all edges present) the 8-neighbourhood grew by 303 bytes per cell from
// 512x512 to 2048x2048 (peak 1.25 GB), under this estimate's 320. The estimate counts every edge
// present and rounds the per-cell part up to cover terrains.
constexpr std::uint64_t kBytesPerCell = 64;
constexpr std::uint64_t kBytesPerEdge = 32;
// A voxel world's edge stores its target and its move (4 + 1; aco/graph.hpp says why), and the
// colony's pheromone and float heuristic (8 + 4); rounded up.
constexpr std::uint64_t kBytesPerVoxelEdge = 20;
constexpr std::uint64_t kFallbackLimit = std::uint64_t(4) << 30;

std::atomic<std::uint64_t> g_limit{0};  // 0: the default
std::atomic<const KeySpelling*> g_spelling{nullptr};  // how the host names max-memory; none: "--max-memory"

std::string limit_origin() {
  const KeySpelling* spelling = g_spelling.load();
  const std::string option = spelling ? spelling->to_give("max-memory") : "--max-memory";
  return g_limit.load() ? "set by " + option : "the default, 3/4 of the available memory; change it with " + option;
}

}  // namespace

std::uint64_t planning_memory_estimate(std::int64_t width, std::int64_t height, Neighbourhood neighbourhood) {
  return planning_memory_estimate(width, height, 1, neighbourhood);
}

std::uint64_t planning_memory_estimate(std::int64_t width, std::int64_t height, std::int64_t depth,
                                       Neighbourhood neighbourhood) {
  if (width <= 0 || height <= 0 || depth <= 0) return 0;
  constexpr auto kMax = std::numeric_limits<std::uint64_t>::max();
  // int by int fits in 62 bits; times a depth or the bytes per cell it may not, so saturate.
  std::uint64_t cells = std::uint64_t(width) * std::uint64_t(height);
  if (cells > kMax / std::uint64_t(depth)) return kMax;
  cells *= std::uint64_t(depth);
  const std::uint64_t per_edge = volumetric(neighbourhood) ? kBytesPerVoxelEdge : kBytesPerEdge;
  const std::uint64_t per_cell = kBytesPerCell + per_edge * static_cast<std::uint64_t>(neighbourhood);
  if (cells > kMax / per_cell) return kMax;
  return cells * per_cell;
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
                           const std::string& name) {
  check_planning_memory(width, height, 1, neighbourhood, name);
}

void check_planning_memory(std::int64_t width, std::int64_t height, std::int64_t depth, Neighbourhood neighbourhood,
                           const std::string& name) {
  const std::uint64_t estimate = planning_memory_estimate(width, height, depth, neighbourhood);
  const std::uint64_t limit = memory_limit();
  if (estimate <= limit) return;
  const bool world = depth > 1 || volumetric(neighbourhood);
  const std::string size = std::to_string(width) + "x" + std::to_string(height) +
                           (world ? std::string("x") + std::to_string(depth) + " voxel world" : " map");
  throw Error(name + ": a " + size + " needs about " + format_bytes(estimate) + " to plan on (estimate with the " +
              std::to_string(static_cast<int>(neighbourhood)) + "-neighbourhood), more than the memory limit of " +
              format_bytes(limit) + " (" + limit_origin() + "): refused");
}

void check_voxel_graph_memory(std::int64_t voxels, std::int64_t edges, const std::string& name) {
  const std::uint64_t estimate = std::uint64_t(std::max<std::int64_t>(voxels, 0)) * kBytesPerCell +
                                 std::uint64_t(std::max<std::int64_t>(edges, 0)) * kBytesPerVoxelEdge;
  const std::uint64_t limit = memory_limit();
  if (estimate <= limit) return;
  throw Error(name + ": " + std::to_string(voxels) + " voxels with " + std::to_string(edges) + " edges need about " +
              format_bytes(estimate) + " to plan on, more than the memory limit of " + format_bytes(limit) + " (" +
              limit_origin() + "): refused");
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
