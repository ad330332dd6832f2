// Maps too large to plan on are refused before they are allocated (aco/memory_limit.hpp): every
// loader whose size comes from a header, build_graph() with the run's neighbourhood, and the
// hosts' --max-memory.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/memory_limit.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

// A header claiming 100000 x 100000 cells: 1e10 cells, some TiB to plan on, far above any
// machine's default limit. The loaders must refuse it from the header alone.
constexpr const char* kHugeMovingAi = "type octile\nheight 100000\nwidth 100000\nmap\n....\n";
constexpr const char* kHugeEsri = "ncols 100000\nnrows 100000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n";
constexpr const char* kHugePgm = "P5\n100000 100000\n255\nabc";

const std::string kHugeEstimate =
    aco::format_bytes(aco::planning_memory_estimate(100000, 100000, aco::Neighbourhood::four));

// One matcher class, not Contains(...) && Contains(...) returned from a function: Catch2's
// composed matchers hold references to their parts, which would not outlive the function.
struct RefusedWithEstimate : Catch::MatcherBase<std::string> {
  bool match(const std::string& message) const override {
    for (const std::string& part : {std::string("100000x100000"), kHugeEstimate, std::string("memory limit")})
      if (message.find(part) == std::string::npos) return false;
    return true;
  }
  std::string describe() const override {
    return "is a refusal of the 100000x100000 map with its estimate " + kHugeEstimate;
  }
};
RefusedWithEstimate refused_with_estimate() { return {}; }

std::string acosim() { return ACO_TEST_ACOSIM; }

// A run host refusing a small map: `args` plan on data's arena.map (or its experiment) with
// --max-memory `size`.
test::CommandResult run_host(const std::string& host, const std::string& size) {
  const auto map = test::data_dir() / "maps/movingai/arena.map";
  if (host == "acoplan")
    return test::acoplan({"--map", map.string(), "--start", "1,3", "--goal", "46,44", "--iterations", "2", "--ants",
                          "5", "--max-memory", size});
  if (host == "acobench") {
    const auto file = test::temp_file(
        "mem.yaml", "name: mem\nrepetitions: 1\nsettings: {ants: 5, iterations: 2}\nproblems:\n  - map: " +
                        map.string() + "\n    start: [1, 3]\n    goal: [46, 44]\n");
    return test::run({ACO_TEST_ACOBENCH, "run", file.string(), "--db", (file.parent_path() / "mem.db").string(),
                      "--max-memory", size});
  }
  const auto file = test::temp_file(
      "mem.yaml", "run: {map: " + map.string() + ", start: [1, 3], goal: [46, 44], ants: 5, iterations: 2}\n");
  return test::run({acosim(), file.string(), "--max-memory", size});
}

}  // namespace

TEST_CASE("the planning estimate grows with the cells and the neighbourhood, and saturates", "[memory]") {
  using aco::Neighbourhood;
  const auto e = [](std::int64_t w, std::int64_t h, Neighbourhood n) { return aco::planning_memory_estimate(w, h, n); };
  CHECK(e(100, 100, Neighbourhood::four) < e(100, 100, Neighbourhood::eight));
  CHECK(e(100, 100, Neighbourhood::eight) < e(100, 100, Neighbourhood::sixteen));
  CHECK(e(200, 100, Neighbourhood::eight) == 2 * e(100, 100, Neighbourhood::eight));
  // At least the graph's target and move and the colony's pheromone and heuristic (4 + 1 + 8 + 4 bytes).
  CHECK(e(100, 100, Neighbourhood::eight) >= 100 * 100 * 8 * 17);
  // A terrain's graph keeps positions and step lengths as well.
  CHECK(aco::planning_memory_estimate(100, 100, Neighbourhood::eight, true) > e(100, 100, Neighbourhood::eight));
  CHECK(e(0, 100, Neighbourhood::eight) == 0);
  CHECK(e(INT32_MAX, INT32_MAX, Neighbourhood::sixteen) == UINT64_MAX);
  CHECK(aco::memory_limit() == aco::default_memory_limit());
  CHECK(aco::default_memory_limit() > 0);
}

