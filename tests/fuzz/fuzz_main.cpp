// One libFuzzer harness, built once per target: ACO_FUZZ_TARGET is its name, ACO_FUZZ_LIST the
// function listing it (map_targets or config_targets).
#include <cstddef>
#include <cstdint>

#include "aco/memory_limit.hpp"
#include "targets.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  static const aco::MemoryLimit limit(fuzz::kMemoryLimit);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fuzz::Target& target = fuzz::find_target(ACO_FUZZ_TARGET, fuzz::ACO_FUZZ_LIST());
  target.run(std::string_view(reinterpret_cast<const char*>(data), size));
  return 0;
}
