// map/octomap: OctoMap octrees (.bt binary, .ot full) as voxel worlds (issue 42), through the
// OctoMap library. The planning grid covers the tree's bounding box (of all its leaves, free and
// occupied) at map.resolution metres per voxel: column = x, row = y, layer = z, each counted from
// the box's lower corner, which is the VoxelMap's origin. A voxel is blocked when an occupied
// leaf overlaps it; space with no leaf (unknown) is blocked or free by map.unknown. README.md
// gives the rules.
//
// The file is checked before OctoMap reads it: OctoMap trusts its input (a truncated binary file
// reads uninitialised bytes, a full file's tree may nest deeper than the 16 levels its keys hold),
// so the header and the node structure are walked here first, and a file that does not hold
// exactly the tree its header announces is refused with the reason.
#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>
#include <octomap/OcTreeStamped.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "aco/plugin.hpp"
#include "aco/voxel.hpp"

namespace {

struct Parameters {
  double resolution = 0.0;
  bool unknown_blocked = true;
  double occupancy = 0.5;
  double padding = 0.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("resolution", &Parameters::resolution, "0:10",
               "metres per voxel of the planning grid (--map.resolution); 0 = the tree's own; a coarser voxel is "
               "blocked when any occupied leaf overlaps it"),
    aco::choice("unknown", &Parameters::unknown_blocked, {"blocked", "free"}, {true, false},
                "space the tree holds no leaf for (never observed), and the padding: blocked (a voxel with any "
                "unknown part) or free"),
    aco::field("occupancy", &Parameters::occupancy, "0.13:0.97",
               "a leaf is occupied when its occupancy probability is at least this (OctoMap's threshold; .bt "
               "leaves are 0.12 or 0.97, so only .ot files' probabilities depend on it)"),
    aco::field("padding", &Parameters::padding, "0:10",
               "metres of unknown space added around the tree's bounding box on every side (whole voxels, "
               "rounded up)"),
});

constexpr const char* kBinaryHeader = "# Octomap OcTree binary file";
constexpr const char* kFullHeader = "# Octomap OcTree file";
constexpr unsigned kTreeDepth = 16;  // OctoMap's keys: 16 bits per axis
constexpr std::int64_t kKeyOrigin = 32768;  // the key whose voxel starts at coordinate 0

enum class Format { binary, full };

// What the header says, and where the nodes start.
struct Header {
  Format format = Format::binary;
  std::string id;
  std::uint64_t size = 0;
  double resolution = 0;
  std::size_t data = 0;
};

std::string number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

