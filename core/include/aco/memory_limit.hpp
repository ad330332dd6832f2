#pragma once
// Maps too large for the machine are refused before they are allocated: a hostile or mistaken
// header ("width 20000, height 20000") would otherwise fill the memory for minutes and then
// fail, or take the machine down with it. Loaders check the size a header claims; build_graph()
// checks again with the run's neighbourhood. Hosts set the limit with --max-memory.
#include <boost/config.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "aco/graph.hpp"
#include "aco/parameters.hpp"

namespace aco {

// Bytes that planning on a width x height map takes with this neighbourhood, every cell free
// (the worst case): the grid or terrain, the graph, the colony's per-edge fields (pheromone and
// heuristic) and the per-node search arrays. Measured, not derived from sizeof alone (see
// memory_limit.cpp). Exact in 64 bits for any int width and height. A terrain's graph stores
// positions and step lengths (aco/graph.hpp): more.
BOOST_SYMBOL_VISIBLE std::uint64_t planning_memory_estimate(std::int64_t width, std::int64_t height,
                                                            Neighbourhood neighbourhood, bool terrain = false);
// The same for a voxel world of `depth` layers (a 6-, 18- or 26-neighbourhood; a voxel world's
// graph stores less per edge, aco/graph.hpp).
BOOST_SYMBOL_VISIBLE std::uint64_t planning_memory_estimate(std::int64_t width, std::int64_t height, std::int64_t depth,
                                                            Neighbourhood neighbourhood);

// The limit in force: a MemoryLimit's while one lives, else default_memory_limit().
BOOST_SYMBOL_VISIBLE std::uint64_t memory_limit();
// 3/4 of the memory available when the process first asks (MemAvailable of /proc/meminfo, or
// the physical memory from sysconf where that file cannot be read; 4 GiB if neither can).
BOOST_SYMBOL_VISIBLE std::uint64_t default_memory_limit();

// Refuses (Error naming `name`, the estimate and the limit) a map whose planning would need
// more than the limit.
BOOST_SYMBOL_VISIBLE void check_planning_memory(std::int64_t width, std::int64_t height, Neighbourhood neighbourhood,
                                                const std::string& name, bool terrain = false);
BOOST_SYMBOL_VISIBLE void check_planning_memory(std::int64_t width, std::int64_t height, std::int64_t depth,
                                                Neighbourhood neighbourhood, const std::string& name);

// A voxel world's file, by its header's size: refuses (Error naming `name`, the size, the estimate
// and the limit) one whose voxels alone (16 bytes each: the world and the graph's per-voxel
// arrays) would need more than the limit. Its edges are checked when its graph is built
// (check_voxel_graph_memory()), which may hold a corridor's only.
BOOST_SYMBOL_VISIBLE void check_voxel_world_memory(std::int64_t width, std::int64_t height, std::int64_t depth,
                                                   const std::string& name);

// A voxel world's graph, once its edges are counted (before they are stored): refuses (Error) one
// whose voxels and edges would need more than the limit. The estimate of a whole world above
// counts every possible edge, so it is the check of a file's header; this one is the run's.
BOOST_SYMBOL_VISIBLE void check_voxel_graph_memory(std::int64_t voxels, std::int64_t edges, const std::string& name);

// The --max-memory option's help, the same in every host (parse_memory_size in
// aco/value_parsers.hpp reads its SIZE).
inline constexpr const char* kMaxMemoryHelp =
    "refuse maps whose planning would need more memory than SIZE (bytes, or with K, M, G, T: 512M, 4G); "
    "default: 3/4 of the memory available at start";
// "1.5 GiB", "512 MiB", "100 bytes".
BOOST_SYMBOL_VISIBLE std::string format_bytes(std::uint64_t bytes);

// The hosts' --max-memory: this limit while the object lives (none given: the default stays);
// a refusal names the option as `spelling` writes it (Python's "max_memory="). Process-wide; the
// previous limit comes back at destruction.
class BOOST_SYMBOL_VISIBLE MemoryLimit {
 public:
  explicit MemoryLimit(std::optional<std::uint64_t> bytes, KeySpelling spelling = "--");
  ~MemoryLimit();
  MemoryLimit(const MemoryLimit&) = delete;
  MemoryLimit& operator=(const MemoryLimit&) = delete;

 private:
  std::uint64_t previous_;  // 0: the default
  KeySpelling spelling_;
  const KeySpelling* previous_spelling_;
};

}  // namespace aco
