// Generated voxel worlds: see voxel_worlds.hpp.
#include "voxel_worlds.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <optional>
#include <queue>
#include <sstream>
#include <vector>

#include "aco/astar.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/rng.hpp"
#include "aco/voxel.hpp"
#include "files.hpp"

namespace mapgen {
namespace {

// ---------------------------------------------------------------------------------------------
// Voxel worlds (--voxel): Moving AI .3dmap files of a city, a forest or caves, each with a
// .3dmap.3dscen whose optimal lengths are exact for the Moving AI voxel benchmarks' moves
// (data/maps/voxel/README.md): 26 neighbours, costs 1, sqrt 2, sqrt 3, no corner cutting.
// z is the layer from the ground up.

struct VoxelSize {
  int width = 0, height = 0, depth = 0;
};

VoxelSize parse_voxel_size(const std::string& text) {
  VoxelSize s;
  char x1 = 0, x2 = 0;
  std::istringstream in(text);
  std::string rest;
  if (!(in >> s.width >> x1 >> s.height >> x2 >> s.depth) || x1 != 'x' || x2 != 'x' || (in >> rest) || s.width < 8 ||
      s.height < 8 || s.depth < 8 || s.width > 1024 || s.height > 1024 || s.depth > 1024)
    throw aco::Error("--voxel: SIZE must be WxHxD with each side 8 to 1024 voxels (e.g. 64x64x32), not '" + text + "'");
  // The generators keep a few bytes per voxel and every scenario a full distance array.
  if (std::int64_t{s.width} * s.height * s.depth > (std::int64_t{1} << 24))
    throw aco::Error("--voxel: SIZE " + text + " has more than 16777216 voxels (256x256x256)");
  return s;
}

void fill_box(aco::VoxelMap& m, int x0, int y0, int z0, int x1, int y1, int z1) {
  for (int z = std::max(z0, 0); z <= std::min(z1, m.depth() - 1); ++z)
    for (int y = std::max(y0, 0); y <= std::min(y1, m.height() - 1); ++y)
      for (int x = std::max(x0, 0); x <= std::min(x1, m.width() - 1); ++x) m.set_blocked({x, y, z}, true);
}

int random_between(aco::Rng& rng, int low, int high) {  // both ends included
  return low + static_cast<int>(rng.below(static_cast<std::uint64_t>(high - low + 1)));
}

// A city: a street grid of blocks 10 to 16 voxels a side between streets 3 or 4 wide, each block
// split into one to four lots; a lot is a building (a box from the ground, set back one voxel from
// its neighbours, of a random height up to 3/4 of the world's) or, one time in six, an empty
// square. The top quarter stays free: the streets and the sky join everything.
aco::VoxelMap city_world(VoxelSize s, aco::Rng& rng, const std::string& name) {
  aco::VoxelMap m(s.width, s.height, s.depth, name);
  const int max_height = std::max(1, s.depth * 3 / 4);
  auto blocks = [&](int extent) {  // [begin, end) of the blocks along one axis
    std::vector<std::pair<int, int>> spans;
    for (int at = random_between(rng, 1, 3); at < extent;) {
      const int size = random_between(rng, 10, 16);
      spans.push_back({at, std::min(at + size, extent)});
      at += size + random_between(rng, 3, 4);
    }
    return spans;
  };
  const auto xs = blocks(s.width);
  const auto ys = blocks(s.height);
  for (const auto& [bx0, bx1] : xs)
    for (const auto& [by0, by1] : ys) {
      // One cut across x and one across y, each with probability 1/2: one to four lots.
      const int cx = bx1 - bx0 >= 8 && rng.below(2) ? random_between(rng, bx0 + 4, bx1 - 4) : bx1;
      const int cy = by1 - by0 >= 8 && rng.below(2) ? random_between(rng, by0 + 4, by1 - 4) : by1;
      for (const auto& [lx0, lx1] : {std::pair{bx0, cx}, std::pair{cx, bx1}})
        for (const auto& [ly0, ly1] : {std::pair{by0, cy}, std::pair{cy, by1}}) {
          if (lx1 - lx0 < 2 || ly1 - ly0 < 2) continue;
          if (rng.below(6) == 0) continue;  // a square
          const int top = random_between(rng, std::max(1, max_height / 4), max_height) - 1;
          fill_box(m, lx0, ly0, 0, lx1 - 2, ly1 - 2, top);
        }
    }
  return m;
}

// A forest: trees on a jittered grid 6 to 10 voxels apart, each a trunk one or two voxels wide and
// a crown, a ball of radius 2 to 4 at its top; heights up to 4/5 of the world's.
aco::VoxelMap forest_world(VoxelSize s, aco::Rng& rng, const std::string& name) {
  aco::VoxelMap m(s.width, s.height, s.depth, name);
  const int spacing = random_between(rng, 6, 10);
  for (int gy = 0; gy < s.height; gy += spacing)
    for (int gx = 0; gx < s.width; gx += spacing) {
      if (rng.below(5) == 0) continue;  // a clearing
      const int x = gx + random_between(rng, 0, spacing - 1), y = gy + random_between(rng, 0, spacing - 1);
      const int trunk = random_between(rng, 1, 2);
      const int height = random_between(rng, std::max(3, s.depth / 4), std::max(3, s.depth * 4 / 5));
      const int radius = random_between(rng, 2, 4);
      fill_box(m, x, y, 0, x + trunk - 1, y + trunk - 1, height - 1);
      const double cx = x + (trunk - 1) / 2.0, cy = y + (trunk - 1) / 2.0, cz = height - 1;
      for (int z = static_cast<int>(cz) - radius; z <= static_cast<int>(cz) + radius; ++z)
        for (int yy = y - radius; yy <= y + trunk - 1 + radius; ++yy)
          for (int xx = x - radius; xx <= x + trunk - 1 + radius; ++xx) {
            const double dx = xx - cx, dy = yy - cy, dz = z - cz;
            if (dx * dx + dy * dy + dz * dz <= radius * radius + 0.5 && m.contains({xx, yy, z}))
              m.set_blocked({xx, yy, z}, true);
          }
    }
  return m;
}

// Free voxels of `m` joined by face steps, which is how far the benchmarks' moves reach: a
// diagonal step needs its whole box free, so a face path runs beside every one. Each part as
// a list of voxel indices (x fastest, then y, then z), largest first, ties by first voxel.
std::vector<std::vector<std::int64_t>> voxel_parts(const aco::VoxelMap& m) {
  const std::int64_t w = m.width(), h = m.height(), d = m.depth();
  std::vector<char> seen(static_cast<std::size_t>(w * h * d), 0);
  std::vector<std::vector<std::int64_t>> parts;
  for (std::int64_t first = 0; first < w * h * d; ++first) {
    const aco::Cell c{int(first % w), int(first / w % h), int(first / (w * h))};
    if (seen[first] || m.blocked(c)) continue;
    std::vector<std::int64_t> part{first};
    seen[first] = 1;
    for (std::size_t i = 0; i < part.size(); ++i) {
      const std::int64_t v = part[i];
      const int x = int(v % w), y = int(v / w % h), z = int(v / (w * h));
      const int step[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
      for (const auto& s : step) {
        const aco::Cell n{x + s[0], y + s[1], z + s[2]};
        if (!m.contains(n) || m.blocked(n)) continue;
        const std::int64_t u = (std::int64_t{n.z} * h + n.y) * w + n.x;
        if (!seen[u]) seen[u] = 1, part.push_back(u);
      }
    }
    parts.push_back(std::move(part));
  }
  std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
  return parts;
}

// Caves: a 3D cellular automaton. Voxels blocked with probability 0.5 (the outer shell always),
// then five rounds of "blocked iff at least 14 of the 26 neighbours are, free iff at most 12,
// else unchanged" (outside counts as blocked); every cave but the largest is filled, so one
// connected system remains.
aco::VoxelMap cave_world(VoxelSize s, aco::Rng& rng, const std::string& name) {
  const int w = s.width, h = s.height, d = s.depth;
  auto at = [&](int x, int y, int z) { return (static_cast<std::size_t>(z) * h + y) * w + x; };
  std::vector<char> rock(static_cast<std::size_t>(w) * h * d);
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const bool shell = x == 0 || y == 0 || z == 0 || x == w - 1 || y == h - 1 || z == d - 1;
        rock[at(x, y, z)] = shell || rng.uniform() < 0.5;
      }
  for (int round = 0; round < 5; ++round) {
    std::vector<char> next = rock;
    for (int z = 0; z < d; ++z)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          int walls = 0;
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                if (!dx && !dy && !dz) continue;
                const int nx = x + dx, ny = y + dy, nz = z + dz;
                walls += nx < 0 || ny < 0 || nz < 0 || nx >= w || ny >= h || nz >= d || rock[at(nx, ny, nz)];
              }
          if (walls >= 14)
            next[at(x, y, z)] = 1;
          else if (walls <= 12)
            next[at(x, y, z)] = 0;
        }
    rock.swap(next);
  }
  aco::VoxelMap m(w, h, d, name);
  for (int z = 0; z < d; ++z)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) m.set_blocked({x, y, z}, rock[at(x, y, z)] != 0);
  const auto parts = voxel_parts(m);
  for (std::size_t p = 1; p < parts.size(); ++p)
    for (const std::int64_t v : parts[p])
      m.set_blocked({int(v % w), int(v / w % h), int(v / (std::int64_t{w} * h))}, true);
  return m;
}