TEST_CASE("a header claiming a huge map is refused with the estimate, in every format", "[memory][bad-input]") {
  SECTION("Moving AI") {
    std::istringstream in(kHugeMovingAi);
    CHECK_THROWS_WITH(aco::read_movingai_map(in, "huge.map"), Contains("huge.map") && refused_with_estimate());
  }
  SECTION("ESRI ASCII") {
    std::istringstream in(kHugeEsri);
    CHECK_THROWS_WITH(aco::read_esri_ascii(in, "huge.asc", {}), Contains("huge.asc") && refused_with_estimate());
  }
  SECTION("PGM heights") {
    const auto file = test::temp_file("huge.pgm", kHugePgm);
    CHECK_THROWS_WITH(aco::load_height_pgm(file, {}), Contains("huge.pgm") && refused_with_estimate());
    CHECK_THROWS_WITH(aco::load_map(file), refused_with_estimate());
  }
  SECTION("ROS YAML + PGM") {
    const auto pgm = test::temp_file("huge.pgm", kHugePgm);
    const auto yaml = test::temp_file("huge.yaml", "image: " + pgm.string() + "\nresolution: 1\norigin: [0, 0, 0]\n");
    CHECK_THROWS_WITH(aco::load_ros_map(yaml), Contains("huge.pgm") && refused_with_estimate());
  }
  SECTION("the limit names its origin") {
    std::istringstream in(kHugeMovingAi);
    CHECK_THROWS_WITH(aco::read_movingai_map(in, "huge.map"), Contains("default") && Contains("--max-memory"));
    const aco::MemoryLimit limit(std::uint64_t(1) << 30);
    std::istringstream again(kHugeMovingAi);
    CHECK_THROWS_WITH(aco::read_movingai_map(again, "huge.map"),
                      Contains("1.0 GiB") && Contains("set by --max-memory"));
  }
}

TEST_CASE("a limit just below a map's estimate refuses it, the estimate itself accepts it", "[memory]") {
  const std::string text = "type octile\nheight 3\nwidth 4\nmap\n....\n.@..\n....\n";
  const auto load = [&] {
    std::istringstream in(text);
    return aco::read_movingai_map(in, "small.map");
  };
  const std::uint64_t four = aco::planning_memory_estimate(4, 3, aco::Neighbourhood::four);
  const std::uint64_t eight = aco::planning_memory_estimate(4, 3, aco::Neighbourhood::eight);
  {
    const aco::MemoryLimit limit(four - 1);
    CHECK_THROWS_WITH(load(), Contains("small.map") && Contains("4x3") && Contains(aco::format_bytes(four)));
  }
  {
    // The loader checks the leanest neighbourhood; build_graph() the run's.
    const aco::MemoryLimit limit(four);
    const aco::OccupancyGrid grid = load();
    CHECK(aco::build_graph(grid, {aco::Neighbourhood::four}).num_nodes() == 12);
    CHECK_THROWS_WITH(aco::build_graph(grid, {aco::Neighbourhood::eight}),
                      Contains("small.map") && Contains(aco::format_bytes(eight)) && Contains("8-neighbourhood"));
  }
  {
    const aco::MemoryLimit limit(eight);
    CHECK(aco::build_graph(load(), {aco::Neighbourhood::eight}).num_edges() > 0);
  }
  CHECK(aco::memory_limit() == aco::default_memory_limit());  // restored
}

TEST_CASE("matrix maps are checked row by row as they grow", "[memory][bad-input]") {
  const aco::MemoryLimit limit(aco::planning_memory_estimate(3, 2, aco::Neighbourhood::four));
  std::istringstream fits("0 0 0\n0 1 0\n");
  CHECK(aco::read_matrix_map(fits, "m.txt").height() == 2);
  std::istringstream grows("0 0 0\n0 1 0\n0 0 0\n");
  CHECK_THROWS_WITH(aco::read_matrix_map(grows, "m.txt"),
                    Contains("m.txt") && Contains("3x3") && Contains("memory limit"));
}

TEST_CASE("acoplan, acobench and acosim: --max-memory below a small map's estimate refuses it, above accepts it",
          "[memory][acoplan][acobench][acosim][bad-input]") {
  // arena.map is 49x49: about 0.5 MiB to plan on with the 8-neighbourhood.
  for (const std::string host : {"acoplan", "acobench", "acosim"}) {
    INFO(host);
    const auto refused = run_host(host, "64K");
    CHECK(refused.exit_code == 1);
    CHECK_THAT(refused.err, Contains("arena.map") && Contains("49x49") && Contains("memory limit of 64 KiB"));
    const auto accepted = run_host(host, "64M");
    CHECK(accepted.exit_code != 1);
    CHECK_THAT(accepted.err, !Contains("memory limit"));
    for (const std::string bad : {"lots", "0", "-5M", "2.5G", "4Q"}) {
      const auto malformed = run_host(host, bad);
      CHECK(malformed.exit_code == 1);
      CHECK_THAT(malformed.err, Contains("--max-memory: '" + bad + "'"));
    }
  }
  const auto help = test::acoplan({"--help"});
  CHECK_THAT(help.out, Contains("--max-memory SIZE"));
  CHECK_THAT(test::run({acosim(), "--help"}).out, Contains("--max-memory"));
  CHECK_THAT(test::run({ACO_TEST_ACOBENCH, "--help"}).out, Contains("--max-memory"));
}

TEST_CASE("acoplan refuses a map file whose header claims a huge size", "[memory][acoplan][bad-input]") {
  const auto map = test::temp_file("huge.map", kHugeMovingAi);
  const auto r = test::acoplan({"--map", map.string(), "--start", "0,0", "--goal", "1,1"});
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, refused_with_estimate());
}
