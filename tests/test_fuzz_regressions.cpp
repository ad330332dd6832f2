// The inputs the fuzzers found (tests/fuzz/regressions/<target>/) and the seed corpus
// (tests/fuzz/corpus/<target>/), replayed through the fuzz targets: each must load or be refused
// with an aco::Error. A crash or a sanitizer report fails the suite, as any other exception does.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "aco/memory_limit.hpp"
#include "targets.hpp"

namespace fs = std::filesystem;

namespace {

std::vector<fuzz::Target> all_targets() {
  std::vector<fuzz::Target> all;
  for (auto list : {fuzz::map_targets(), fuzz::config_targets()}) all.insert(all.end(), list.begin(), list.end());
  return all;
}

}  // namespace

TEST_CASE("fuzz regression inputs and seeds load or are refused with an aco::Error", "[fuzz][bad-input]") {
  const aco::MemoryLimit limit(fuzz::kMemoryLimit);  // as in the harnesses
  const std::vector<fuzz::Target> targets = all_targets();
  int replayed = 0;
  for (const char* kind : {"regressions", "corpus"}) {
    const fs::path root = fs::path(ACO_TEST_FUZZ_DIR) / kind;
    for (const auto& folder : fs::directory_iterator(root)) {
      // A misspelt folder would silently skip its inputs.
      INFO(folder.path().string());
      REQUIRE_NOTHROW(fuzz::find_target(folder.path().filename().string(), targets));
    }
    for (const auto& target : targets) {
      if (!fs::exists(root / target.name)) continue;
      for (const auto& input : fs::directory_iterator(root / target.name)) {
        INFO(input.path().string());
        std::ifstream in(input.path(), std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        CHECK_NOTHROW(target.run(bytes));
        ++replayed;
      }
    }
  }
  CHECK(replayed > 0);
}
