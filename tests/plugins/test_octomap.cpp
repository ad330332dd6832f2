// map/octomap: OctoMap octrees as voxel worlds (issue 42), on the bundled hall
// (data/maps/octomap, made by tools/octomapgen: 32 x 24 x 12 voxels of 0.25 m from (-4, -3, 0),
// 1540 occupied, 528 unknown behind the tower, the rest free).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "aco/engine/map_formats.hpp"
#include "aco/memory_limit.hpp"
#include "aco/voxel.hpp"
#include "support.hpp"

using Catch::Contains;

namespace {

namespace fs = std::filesystem;

const fs::path hall_bt = test::data_dir() / "maps/octomap/hall.bt";
const fs::path hall_ot = test::data_dir() / "maps/octomap/hall.ot";

std::unique_ptr<aco::VoxelMap> read(const fs::path& file, const std::map<std::string, std::string>& params = {}) {
  const auto reader = test::make<aco::MapReader>("map", "octomap", params);
  std::unique_ptr<aco::Map> map = reader->read(file, {});
  auto* voxels = dynamic_cast<aco::VoxelMap*>(map.get());
  REQUIRE(voxels != nullptr);
  map.release();
  return std::unique_ptr<aco::VoxelMap>(voxels);
}

void check_size(const aco::VoxelMap& map, int width, int height, int depth) {
  CHECK(map.width() == width);
  CHECK(map.height() == height);
  CHECK(map.depth() == depth);
  CHECK(map.volumetric());
}

// The coarse grid at resolution num/den tree voxels, as the README's rule states it, from the
// tree-resolution grids: a coarse voxel is blocked when a tree voxel it overlaps (with volume) is
// occupied, or, unknown space being blocked, unknown.
std::int64_t reference_blocked(const aco::VoxelMap& occupied, const aco::VoxelMap& occupied_or_unknown,
                               const aco::VoxelMap& coarse, int num, int den, bool unknown_blocked) {
  std::int64_t blocked = 0;
  for (int z = 0; z < coarse.depth(); ++z)
    for (int y = 0; y < coarse.height(); ++y)
      for (int x = 0; x < coarse.width(); ++x) {
        bool b = false;
        const auto overlapping = [&](int i, int fine) {
          return fine * den < (i + 1) * num && (fine + 1) * den > i * num;
        };
        for (int k = 0; k < occupied.depth(); ++k)
          for (int j = 0; j < occupied.height(); ++j)
            for (int i = 0; i < occupied.width(); ++i)
              if (overlapping(x, i) && overlapping(y, j) && overlapping(z, k))
                b = b || (unknown_blocked ? occupied_or_unknown : occupied).blocked({i, j, k});
        INFO("voxel " << x << "," << y << "," << z);
        CHECK(coarse.blocked({x, y, z}) == b);
        blocked += b;
      }
  return blocked;
}

fs::path scratch_file(const std::string& name, const std::string& contents) {
  const fs::path folder = fs::temp_directory_path() / "aco-test-octomap";
  fs::create_directories(folder);
  const fs::path file = folder / name;
  std::ofstream(file, std::ios::binary) << contents;
  return file;
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string binary_header(const std::string& size, const std::string& res = "0.25", const std::string& id = "OcTree") {
  return "# Octomap OcTree binary file\n#\nid " + id + "\nsize " + size + "\nres " + res + "\ndata\n";
}

std::string full_node(float log_odds, unsigned char children) {
  std::string node(sizeof(float), '\0');
  std::memcpy(node.data(), &log_odds, sizeof(float));
  return node + static_cast<char>(children);
}

}  // namespace

TEST_CASE("octomap: declared parameters and claimed endings", "[plugin][octomap]") {
  const auto& d = test::plugins().load("map", "octomap");
  REQUIRE(d.parameters().size() == 4);
  CHECK(d.parameters()[0].name == std::string("resolution"));
  CHECK(d.parameters()[1].name == std::string("unknown"));
  CHECK(d.parameters()[2].name == std::string("occupancy"));
  CHECK(d.parameters()[3].name == std::string("padding"));
  CHECK(test::make<aco::MapReader>("map", "octomap")->extensions() == std::vector<std::string>{".bt", ".ot"});
  CHECK(aco::map_format_of(hall_bt, "", test::plugins()) == "octomap");
  CHECK(aco::map_format_of(hall_ot, "", test::plugins()) == "octomap");
  const auto map = aco::load_map(hall_bt, {}, test::plugins());
  CHECK(map->volumetric());
  CHECK(map->depth() == 12);
}

TEST_CASE("octomap: the hall at the tree's resolution, unknown space blocked or free", "[plugin][octomap]") {
  for (const fs::path& file : {hall_bt, hall_ot}) {
    INFO(file.string());
    const auto blocked = read(file);  // the defaults: resolution 0 (the tree's), unknown blocked
    const auto free = read(file, {{"unknown", "free"}});
    for (const auto* map : {blocked.get(), free.get()}) {
      check_size(*map, 32, 24, 12);
      CHECK(map->resolution() == 0.25);
      CHECK(map->origin() == Eigen::Vector3d(-4, -3, 0));
      CHECK(map->name() == file.string());
      CHECK(map->blocked({0, 0, 0}));  // the floor
      CHECK(map->blocked({31, 23, 0}));
      CHECK(map->passable({0, 0, 1}));  // above it
      CHECK(map->blocked({12, 5, 6}));  // the wall at x -1..-0.5 ...
      CHECK(map->passable({13, 11, 6}));  // ... and its window, y -0.5..0.5, z 1.25..2
      CHECK(map->blocked({13, 11, 8}));  // above the window
      CHECK(map->blocked({21, 5, 3}));  // the box
      CHECK(map->passable({21, 5, 6}));  // over it
      CHECK(map->blocked({25, 19, 8}));  // the tower's top layer
      CHECK(map->blocked({4, 18, 11}));  // the pillar, to the top
      CHECK(map->blocked({4, 4, 1}));  // the foliage (probability 0.6)
    }
    CHECK(free->blocked_count() == 1540);  // the occupied voxels
    CHECK(blocked->blocked_count() == 1540 + 528);  // and the unknown ones behind the tower
    CHECK(free->passable({28, 20, 5}));
    CHECK(blocked->blocked({28, 20, 5}));
    CHECK(free->passable({26, 16, 11}));
    CHECK(blocked->blocked({26, 16, 11}));
    CHECK(blocked->passable({25, 16, 9}));  // above the tower, beside the shadow
  }
}

TEST_CASE("octomap: the occupancy threshold reads the .ot file's probabilities", "[plugin][octomap]") {
  // The foliage's probability 0.6 is kept in the full file; the binary file stores it occupied.
  const auto ot = read(hall_ot, {{"unknown", "free"}, {"occupancy", "0.7"}});
  CHECK(ot->blocked_count() == 1540 - 16);
  CHECK(ot->passable({4, 4, 1}));
  const auto bt = read(hall_bt, {{"unknown", "free"}, {"occupancy", "0.7"}});
  CHECK(bt->blocked_count() == 1540);
  CHECK(bt->blocked({4, 4, 1}));
  CHECK(read(hall_ot, {{"unknown", "free"}, {"occupancy", "0.13"}})->blocked_count() == 1540);
}

TEST_CASE("octomap: coarser resolutions block a voxel that any occupied leaf overlaps", "[plugin][octomap]") {
  const auto occupied = read(hall_bt, {{"unknown", "free"}});
  const auto occupied_or_unknown = read(hall_bt);
  SECTION("0.5 m: two tree voxels per voxel") {
    const auto free = read(hall_bt, {{"resolution", "0.5"}, {"unknown", "free"}});
    const auto blocked = read(hall_bt, {{"resolution", "0.5"}});
    check_size(*free, 16, 12, 6);
    check_size(*blocked, 16, 12, 6);
    CHECK(free->resolution() == 0.5);
    CHECK(free->origin() == Eigen::Vector3d(-4, -3, 0));
    CHECK(free->passable({6, 5, 3}));  // the window survives, 1 x 2 x 1 voxels
    CHECK(free->passable({6, 6, 3}));
    CHECK(free->blocked({6, 5, 2}));  // z 1..1.5 holds the wall's part below the window
    CHECK(free->blocked({6, 4, 3}));
    CHECK(blocked->passable({6, 5, 3}));
    CHECK(free->passable({14, 9, 4}));  // in the shadow
    CHECK(blocked->blocked({14, 9, 4}));
    CHECK(reference_blocked(*occupied, *occupied_or_unknown, *free, 2, 1, false) == free->blocked_count());
    CHECK(reference_blocked(*occupied, *occupied_or_unknown, *blocked, 2, 1, true) == blocked->blocked_count());
    CHECK(free->blocked_count() == 16 * 12 + 89);  // the floor layer, and 89 voxels above it
    CHECK(blocked->blocked_count() == 16 * 12 + 89 + 60);  // and 60 with unknown space
  }
  SECTION("0.6 m: not a multiple of the tree's 0.25 m; the last voxels reach past the box") {
    const auto free = read(hall_bt, {{"resolution", "0.6"}, {"unknown", "free"}});
    const auto blocked = read(hall_bt, {{"resolution", "0.6"}});
    check_size(*free, 14, 10, 5);  // 8 / 0.6 = 13.3, 6 / 0.6 = 10, 3 / 0.6 = 5
    CHECK(free->resolution() == 0.6);
    // 0.6 m = 12/5 tree voxels.
    CHECK(reference_blocked(*occupied, *occupied_or_unknown, *free, 12, 5, false) == free->blocked_count());
    CHECK(reference_blocked(*occupied, *occupied_or_unknown, *blocked, 12, 5, true) == blocked->blocked_count());
    CHECK(free->blocked_count() == 232);
    CHECK(blocked->blocked_count() == 287);
  }
  SECTION("10 m: one voxel, blocked") {
    const auto one = read(hall_bt, {{"resolution", "10"}, {"unknown", "free"}});
    check_size(*one, 1, 1, 1);
    CHECK(one->blocked({0, 0, 0}));
  }
}

TEST_CASE("octomap: padding adds unknown space around the box", "[plugin][octomap]") {
  const auto free = read(hall_bt, {{"padding", "0.4"}, {"unknown", "free"}});  // 0.4 m: 2 voxels, rounded up
  const auto blocked = read(hall_bt, {{"padding", "0.4"}});
  check_size(*free, 36, 28, 16);
  CHECK(free->origin() == Eigen::Vector3d(-4.5, -3.5, -0.5));
  CHECK(free->blocked_count() == 1540);
  CHECK(free->passable({0, 0, 0}));
  CHECK(free->blocked({2, 2, 2}));  // the hall's floor at (0, 0, 0)
  CHECK(blocked->blocked_count() == 36 * 28 * 16 - 7148);  // all but the hall's free voxels
  CHECK(blocked->blocked({0, 0, 0}));
  CHECK(blocked->passable({2, 2, 3}));
}

TEST_CASE("octomap: its sample is a small room", "[plugin][octomap]") {
  const auto reader = test::make<aco::MapReader>("map", "octomap");
  const std::string sample = reader->sample();
  CHECK(sample.rfind("# Octomap OcTree binary file\n", 0) == 0);
  CHECK(sample == reader->sample());
  const auto room = read(scratch_file("sample.bt", sample), {{"unknown", "free"}});
  check_size(*room, 4, 3, 2);
  CHECK(room->blocked({1, 1, 0}));  // the pillar
  CHECK(room->blocked({1, 1, 1}));
  CHECK(room->blocked({3, 0, 0}));  // the crate
  CHECK(room->blocked_count() == 3);
  CHECK(read(scratch_file("sample.bt", sample))->blocked({3, 2, 1}));  // the corner never observed
}

TEST_CASE("octomap: .ot files of the other tree types with occupancy", "[plugin][octomap]") {
  // One voxel at the deepest level: 16 inner nodes, each with its first child only (towards
  // lower keys), then the leaf, whose key is 0 on every axis: the corner -32768 voxels from 0.
  const auto one_voxel = [](const std::string& id, std::size_t extra, float leaf) {
    std::string file = "# Octomap OcTree file\nid " + id + "\nsize 17\nres 0.5\ndata\n";
    const auto node = [&](float log_odds, unsigned char children) {
      std::string n = full_node(log_odds, children);
      return n.insert(sizeof(float), std::string(extra, '\x7f'));  // the colour, between value and children
    };
    for (int level = 0; level < 16; ++level) file += node(leaf, 1);
    return file + node(leaf, 0);
  };
  for (const auto& [id, extra] :
       std::vector<std::pair<std::string, std::size_t>>{{"OcTree", 0}, {"ColorOcTree", 3}, {"OcTreeStamped", 0}}) {
    INFO(id);
    const auto occupied = read(scratch_file(id + "_occupied.ot", one_voxel(id, extra, 2.0f)));
    check_size(*occupied, 1, 1, 1);
    CHECK(occupied->origin() == Eigen::Vector3d(-16384, -16384, -16384));
    CHECK(occupied->blocked({0, 0, 0}));
    const auto free = read(scratch_file(id + "_free.ot", one_voxel(id, extra, -2.0f)));
    CHECK(free->passable({0, 0, 0}));
  }
}

TEST_CASE("octomap: every refusal names the file and the cause", "[plugin][octomap]") {
  const auto reader = test::make<aco::MapReader>("map", "octomap");
  const auto refused = [&](const fs::path& file, const std::string& cause,
                           const std::map<std::string, std::string>& params = {}) {
    INFO(file.string() << ": " << cause);
    CHECK_THROWS_WITH(test::make<aco::MapReader>("map", "octomap", params)->read(file, {}),
                      Contains(file.string()) && Contains(cause));
  };
  refused("no/such/hall.bt", "no such OctoMap file");
  refused(fs::temp_directory_path(), "no such OctoMap file");  // a folder
  refused(scratch_file("empty.bt", ""), "not an OctoMap file");
  refused(scratch_file("garbage.bt", "P5\n4 4\n255\n\x01\x02"), "not an OctoMap file");
  refused(scratch_file("text.ot", "# Octomap OcTree file\nid OcTree\nsize 3\n"), "ends before its 'data' line");
  refused(scratch_file("no_res.bt", "# Octomap OcTree binary file\nid OcTree\nsize 1\ndata\n"), "lacks its 'res' line");
  refused(scratch_file("bad_res.bt", binary_header("1", "-0.1")), "is not a positive number of metres");
  refused(scratch_file("bad_size.bt", binary_header("many")), "is not a node count");
  refused(scratch_file("unknown_line.bt", "# Octomap OcTree binary file\nid OcTree\nlevels 3\n"), "unknown line");
  refused(scratch_file("colour.bt", binary_header("1", "0.1", "ColorOcTree") + std::string(2, '\0')),
          "binary files hold an OcTree");
  refused(scratch_file("counting.ot", "# Octomap OcTree file\nid CountingOcTree\nsize 1\nres 0.1\ndata\n"),
          "holds no occupancy this reader knows");
  refused(scratch_file("empty_tree.bt", binary_header("0")), "the tree is empty");

  const std::string hall = read_bytes(hall_bt);
  refused(scratch_file("truncated.bt", hall.substr(0, hall.size() - 40)), "ends inside the tree");
  refused(scratch_file("trailing.bt", hall + "xyz"), "3 bytes follow");
  std::string wrong_size = hall;
  wrong_size.replace(wrong_size.find("size 2105"), 9, "size 2106");
  refused(scratch_file("wrong_size.bt", wrong_size), "announces 2106 nodes but the data holds 2105");
  wrong_size.replace(wrong_size.find("size 2106"), 9, "size 2000");
  refused(scratch_file("too_many.bt", wrong_size), "more nodes than the 2000");
  const std::string full = read_bytes(hall_ot);
  refused(scratch_file("truncated.ot", full.substr(0, full.size() / 2)), "ends inside the tree");

  // A full tree whose every node has one child, 17 levels below the root: deeper than keys go.
  std::string deep = "# Octomap OcTree file\nid OcTree\nsize 18\nres 0.1\ndata\n";
  for (int level = 0; level < 17; ++level) deep += full_node(0.0f, 1);
  deep += full_node(1.0f, 0);
  refused(scratch_file("deep.ot", deep), "deeper than OctoMap's 16 levels");
  std::string deep_binary = binary_header("17");  // inner nodes to depth 16, which holds no children
  for (int level = 0; level < 16; ++level) deep_binary += std::string("\x03\x00", 2);
  refused(scratch_file("deep.bt", deep_binary), "deeper than OctoMap's 16 levels");
  std::string nan = "# Octomap OcTree file\nid OcTree\nsize 1\nres 0.1\ndata\n";
  nan += full_node(std::numeric_limits<float>::quiet_NaN(), 0);
  refused(scratch_file("nan.ot", nan), "not a number");

  // Resolutions: finer than the tree's is refused (0 takes the tree's).
  refused(hall_bt, "map.resolution 0.1 is finer than the tree's own 0.25", {{"resolution", "0.1"}});
  // A tree that is only its root: one leaf, the whole of OctoMap's 65536^3 key space.
  refused(scratch_file("root.bt", binary_header("1") + std::string(2, '\0')),
          "65536x65536x65536 voxel grid at 0.25 m per voxel is 281474976710656 voxels, more than the graph's "
          "32-bit node ids allow");
  {
    // 1 MiB: the hall's 9216 voxels need about 1.2 MiB (136 bytes each with the 6-neighbourhood)
    const aco::MemoryLimit limit(std::uint64_t(1) << 20);
    refused(hall_bt, "needs about 1.2 MiB", {{"unknown", "free"}});
    refused(hall_bt, "more than the memory limit of 1.0 MiB");
    CHECK(read(hall_bt, {{"resolution", "0.5"}})->voxels() == 16 * 12 * 6);
  }
}
