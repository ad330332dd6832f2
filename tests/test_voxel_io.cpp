// Voxel worlds on disk: Moving AI .3dmap and .3dscen (data/maps/voxel/README.md), the bundled
// Warframe sample, and aco_mapgen --voxel.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/engine/map_formats.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/memory_limit.hpp"
#include "aco/voxel.hpp"
#include "support.hpp"

namespace fs = std::filesystem;
using Catch::Contains;

namespace {

aco::VoxelMap voxels(const std::string& text, const std::string& name = "inline.3dmap") {
  std::istringstream in(text);
  return aco::read_movingai_voxels(in, name);
}

std::vector<aco::Scenario> voxel_scenarios(const std::string& text, const std::string& name = "inline.3dscen") {
  std::istringstream in(text);
  return aco::read_voxel_scenarios(in, name);
}

std::string written(const aco::VoxelMap& map) {
  std::ostringstream out;
  aco::write_movingai_voxels(map, out);
  return out.str();
}

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path voxel_dir() { return test::data_dir() / "maps" / "voxel" / "warframe"; }

// Whether `b` can be reached from `a` by face steps through free voxels.
bool face_connected(const aco::VoxelMap& m, aco::Cell a, aco::Cell b) {
  const std::int64_t w = m.width(), h = m.height();
  std::vector<char> seen(static_cast<std::size_t>(m.voxels()), 0);
  auto id = [&](aco::Cell c) { return (std::int64_t{c.z} * h + c.y) * w + c.x; };
  std::deque<aco::Cell> queue{a};
  seen[id(a)] = 1;
  while (!queue.empty()) {
    const aco::Cell c = queue.front();
    queue.pop_front();
    if (c == b) return true;
    for (const aco::Cell n : {aco::Cell{c.x + 1, c.y, c.z}, aco::Cell{c.x - 1, c.y, c.z}, aco::Cell{c.x, c.y + 1, c.z},
                              aco::Cell{c.x, c.y - 1, c.z}, aco::Cell{c.x, c.y, c.z + 1}, aco::Cell{c.x, c.y, c.z - 1}})
      if (m.passable(n) && !seen[id(n)]) seen[id(n)] = 1, queue.push_back(n);
  }
  return false;
}

double octile3(aco::Cell a, aco::Cell b) {
  int d[3] = {std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)};
  std::sort(d, d + 3);
  return std::sqrt(3.0) * d[0] + std::sqrt(2.0) * (d[1] - d[0]) + (d[2] - d[1]);
}

}  // namespace

TEST_CASE(".3dmap: the header gives the size, every other line a blocked voxel", "[voxel_io]") {
  const auto m = voxels("voxel 4 3 2\n0 0 0\n3 2 1\n1 2 0\n");
  CHECK(m.width() == 4);
  CHECK(m.height() == 3);
  CHECK(m.depth() == 2);
  CHECK(m.volumetric());
  CHECK(m.name() == "inline.3dmap");
  CHECK(m.blocked_count() == 3);
  CHECK(m.blocked({0, 0, 0}));
  CHECK(m.blocked({3, 2, 1}));
  CHECK(m.blocked({1, 2, 0}));
  CHECK_FALSE(m.blocked({1, 2, 1}));
  CHECK(m.passable({2, 1, 1}));
}

TEST_CASE(".3dmap: CRLF, tabs, blank lines, repeated voxels and no voxels at all are accepted", "[voxel_io]") {
  const auto m = voxels("voxel\t3 3 3\r\n1 1 1\r\n\r\n  1\t1 1  \r\n2 0 2\r\n\n");
  CHECK(m.blocked_count() == 2);
  CHECK(m.blocked({1, 1, 1}));
  CHECK(m.blocked({2, 0, 2}));
  CHECK(voxels("voxel 2 2 2\n").blocked_count() == 0);
  CHECK(voxels("voxel 2 2 2").blocked_count() == 0);
}