class OctoMapReader final : public aco::MapReader {
 public:
  explicit OctoMapReader(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  std::vector<std::string> extensions() const override { return {".bt", ".ot"}; }

  std::string sample() const override;

  std::unique_ptr<aco::Map> read(const std::filesystem::path& file, const aco::TerrainOptions&) const override {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw aco::Error(name + ": no such OctoMap file");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw aco::Error(name + ": cannot open the OctoMap file");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw aco::Error(name + ": cannot read the OctoMap file");
    const Header header = parse_header(bytes, name);
    check_nodes(bytes, header, name);
    if (header.size == 0) throw aco::Error(name + ": the tree is empty (0 nodes): nothing to plan in");

    std::istringstream data(bytes);
    data.seekg(static_cast<std::streamoff>(header.data));
    if (header.format == Format::binary) {
      octomap::OcTree tree(header.resolution);
      tree.readBinaryData(data);
      return rasterise(tree, name);
    }
    if (header.id == "ColorOcTree") {
      octomap::ColorOcTree tree(header.resolution);
      tree.readData(data);
      return rasterise(tree, name);
    }
    if (header.id == "OcTreeStamped") {
      octomap::OcTreeStamped tree(header.resolution);
      tree.readData(data);
      return rasterise(tree, name);
    }
    octomap::OcTree tree(header.resolution);
    tree.readData(data);
    return rasterise(tree, name);
  }

 private:
  static Header parse_header(const std::string& bytes, const std::string& name);
  static void check_nodes(const std::string& bytes, const Header& header, const std::string& name);

  template <class Tree>
  std::unique_ptr<aco::Map> rasterise(Tree& tree, const std::string& name) const;

  Parameters p_;
};

Header OctoMapReader::parse_header(const std::string& bytes, const std::string& name) {
  const auto fail = [&](const std::string& why) { return aco::Error(name + ": " + why); };
  Header h;
  std::size_t at = 0;
  // One line, without its '\n' (and a '\r' before it); false at the end of the bytes.
  const auto next_line = [&](std::string& line) {
    if (at >= bytes.size()) return false;
    std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) end = bytes.size();
    line = bytes.substr(at, end - at);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    at = end + 1;
    return true;
  };
  std::string line;
  // OctoMap's reader takes the first line as a prefix (its writers add nothing after it).
  const bool first = next_line(line);
  if (first && line.rfind(kBinaryHeader, 0) == 0) {
    h.format = Format::binary;
  } else if (first && line.rfind(kFullHeader, 0) == 0) {
    h.format = Format::full;
  } else {
    throw fail(std::string("not an OctoMap file: its first line is not '") + kBinaryHeader + "' (.bt) or '" +
               kFullHeader + "' (.ot)");
  }
  bool has_size = false, has_res = false;
  for (;;) {
    if (!next_line(line)) throw fail("the OctoMap header ends before its 'data' line");
    std::istringstream words(line);
    std::string key;
    if (!(words >> key) || key[0] == '#') continue;
    if (key == "data") break;
    std::string value, extra;
    if (!(words >> value) || (words >> extra)) throw fail("the OctoMap header line '" + line + "' is not 'KEY VALUE'");
    if (key == "id") {
      h.id = value;
    } else if (key == "size") {
      std::istringstream v(value);
      if (value.find_first_not_of("0123456789") != std::string::npos || !(v >> h.size))
        throw fail("the OctoMap header's size '" + value + "' is not a node count");
      has_size = true;
    } else if (key == "res") {
      std::istringstream v(value);
      if (!(v >> h.resolution) || !v.eof() || !std::isfinite(h.resolution) || h.resolution <= 0)
        throw fail("the OctoMap header's resolution '" + value + "' is not a positive number of metres");
      has_res = true;
    } else {
      throw fail("the OctoMap header has an unknown line '" + line + "' (expected id, size, res or data)");
    }
  }
  if (h.id.empty() || !has_size || !has_res)
    throw fail(std::string("the OctoMap header lacks its ") +
               (h.id.empty() ? "'id'"
                : !has_size  ? "'size'"
                             : "'res'") +
               " line");
  if (h.format == Format::binary && h.id != "OcTree")
    throw fail("a binary OctoMap file of a '" + h.id + "': binary files hold an OcTree ('id OcTree')");
  if (h.format == Format::full && h.id != "OcTree" && h.id != "ColorOcTree" && h.id != "OcTreeStamped")
    throw fail("an OctoMap file of a '" + h.id +
               "', which holds no occupancy this reader knows (OcTree, ColorOcTree or OcTreeStamped)");
  h.data = at;
  return h;
}

// Walks the nodes as OctoMap's readers will: every byte they read is there, the tree nests no
// deeper than its keys allow, the full format's occupancies are numbers, and the node count is
// the header's, with nothing after the last node.
void OctoMapReader::check_nodes(const std::string& bytes, const Header& header, const std::string& name) {
  const auto fail = [&](const std::string& why) { return aco::Error(name + ": " + why); };
  if (header.size == 0) {
    if (header.data != bytes.size())
      throw fail("the OctoMap header says 0 nodes but " + std::to_string(bytes.size() - header.data) +
                 " bytes of data follow");
    return;
  }
  std::size_t at = header.data;
  std::uint64_t nodes = 1;  // the root
  const auto truncated = [&] {
    return fail("the OctoMap data ends inside the tree (truncated, or not the " + std::to_string(header.size) +
                " nodes its header announces)");
  };
  const auto too_deep = [&] { return fail("the OctoMap tree nests deeper than OctoMap's 16 levels (corrupt data)"); };
  const auto too_many = [&] {
    return fail("the OctoMap data holds more nodes than the " + std::to_string(header.size) + " its header announces");
  };
  if (header.format == Format::binary) {
    // Per node two bytes, two bits per child: 01 occupied leaf, 10 free leaf, 11 inner node
    // (its own two bytes follow, after its siblings' flags), 00 none.
    const auto walk = [&](const auto& self, unsigned depth) -> void {
      if (at + 2 > bytes.size()) throw truncated();
      const auto low = static_cast<unsigned char>(bytes[at]), high = static_cast<unsigned char>(bytes[at + 1]);
      at += 2;
      const unsigned flags = low | (unsigned(high) << 8);
      for (unsigned child = 0; child < 8; ++child)
        if ((flags >> (2 * child)) & 3u) ++nodes;
      if (nodes > header.size) throw too_many();
      for (unsigned child = 0; child < 8; ++child)
        if (((flags >> (2 * child)) & 3u) == 3u) {
          if (depth + 1 >= kTreeDepth) throw too_deep();
          self(self, depth + 1);
        }
    };
    walk(walk, 0);
  } else {
    // Per node its data (the occupancy's log-odds as a float, and a ColorOcTree's colour, 3
    // bytes; an OcTreeStamped writes no time stamp), then one byte with a bit per child; the
    // children follow in order.
    const std::size_t extra = header.id == "ColorOcTree" ? 3 : 0;
    const auto walk = [&](const auto& self, unsigned depth) -> void {
      if (at + sizeof(float) + extra + 1 > bytes.size()) throw truncated();
      float log_odds = 0;
      std::memcpy(&log_odds, bytes.data() + at, sizeof(float));
      if (!std::isfinite(log_odds)) throw fail("the OctoMap data holds an occupancy that is not a number");
      at += sizeof(float) + extra;
      const auto children = static_cast<unsigned char>(bytes[at++]);
      for (unsigned child = 0; child < 8; ++child)
        if ((children >> child) & 1u) {
          if (depth + 1 > kTreeDepth) throw too_deep();
          if (++nodes > header.size) throw too_many();
          self(self, depth + 1);
        }
    };
    walk(walk, 0);
  }
  if (nodes != header.size)
    throw fail("the OctoMap header announces " + std::to_string(header.size) + " nodes but the data holds " +
               std::to_string(nodes));
  if (at != bytes.size()) throw fail(std::to_string(bytes.size() - at) + " bytes follow the OctoMap tree's last node");
}