// The 3D octile distance, the heuristic the .3dscen ratio column divides by.
double voxel_octile(aco::Cell a, aco::Cell b) {
  int d[3] = {std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)};
  std::sort(d, d + 3);
  return std::sqrt(3.0) * d[0] + std::sqrt(2.0) * (d[1] - d[0]) + (d[2] - d[1]);
}

// `count` problems in the largest connected part, start and goal distinct and drawn uniformly
// from it, in Moving AI's .3dscen layout.
std::string voxel_scenarios(const aco::VoxelMap& m, const std::string& map_file, int count, aco::Rng& rng) {
  const auto parts = voxel_parts(m);
  std::string text = "version 1\n" + map_file + "\n";
  if (parts.empty() || parts.front().size() < 2) throw aco::Error(m.name() + ": fewer than two connected free voxels");
  const auto& part = parts.front();
  const std::int64_t w = m.width(), h = m.height();
  auto cell = [&](std::int64_t v) { return aco::Cell{int(v % w), int(v / w % h), int(v / (w * h))}; };
  // The benchmarks' moves: 26 neighbours, every voxel of a move's box free (no corner cutting).
  const aco::Graph graph = aco::build_graph(m, {aco::Neighbourhood::twenty_six, false});
  for (int k = 0; k < count; ++k) {
    // As Moving AI's generator does, problems a straight line solves are redrawn: up to 8 times,
    // so that an open world still gets its scenarios.
    aco::Cell start, goal;
    std::optional<double> length;
    for (int draw = 0; draw < 8; ++draw) {
      start = cell(part[rng.below(part.size())]);
      goal = start;
      while (goal == start) goal = cell(part[rng.below(part.size())]);
      const auto found = aco::astar(graph, graph.node(start), graph.node(goal));
      length = found ? std::optional<double>(found->length) : std::nullopt;
      if (!length) throw aco::Error(m.name() + ": a voxel of the largest part is unreachable (a bug)");
      if (*length > voxel_octile(start, goal) + 1e-9) break;
    }
    char line[160];
    std::snprintf(line, sizeof line, "%d %d %d %d %d %d %.8f %.3f\n", start.x, start.y, start.z, goal.x, goal.y, goal.z,
                  *length, *length / voxel_octile(start, goal));
    text += line;
  }
  return text;
}

}  // namespace