TEST_CASE(".3dmap: writing and reading again gives the same world and the same bytes", "[voxel_io]") {
  aco::VoxelMap m(5, 4, 3, "round.3dmap");
  for (const aco::Cell c :
       {aco::Cell{0, 0, 0}, aco::Cell{4, 3, 2}, aco::Cell{2, 1, 0}, aco::Cell{2, 1, 2}, aco::Cell{0, 3, 1}})
    m.set_blocked(c, true);
  const std::string text = written(m);
  // HOG2's order: x, then y, then z.
  CHECK(text == "voxel 5 4 3\n0 0 0\n0 3 1\n2 1 0\n2 1 2\n4 3 2\n");
  const auto back = voxels(text, "round.3dmap");
  REQUIRE(back.width() == 5);
  REQUIRE(back.height() == 4);
  REQUIRE(back.depth() == 3);
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 5; ++x) CHECK(back.blocked({x, y, z}) == m.blocked({x, y, z}));
  CHECK(written(back) == text);
  CHECK(written(aco::VoxelMap(2, 2, 2, "empty")) == "voxel 2 2 2\n");
}

TEST_CASE("Malformed .3dmap files are rejected naming the file, the line and the fault", "[voxel_io][bad-input]") {
  SECTION("empty file") {
    CHECK_THROWS_AS(voxels("", "bad.3dmap"), aco::Error);
    CHECK_THROWS_WITH(voxels("", "bad.3dmap"), Contains("bad.3dmap:1:") && Contains("empty voxel file"));
  }
  SECTION("bad header keyword or field count") {
    CHECK_THROWS_WITH(voxels("voxels 2 2 2\n", "bad.3dmap"),
                      Contains("bad.3dmap:1:") && Contains("expected a first line 'voxel WIDTH HEIGHT DEPTH'") &&
                          Contains("'voxels 2 2 2'"));
    CHECK_THROWS_WITH(voxels("voxel 2 2\n", "bad.3dmap"), Contains("bad.3dmap:1:") && Contains("'voxel 2 2'"));
    CHECK_THROWS_WITH(voxels("voxel 2 2 2 2\n", "bad.3dmap"), Contains("bad.3dmap:1:"));
    CHECK_THROWS_WITH(voxels("type octile\nheight 2\n", "bad.3dmap"), Contains("bad.3dmap:1:"));
  }
  SECTION("non-numeric, zero, negative and too large sizes") {
    CHECK_THROWS_WITH(voxels("voxel 2 two 2\n", "bad.3dmap"),
                      Contains("bad.3dmap:1:") && Contains("height 'two'") && Contains("not a whole number"));
    CHECK_THROWS_WITH(voxels("voxel 0 2 2\n", "bad.3dmap"), Contains("bad.3dmap:1:") && Contains("width '0'"));
    CHECK_THROWS_WITH(voxels("voxel 2 2 -3\n", "bad.3dmap"), Contains("bad.3dmap:1:") && Contains("depth '-3'"));
    CHECK_THROWS_WITH(voxels("voxel 2 2 100001\n", "bad.3dmap"), Contains("depth '100001'"));
    CHECK_THROWS_WITH(voxels("voxel 2.5 2 2\n", "bad.3dmap"), Contains("width '2.5'"));
  }
  SECTION("a size whose planning would not fit the memory is refused before it is allocated") {
    CHECK_THROWS_WITH(voxels("voxel 100000 100000 100000\n", "huge.3dmap"),
                      Contains("huge.3dmap") && Contains("100000x100000x100000 voxel world") &&
                          Contains("more than the memory limit") && Contains("refused"));
    const aco::MemoryLimit limit(1 << 20);
    CHECK_THROWS_WITH(voxels("voxel 64 64 64\n", "big.3dmap"), Contains("big.3dmap") && Contains("1.0 MiB"));
    CHECK(voxels("voxel 8 8 8\n").voxels() == 512);
  }
  SECTION("a voxel outside the world") {
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n0 0 0\n4 0 0\n", "bad.3dmap"),
                      Contains("bad.3dmap:3:") && Contains("voxel (4,0,0) is outside the 4x3x2 world") &&
                          Contains("x must be 0 to 3"));
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n0 3 0\n", "bad.3dmap"),
                      Contains("bad.3dmap:2:") && Contains("y must be 0 to 2"));
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n0 0 2\n", "bad.3dmap"), Contains("z must be 0 to 1"));
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n0 -1 0\n", "bad.3dmap"), Contains("bad.3dmap:2:") && Contains("(0,-1,0)"));
  }
  SECTION("a voxel line of the wrong length or with a non-number") {
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n\n1 2\n", "bad.3dmap"),
                      Contains("bad.3dmap:3:") && Contains("expected a blocked voxel 'x y z', found 2 fields"));
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n1 2 1 0\n", "bad.3dmap"),
                      Contains("bad.3dmap:2:") && Contains("more than 3"));
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n1 y 1\n", "bad.3dmap"),
                      Contains("bad.3dmap:2:") && Contains("y 'y' is not a whole number"));
    CHECK_THROWS_WITH(voxels("voxel 4 3 2\n1 1 1.0\n", "bad.3dmap"), Contains("z '1.0'"));
  }
  SECTION("binary data") {
    CHECK_THROWS_AS(voxels(std::string("voxel 4 3 2\n\x01\x02\x00 1 1\n", 20), "bad.3dmap"), aco::Error);
  }
  SECTION("a missing file") {
    CHECK_THROWS_WITH(aco::load_movingai_voxels("/nonexistent/none.3dmap"), Contains("none.3dmap"));
  }
}