// The planning grid over the tree. Everything is counted in the tree's voxels ("keys"): a leaf
// at depth d covers 2^(16-d) of them along each axis, aligned to its size; planning voxel i
// covers [i f, (i+1) f) of them from the box's lower corner, f = resolution / the tree's.
template <class Tree>
std::unique_ptr<aco::Map> OctoMapReader::rasterise(Tree& tree, const std::string& name) const {
  const double tree_resolution = tree.getResolution();
  const double resolution = p_.resolution == 0 ? tree_resolution : p_.resolution;
  // A relative margin for resolutions that are a multiple of the tree's up to rounding.
  constexpr double kSlack = 1e-9;
  if (resolution < tree_resolution * (1 - kSlack))
    throw aco::Error(name + ": map.resolution " + number(resolution) + " is finer than the tree's own " +
                     number(tree_resolution) + " m; give 0 (the tree's) or at least " + number(tree_resolution));
  tree.setOccupancyThres(p_.occupancy);

  // Each leaf as its lower corner and size in tree voxels. The leaves are visited twice (the box,
  // then the grid) rather than kept: a large tree holds millions.
  struct Leaf {
    std::int64_t lo[3];
    std::int64_t size;
  };
  const auto leaf_of = [](const auto& it) {
    const std::int64_t size = std::int64_t{1} << (kTreeDepth - it.getDepth());
    const octomap::OcTreeKey key = it.getKey();  // of the leaf's centre, or its one voxel
    Leaf leaf{{}, size};
    for (int axis = 0; axis < 3; ++axis) leaf.lo[axis] = std::int64_t{key[axis]} & ~(size - 1);
    return leaf;
  };
  std::int64_t lo[3] = {std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::max(),
                        std::numeric_limits<std::int64_t>::max()};
  std::int64_t hi[3] = {std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::min(),
                        std::numeric_limits<std::int64_t>::min()};
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const Leaf leaf = leaf_of(it);
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::min(lo[axis], leaf.lo[axis]);
      hi[axis] = std::max(hi[axis], leaf.lo[axis] + leaf.size);
    }
  }
  if (lo[0] > hi[0]) throw aco::Error(name + ": the tree holds no leaves: nothing to plan in");

  const double f = resolution / tree_resolution;
  const std::int64_t pad = static_cast<std::int64_t>(std::ceil(p_.padding / resolution - kSlack));
  std::int64_t count[3];
  for (int axis = 0; axis < 3; ++axis)
    count[axis] = static_cast<std::int64_t>(std::ceil(double(hi[axis] - lo[axis]) / f - kSlack)) + 2 * pad;
  const std::int64_t voxels = count[0] * count[1] * count[2];
  const std::string grid = std::to_string(count[0]) + "x" + std::to_string(count[1]) + "x" + std::to_string(count[2]);
  if (voxels > std::numeric_limits<std::int32_t>::max())
    throw aco::Error(name + ": a " + grid + " voxel grid at " + number(resolution) + " m per voxel is " +
                     std::to_string(voxels) +
                     " voxels, more than the graph's 32-bit node ids allow; choose a coarser map.resolution");
  // Planning memory at the least the graph will need, the 6-neighbourhood's (the run's own edges are
  // counted and checked when the graph is built), and the reader's own per-voxel unknown share.
  const std::uint64_t needed = aco::planning_memory_estimate(count[0], count[1], count[2], aco::Neighbourhood::six) +
                               std::uint64_t(voxels) * (p_.unknown_blocked ? sizeof(double) : 0);
  if (needed > aco::memory_limit())
    throw aco::Error(
        name + ": a " + grid + " voxel grid at " + number(resolution) + " m per voxel needs about " +
        aco::format_bytes(needed) + " to plan on (estimate with the 6-neighbourhood), more than the memory limit of " +
        aco::format_bytes(aco::memory_limit()) + ": refused; choose a coarser map.resolution or raise --max-memory");

  auto map = std::make_unique<aco::VoxelMap>(int(count[0]), int(count[1]), int(count[2]), name);
  const Eigen::Vector3d corner(double(lo[0] - kKeyOrigin) * tree_resolution,
                               double(lo[1] - kKeyOrigin) * tree_resolution,
                               double(lo[2] - kKeyOrigin) * tree_resolution);
  map->set_placement(resolution, corner - Eigen::Vector3d::Constant(double(pad) * resolution));

  const auto index = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
    return std::size_t((z * count[1] + y) * count[0] + x);
  };
  // The tree's volume known (covered by a leaf) per planning voxel, in tree voxels, when unknown
  // space is blocked.
  std::vector<double> known(p_.unknown_blocked ? std::size_t(voxels) : 0, 0.0);
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const bool occupied = tree.isNodeOccupied(*it);
    if (!occupied && !p_.unknown_blocked) continue;
    const Leaf leaf = leaf_of(it);
    std::int64_t first[3], last[3];  // planning voxels the leaf overlaps, without the padding
    double a[3], b[3];
    for (int axis = 0; axis < 3; ++axis) {
      a[axis] = double(leaf.lo[axis] - lo[axis]);
      b[axis] = a[axis] + double(leaf.size);
      first[axis] = static_cast<std::int64_t>(std::floor(a[axis] / f + kSlack));
      last[axis] = static_cast<std::int64_t>(std::ceil(b[axis] / f - kSlack)) - 1;
    }
    const auto overlap = [&](int axis, std::int64_t i) {
      return std::min(b[axis], double(i + 1) * f) - std::max(a[axis], double(i) * f);
    };
    for (std::int64_t z = first[2]; z <= last[2]; ++z)
      for (std::int64_t y = first[1]; y <= last[1]; ++y)
        for (std::int64_t x = first[0]; x <= last[0]; ++x) {
          const aco::Cell cell{int(x + pad), int(y + pad), int(z + pad)};
          if (occupied) map->set_blocked(cell, true);
          if (p_.unknown_blocked) known[index(cell.x, cell.y, cell.z)] += overlap(0, x) * overlap(1, y) * overlap(2, z);
        }
  }
  if (p_.unknown_blocked) {
    // A voxel is known when leaves cover all of its part inside the box; the padding is unknown.
    const auto inside = [&](int axis, std::int64_t i) {
      if (i < pad || i >= count[axis] - pad) return 0.0;
      const double from = double(i - pad) * f, to = std::min(double(i - pad + 1) * f, double(hi[axis] - lo[axis]));
      return to - from;
    };
    for (std::int64_t z = 0; z < count[2]; ++z)
      for (std::int64_t y = 0; y < count[1]; ++y)
        for (std::int64_t x = 0; x < count[0]; ++x) {
          const double volume = inside(0, x) * inside(1, y) * inside(2, z);
          if (volume == 0 || known[index(x, y, z)] < volume * (1 - 1e-9))
            map->set_blocked({int(x), int(y), int(z)}, true);
        }
  }
  return map;
}

