#pragma once
// The colony's per-edge fields (pheromone, heuristic) are its largest buffers: a hint to the
// kernel about their pages.
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace aco::colony_detail {

// Asks the kernel to back a large, untouched buffer with transparent huge pages. On a 512x512 map
// a per-edge field is 16 MB; faulting it in 4 kB pages costs tens of milliseconds per run, more
// than the ants' work on a short run. Asked only where the kernel gives huge pages to those who
// ask ("madvise" mode): in "always" mode it backs the buffer with them anyway where it has them
// free, and asking adds the wait while it compacts memory for more (up to 0.3 s for a 2048x2048
// map's field). A hint only: never a change of result.
inline bool huge_pages_on_request() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(mode, modes);
  return modes.find("[madvise]") != std::string::npos;
}

inline void prefer_huge_pages(void* data, std::size_t bytes) {
#ifdef __linux__
  static const bool on_request = huge_pages_on_request();
  constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
  const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (on_request && end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace aco::colony_detail