void write_voxel_world(const std::string& kind, const std::string& size_text, const std::string& seed_text,
                       const std::filesystem::path& dir, int count) {
  const VoxelSize s = parse_voxel_size(size_text);
  std::uint64_t seed = 0;
  if (seed_text.empty() || seed_text.find_first_not_of("0123456789") != std::string::npos || seed_text.size() > 18)
    throw aco::Error("--voxel: SEED must be a whole number, not '" + seed_text + "'");
  seed = std::stoull(seed_text);
  if (count < 0 || count > 100000) throw aco::Error("--voxel: COUNT must be 0 to 100000, not " + std::to_string(count));
  const std::string name = kind + std::to_string(s.width) + "x" + std::to_string(s.height) + "x" +
                           std::to_string(s.depth) + "-s" + seed_text;
  const std::vector<std::string> kinds = {"city", "forest", "caves"};
  const auto known = std::find(kinds.begin(), kinds.end(), kind);
  if (known == kinds.end()) throw aco::Error("--voxel: KIND must be city, forest or caves, not '" + kind + "'");
  // The kind joins the seed so that a city and a forest of one seed draw different numbers.
  aco::Rng rng(aco::splitmix64(seed) + static_cast<std::uint64_t>(known - kinds.begin()));
  const std::string file = name + ".3dmap";
  std::optional<aco::VoxelMap> world;
  if (kind == "city")
    world.emplace(city_world(s, rng, file));
  else if (kind == "forest")
    world.emplace(forest_world(s, rng, file));
  else
    world.emplace(cave_world(s, rng, file));
  std::ostringstream map_text;
  aco::write_movingai_voxels(*world, map_text);
  // Both texts made before either file is written: a world whose scenarios fail leaves no file.
  const std::string scenarios = count > 0 ? voxel_scenarios(*world, file, count, rng) : "";
  std::filesystem::create_directories(dir);
  write_file(dir / file, map_text.str());
  if (count > 0) write_file(dir / (file + ".3dscen"), scenarios);
  std::cout << file << ": " << s.width << "x" << s.height << "x" << s.depth << ", " << world->blocked_count()
            << " blocked, " << count << " scenarios\n";
}

}  // namespace mapgen