// A 2 x 1.5 x 1 metre room at 0.5 m per voxel (4 x 3 x 2 voxels): a pillar at x 0.5..1, y
// 0.5..1, a crate at x 1.5..2, y 0..0.5 on the ground, and one corner never observed (x 1.5..2,
// y 1..1.5, z 0.5..1), written as OctoMap's writeBinary() writes it.
std::string OctoMapReader::sample() const {
  octomap::OcTree tree(0.5);
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) {
        if (x == 3 && y == 2 && z == 1) continue;
        const bool occupied = (x == 1 && y == 1) || (x == 3 && y == 0 && z == 0);
        tree.updateNode(octomap::point3d(float(x * 0.5 + 0.25), float(y * 0.5 + 0.25), float(z * 0.5 + 0.25)), occupied,
                        true);
      }
  tree.updateInnerOccupancy();
  tree.toMaxLikelihood();
  tree.prune();
  std::ostringstream out;
  out << kBinaryHeader << "\n# a sample of map/octomap\nid OcTree\nsize " << tree.size() << "\nres "
      << tree.getResolution() << "\ndata\n";
  tree.writeBinaryData(out);
  return out.str();
}

}  // namespace

ACO_PLUGIN(map, octomap, OctoMapReader, "0.1",
           "OctoMap octrees (.bt, .ot) as voxel worlds at map.resolution, unknown space blocked or free", kParams)