TEST_CASE(".3dscen: version line, map name, then start, goal, length and ratio", "[voxel_io]") {
  const auto s = voxel_scenarios("version 1\nSimple.3dmap\n56 76 52 48 85 45 15.31710829 1.054\n\n1 2 3 4 5 6 7.5\n");
  REQUIRE(s.size() == 2);
  CHECK(s[0].map_path == "Simple.3dmap");
  CHECK(s[0].volumetric);
  CHECK(s[0].start == aco::Cell{56, 76, 52});
  CHECK(s[0].goal == aco::Cell{48, 85, 45});
  CHECK(s[0].optimal_length == Approx(15.31710829));
  CHECK(s[0].ratio == Approx(1.054));
  CHECK(s[0].bucket == 0);
  CHECK(s[0].width == 0);
  CHECK(s[1].start == aco::Cell{1, 2, 3});
  CHECK(s[1].goal == aco::Cell{4, 5, 6});
  CHECK(s[1].ratio == 0.0);  // an older file's line without it
  CHECK(voxel_scenarios("version 1\r\nx.3dmap\r\n1 1 1 2 2 2 1.7320508 1\r\n").size() == 1);
  CHECK(voxel_scenarios("version 1\nx.3dmap\n").empty());
}

TEST_CASE("Malformed .3dscen files are rejected naming the file, the line and the fault", "[voxel_io][bad-input]") {
  const std::string head = "version 1\nSimple.3dmap\n";
  CHECK_THROWS_WITH(voxel_scenarios("", "bad.3dscen"), Contains("bad.3dscen") && Contains("empty scenario file"));
  CHECK_THROWS_WITH(voxel_scenarios("version 2\nx.3dmap\n", "bad.3dscen"),
                    Contains("bad.3dscen:1:") && Contains("expected 'version 1', found 'version 2'"));
  CHECK_THROWS_WITH(voxel_scenarios("version 1\n", "bad.3dscen"),
                    Contains("bad.3dscen:2:") && Contains("expected the map's file name on line 2"));
  CHECK_THROWS_WITH(voxel_scenarios("version 1\nSimple 3dmap\n", "bad.3dscen"),
                    Contains("bad.3dscen:2:") && Contains("map's file name"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 3 4 5 6 7 1\n1 2 3 4 5 6\n", "bad.3dscen"),
                    Contains("bad.3dscen:4:") && Contains("expected 8 fields") && Contains("or 7 without the ratio") &&
                        Contains("found 6"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 3 4 5 6 7 1 9\n", "bad.3dscen"), Contains("more than 8"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 z 4 5 6 7 1\n", "bad.3dscen"),
                    Contains("bad.3dscen:3:") && Contains("start z 'z'"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 3 4 -5 6 7 1\n", "bad.3dscen"),
                    Contains("bad.3dscen:3:") && Contains("goal y '-5'"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 3 4 5 6 long 1\n", "bad.3dscen"),
                    Contains("bad.3dscen:3:") && Contains("optimal length 'long'"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 3 4 5 6 -7 1\n", "bad.3dscen"), Contains("optimal length '-7'"));
  CHECK_THROWS_WITH(voxel_scenarios(head + "1 2 3 4 5 6 7 nan\n", "bad.3dscen"), Contains("ratio 'nan'"));
  // The 2D reader keeps its own format: a .3dscen is not a .scen.
  std::istringstream in(head + "1 2 3 4 5 6 7 1\n");
  CHECK_THROWS_WITH(aco::read_scenarios(in, "x.3dscen"), Contains("expected 9 fields"));
}

TEST_CASE("The bundled Warframe worlds load with their sizes, blocked voxels and scenarios", "[voxel_io]") {
  // DB1's 49 million voxels are checked at 16 bytes each (0.73 GiB) as the file is read: more than
  // the default limit of a machine with little memory free; reading it takes 50 MB.
  const aco::MemoryLimit limit(std::uint64_t{64} << 30);
  struct Expected {
    const char* name;
    int width, height, depth;
    std::int64_t blocked;
  };
  for (const Expected e : {Expected{"Simple", 105, 132, 105, 512}, Expected{"Complex", 246, 154, 205, 46298},
                           Expected{"DB1", 409, 261, 462, 166123}}) {
    INFO(e.name);
    const fs::path map_file = voxel_dir() / (std::string(e.name) + ".3dmap");
    const auto m = aco::load_movingai_voxels(map_file);
    CHECK(m.width() == e.width);
    CHECK(m.height() == e.height);
    CHECK(m.depth() == e.depth);
    CHECK(m.blocked_count() == e.blocked);
    const fs::path scen_file = voxel_dir() / (std::string(e.name) + ".3dmap.3dscen");
    const auto s = aco::load_voxel_scenarios(scen_file);
    REQUIRE(s.size() == 10000);
    CHECK(aco::scenario_map_file(scen_file) == map_file);
    CHECK(s.front().map_path == map_file.filename().string());
    for (const auto& p : s) {
      REQUIRE(m.passable(p.start));
      REQUIRE(m.passable(p.goal));
      // The ratio is the length over the 3D octile distance, printed to three decimals.
      REQUIRE(p.ratio == Approx(p.optimal_length / octile3(p.start, p.goal)).margin(0.0006));
    }
    // load_scenarios reads a .3dscen too, and load_map knows the format by its ending.
    CHECK(aco::load_scenarios(scen_file).size() == 10000);
    if (std::string(e.name) == "Simple") {
      const auto any = aco::load_map(map_file);
      CHECK(any->volumetric());
      CHECK(any->depth() == 105);
      aco::PluginRegistry registry({});
      CHECK(aco::map_format_of(map_file, "", registry) == "movingai3d");
      CHECK(aco::map_format_of(scen_file, "", registry).empty());
    }
  }
}

TEST_CASE("The Simple world's optimal lengths are the benchmark rule's: no corner cutting", "[voxel_io]") {
  const auto m = aco::load_movingai_voxels(voxel_dir() / "Simple.3dmap");
  const auto s = aco::load_voxel_scenarios(voxel_dir() / "Simple.3dmap.3dscen");
  for (std::size_t i = 0; i < s.size(); i += 2000) {
    INFO("scenario " << i);
    const auto length = test::reference_voxel_distance(m, s[i].start, s[i].goal);
    REQUIRE(length);
    CHECK(*length == Approx(s[i].optimal_length).margin(1e-7));
  }
}

TEST_CASE("aco_mapgen --voxel writes worlds of the size asked, the same bytes for the same seed", "[voxel_io][tools]") {
  const fs::path first = test::temp_file("unused", "").parent_path();
  const fs::path second = test::temp_file("unused", "").parent_path();
  for (const std::string kind : {"city", "forest", "caves"}) {
    INFO(kind);
    const auto a = test::run({ACO_TEST_MAPGEN, "--voxel", kind, "40x32x16", "7", first.string(), "4"});
    REQUIRE(a.exit_code == 0);
    const auto b = test::run({ACO_TEST_MAPGEN, "--voxel", kind, "40x32x16", "7", second.string(), "4"});
    REQUIRE(b.exit_code == 0);
    const std::string stem = kind + "40x32x16-s7.3dmap";
    CHECK(a.out.find(stem) != std::string::npos);
    REQUIRE(file_bytes(first / stem) == file_bytes(second / stem));
    REQUIRE(file_bytes(first / (stem + ".3dscen")) == file_bytes(second / (stem + ".3dscen")));
    const auto m = aco::load_movingai_voxels(first / stem);
    CHECK(m.width() == 40);
    CHECK(m.height() == 32);
    CHECK(m.depth() == 16);
    CHECK(m.blocked_count() > 0);
    CHECK(m.blocked_count() < m.voxels());
    const auto s = aco::load_voxel_scenarios(first / (stem + ".3dscen"));
    REQUIRE(s.size() == 4);
    for (const auto& p : s) {
      CHECK(p.map_path == stem);
      REQUIRE(m.passable(p.start));
      REQUIRE(m.passable(p.goal));
      CHECK_FALSE(p.start == p.goal);
      CHECK(face_connected(m, p.start, p.goal));
      const auto length = test::reference_voxel_distance(m, p.start, p.goal);
      REQUIRE(length);
      CHECK(*length == Approx(p.optimal_length).margin(1e-7));
      CHECK(p.ratio == Approx(p.optimal_length / octile3(p.start, p.goal)).margin(0.0006));
    }
    // Another seed, another world.
    REQUIRE(test::run({ACO_TEST_MAPGEN, "--voxel", kind, "40x32x16", "8", second.string(), "0"}).exit_code == 0);
    CHECK(file_bytes(second / (kind + "40x32x16-s8.3dmap")) != file_bytes(first / stem));
    CHECK_FALSE(fs::exists(second / (kind + "40x32x16-s8.3dmap.3dscen")));
  }
}

TEST_CASE("aco_mapgen --voxel refuses a bad kind, size, seed or count", "[voxel_io][tools][bad-input]") {
  const fs::path dir = test::temp_file("unused", "").parent_path();
  const auto fails = [&](std::vector<std::string> args, const std::string& message) {
    args.insert(args.begin(), {ACO_TEST_MAPGEN, "--voxel"});
    const auto r = test::run(args);
    CHECK(r.exit_code != 0);
    CHECK_THAT(r.err, Contains(message));
  };
  fails({"towers", "16x16x16", "1", dir.string()}, "KIND must be city, forest or caves, not 'towers'");
  fails({"city", "16x16", "1", dir.string()}, "SIZE must be WxHxD");
  fails({"city", "4x16x16", "1", dir.string()}, "SIZE must be WxHxD");
  fails({"city", "512x512x512", "1", dir.string()}, "more than 16777216 voxels");
  fails({"city", "16x16x16", "-1", dir.string()}, "SEED must be a whole number");
  fails({"city", "16x16x16", "1", dir.string(), "-2"}, "COUNT must be 0 to 100000");
  fails({"city", "16x16x16", "1", dir.string(), "99999999999"},
        "--voxel: COUNT must be a whole number from -2147483648 to 2147483647, not '99999999999'");
}
