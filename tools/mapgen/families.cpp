// The benchmark map families: see families.hpp.
#include "families.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

#include "aco/error.hpp"
#include "shapes.hpp"

namespace mapgen {
namespace {

// A random spanning tree of an n x n grid of cells (depth-first, random order of neighbours):
// per cell, whether the edge to its right (h) and to its lower (v) neighbour is in the tree.
struct SpanningTree {
  std::vector<char> h, v;
};

SpanningTree random_spanning_tree(int n, aco::Rng& rng) {
  SpanningTree tree{std::vector<char>(n * n, 0), std::vector<char>(n * n, 0)};
  std::vector<char> visited(n * n, 0);
  std::vector<std::pair<int, int>> stack{{0, 0}};
  visited[0] = 1;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    std::vector<std::pair<int, int>> next;
    for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
      const int a = i + di, b = j + dj;
      if (a >= 0 && b >= 0 && a < n && b < n && !visited[b * n + a]) next.push_back({a, b});
    }
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const auto [a, b] = next[rng.below(next.size())];
    (a != i ? tree.h : tree.v)[std::min(j, b) * n + std::min(i, a)] = 1;
    visited[b * n + a] = 1;
    stack.push_back({a, b});
  }
  return tree;
}

// The 4-connected parts of the free cells of an n x n grid (blocked[i] != 0: blocked), each a list
// of cell indices in row-major order, in the order of their first cell.
std::vector<std::vector<int>> free_parts(const std::vector<char>& blocked, int n) {
  std::vector<int> label(blocked.size(), -1);
  std::vector<std::vector<int>> parts;
  for (int first = 0; first < n * n; ++first) {
    if (blocked[first] || label[first] >= 0) continue;
    std::vector<int> part{first};
    label[first] = static_cast<int>(parts.size());
    for (std::size_t k = 0; k < part.size(); ++k) {
      const int x = part[k] % n, y = part[k] / n;
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || v < 0 || u >= n || v >= n || blocked[v * n + u] || label[v * n + u] >= 0) continue;
        label[v * n + u] = label[first];
        part.push_back(v * n + u);
      }
    }
    std::sort(part.begin(), part.end());
    parts.push_back(std::move(part));
  }
  return parts;
}

// Frees the rectangle, corners inclusive.
void fill_free(aco::OccupancyGrid& g, int x0, int y0, int x1, int y1) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (g.contains({x, y})) g.set_blocked({x, y}, false);
}

// A room: the free rectangle [x0, x1] x [y0, y1], inclusive, walls or the map's edge around it.
struct Rect {
  int x0, y0, x1, y1;
};

// Divides the free rectangle `r` into rooms as hall_map says (binary space partition across the
// longer side, one-cell walls, rooms of `room` to 2 x `room` cells a side, one door of 1 to
// `max_door` cells per wall and a second with probability `loops`). Returns the rooms.
std::vector<Rect> divide_into_rooms(aco::OccupancyGrid& g, Rect r, int room, double loops, int max_door,
                                    aco::Rng& rng) {
  std::vector<Rect> rooms;
  const auto closed = [&](int x, int y) { return !g.contains({x, y}) || g.blocked({x, y}); };
  const std::function<void(int, int, int, int)> split = [&](int x0, int y0, int x1, int y1) {
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    const bool vertical = w >= h;  // a vertical wall splits the width
    const int side = vertical ? w : h;
    // Where the wall may stand: `room` cells on either side, not in front of a door.
    std::vector<int> places;
    if (side >= 2 * room + 1)
      for (int at = (vertical ? x0 : y0) + room; at <= (vertical ? x1 : y1) - room; ++at)
        if (vertical ? closed(at, y0 - 1) && closed(at, y1 + 1) : closed(x0 - 1, at) && closed(x1 + 1, at))
          places.push_back(at);
    if (places.empty()) {
      rooms.push_back({x0, y0, x1, y1});
      return;
    }
    const int at = places[rng.below(places.size())];
    const int length = vertical ? h : w;
    if (vertical)
      fill_rect(g, at, y0, at, y1);
    else
      fill_rect(g, x0, at, x1, at);
    const int doors = rng.uniform() < loops ? 2 : 1;
    for (int d = 0; d < doors; ++d) {
      const int width = std::min(length, 1 + static_cast<int>(rng.below(max_door)));
      const int along = static_cast<int>(rng.below(length - width + 1));
      for (int k = along; k < along + width; ++k)
        g.set_blocked(vertical ? aco::Cell{at, y0 + k} : aco::Cell{x0 + k, at}, false);
    }
    if (vertical) {
      split(x0, y0, at - 1, y1);
      split(at + 1, y0, x1, y1);
    } else {
      split(x0, y0, x1, at - 1);
      split(x0, at + 1, x1, y1);
    }
  };
  split(r.x0, r.y0, r.x1, r.y1);
  return rooms;
}

}  // namespace

aco::OccupancyGrid random_map(int size, double density, aco::Rng& rng, const std::string& name) {
  aco::OccupancyGrid g(size, size, name);
  scatter(g, rng, density, [](aco::Cell) { return false; });
  return g;
}

aco::OccupancyGrid room_map(int size, int room, double extra_doors, aco::Rng& rng, const std::string& name) {
  aco::OccupancyGrid g(size, size, name);
  const int rooms = size / room;
  for (int k = 1; k < rooms; ++k) {
    fill_rect(g, k * room - 1, 0, k * room - 1, size - 1);
    fill_rect(g, 0, k * room - 1, size - 1, k * room - 1);
  }
  // Wall between room (i, j) and its right (horizontal) or lower neighbour: open one cell of it.
  const auto open_door = [&](int i, int j, bool horizontal) {
    const int along = static_cast<int>(rng.below(room - 1));
    if (horizontal)
      g.set_blocked({(i + 1) * room - 1, j * room + along}, false);
    else
      g.set_blocked({i * room + along, (j + 1) * room - 1}, false);
  };
  const SpanningTree doors = random_spanning_tree(rooms, rng);
  for (int j = 0; j < rooms; ++j)
    for (int i = 0; i < rooms; ++i) {
      if (i + 1 < rooms && (doors.h[j * rooms + i] || rng.uniform() < extra_doors)) open_door(i, j, true);
      if (j + 1 < rooms && (doors.v[j * rooms + i] || rng.uniform() < extra_doors)) open_door(i, j, false);
    }
  return g;
}

aco::OccupancyGrid maze_map(int size, int corridor, double loops, aco::Rng& rng, const std::string& name) {
  aco::OccupancyGrid g(size, size, name);
  fill_rect(g, 0, 0, size - 1, size - 1);
  const int pitch = corridor + 1;
  const int cells = (size - 1) / pitch;
  // Clear a rectangle of corridor: cell (i, j), or the wall from it to its right/lower neighbour.
  const auto carve = [&](int i, int j, int di, int dj) {
    const int x0 = 1 + i * pitch, y0 = 1 + j * pitch;
    const int x1 = x0 + corridor - 1 + di * pitch, y1 = y0 + corridor - 1 + dj * pitch;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) g.set_blocked({x, y}, false);
  };
  const SpanningTree open = random_spanning_tree(cells, rng);
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      carve(i, j, 0, 0);
      if (open.h[j * cells + i]) carve(i, j, 1, 0);
      if (open.v[j * cells + i]) carve(i, j, 0, 1);
    }
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      if (i + 1 < cells && !open.h[j * cells + i] && rng.uniform() < loops) carve(i, j, 1, 0);
      if (j + 1 < cells && !open.v[j * cells + i] && rng.uniform() < loops) carve(i, j, 0, 1);
    }
  return g;
}

aco::OccupancyGrid cave_map(int size, int scale, double loops, aco::Rng& rng, const std::string& name) {
  const auto smooth = [](std::vector<char>& blocked, int n, int rounds) {
    std::vector<char> next(blocked.size());
    for (int round = 0; round < rounds; ++round) {
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          int count = 0;
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int u = x + dx, v = y + dy;
              count += u < 0 || v < 0 || u >= n || v >= n || blocked[v * n + u];
            }
          next[y * n + x] = count >= 5;
        }
      blocked.swap(next);
    }
  };
  const int coarse = size / scale;
  std::vector<char> cells(static_cast<std::size_t>(coarse) * coarse);
  for (int y = 0; y < coarse; ++y)
    for (int x = 0; x < coarse; ++x) {
      const bool border = x == 0 || y == 0 || x == coarse - 1 || y == coarse - 1;
      cells[y * coarse + x] = rng.uniform() < 0.5 || border;
    }
  smooth(cells, coarse, 5);
  std::vector<char> fine(static_cast<std::size_t>(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      fine[y * size + x] = cells[std::min(y / scale, coarse - 1) * coarse + std::min(x / scale, coarse - 1)];
  smooth(fine, size, 2);
  std::vector<std::vector<int>> caverns;
  for (auto& part : free_parts(fine, size)) {
    if (static_cast<int>(part.size()) >= scale * scale * 8)
      caverns.push_back(std::move(part));
    else
      for (int c : part) fine[c] = 1;
  }
  // The tunnel between two caverns: their nearest pair of cells, on a sample of each cavern's
  // cells (every cell would cost |A| x |B|; a sample of 400 is within a few cells of it).
  struct Tunnel {
    double length;
    int from, to;  // cells
    std::size_t a, b;  // caverns
  };
  const auto sample = [](const std::vector<int>& part) {
    std::vector<int> some;
    const std::size_t step = std::max<std::size_t>(1, part.size() / 400);
    for (std::size_t k = 0; k < part.size(); k += step) some.push_back(part[k]);
    return some;
  };
  std::vector<std::vector<int>> samples;
  for (const auto& cavern : caverns) samples.push_back(sample(cavern));
  std::vector<Tunnel> tunnels;
  for (std::size_t a = 0; a < caverns.size(); ++a)
    for (std::size_t b = a + 1; b < caverns.size(); ++b) {
      Tunnel best{std::numeric_limits<double>::infinity(), 0, 0, a, b};
      for (int p : samples[a])
        for (int q : samples[b]) {
          const double d = std::hypot(p % size - q % size, p / size - q / size);
          if (d < best.length) best = {d, p, q, a, b};
        }
      tunnels.push_back(best);
    }
  std::sort(tunnels.begin(), tunnels.end(), [](const Tunnel& x, const Tunnel& y) { return x.length < y.length; });
  // Kruskal's minimum spanning tree over the caverns; a tunnel left out joins a cavern that has
  // no extra tunnel yet with probability `loops`.
  std::vector<std::size_t> root(caverns.size());
  std::iota(root.begin(), root.end(), std::size_t{0});
  const std::function<std::size_t(std::size_t)> find = [&](std::size_t i) {
    return root[i] == i ? i : root[i] = find(root[i]);
  };
  std::vector<char> has_loop(caverns.size(), 0);
  const auto dig = [&](const Tunnel& t) {
    const double x0 = t.from % size, y0 = t.from / size, x1 = t.to % size, y1 = t.to / size;
    const int width = 2 + static_cast<int>(rng.below(3));
    const int steps = static_cast<int>(std::ceil(4.0 * t.length)) + 1;
    for (int k = 0; k <= steps; ++k) {
      const double x = x0 + (x1 - x0) * k / steps, y = y0 + (y1 - y0) * k / steps;
      for (int dy = 0; dy < width; ++dy)
        for (int dx = 0; dx < width; ++dx) {
          const int u = static_cast<int>(std::lround(x)) + dx - width / 2,
                    v = static_cast<int>(std::lround(y)) + dy - width / 2;
          if (u > 0 && v > 0 && u < size - 1 && v < size - 1) fine[v * size + u] = 0;
        }
    }
  };
  for (const Tunnel& t : tunnels) {
    if (find(t.a) != find(t.b)) {
      root[find(t.a)] = find(t.b);
      dig(t);
    } else if (!has_loop[t.a] && !has_loop[t.b] && t.length < 4.0 * scale && rng.uniform() < loops) {
      has_loop[t.a] = has_loop[t.b] = 1;
      dig(t);
    }
  }
  aco::OccupancyGrid g(size, size, name);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) g.set_blocked({x, y}, fine[y * size + x]);
  return g;
}

aco::OccupancyGrid hall_map(int size, int room, double loops, int max_door, aco::Rng& rng, const std::string& name) {
  aco::OccupancyGrid g(size, size, name);
  divide_into_rooms(g, {0, 0, size - 1, size - 1}, room, loops, max_door, rng);
  return g;
}

aco::OccupancyGrid office_map(int size, int room, double loops, aco::Rng& rng, const std::string& name) {
  aco::OccupancyGrid g(size, size, name);
  fill_rect(g, 0, 0, size - 1, size - 1);
  // The corridors across one axis: first cell and width, three of them, about a quarter apart.
  const auto corridors = [&] {
    std::vector<std::pair<int, int>> across;
    for (int k = 1; k <= 3; ++k) {
      const int jitter = static_cast<int>(rng.below(size / 8 + 1)) - size / 16;
      across.push_back({k * size / 4 + jitter, 2 + static_cast<int>(rng.below(3))});
    }
    return across;
  };
  const auto columns = corridors(), rows = corridors();
  for (const auto& [at, width] : columns) fill_free(g, at, 0, at + width - 1, size - 1);
  for (const auto& [at, width] : rows) fill_free(g, 0, at, size - 1, at + width - 1);
  // The blocks between the corridors along one axis: [first, last] cells, walls included.
  const auto blocks = [&](const std::vector<std::pair<int, int>>& across) {
    std::vector<std::pair<int, int>> spans;
    int from = 0;
    for (const auto& [at, width] : across) {
      spans.push_back({from, at - 1});
      from = at + width;
    }
    spans.push_back({from, size - 1});
    return spans;
  };
  for (const auto& [bx0, bx1] : blocks(columns))
    for (const auto& [by0, by1] : blocks(rows)) {
      // A wall against a corridor; the map's edge is wall enough.
      const Rect inside{bx0 + (bx0 > 0), by0 + (by0 > 0), bx1 - (bx1 < size - 1), by1 - (by1 < size - 1)};
      fill_free(g, inside.x0, inside.y0, inside.x1, inside.y1);
      const std::vector<Rect> offices = divide_into_rooms(g, inside, room, loops, 4, rng);
      // Doors onto a corridor: on an office's side along the block's wall (the map's edge has none).
      struct Side {
        bool vertical;  // a side along a column
        int at, from, to;  // the wall's column (row), the cells along it
      };
      std::vector<std::vector<Side>> on_corridor;  // per office that has such sides
      for (const Rect& o : offices) {
        std::vector<Side> sides;
        if (o.x0 == inside.x0 && bx0 > 0) sides.push_back({true, o.x0 - 1, o.y0, o.y1});
        if (o.x1 == inside.x1 && bx1 < size - 1) sides.push_back({true, o.x1 + 1, o.y0, o.y1});
        if (o.y0 == inside.y0 && by0 > 0) sides.push_back({false, o.y0 - 1, o.x0, o.x1});
        if (o.y1 == inside.y1 && by1 < size - 1) sides.push_back({false, o.y1 + 1, o.x0, o.x1});
        if (!sides.empty()) on_corridor.push_back(std::move(sides));
      }
      bool opened = false;
      for (std::size_t i = 0; i < on_corridor.size(); ++i) {
        const bool last_chance = !opened && i + 1 == on_corridor.size();
        if (rng.uniform() >= 0.5 && !last_chance) continue;
        const Side& s = on_corridor[i][rng.below(on_corridor[i].size())];
        const int length = s.to - s.from + 1;
        const int width = std::min(length, 1 + static_cast<int>(rng.below(4)));
        const int along = s.from + static_cast<int>(rng.below(length - width + 1));
        for (int k = along; k < along + width; ++k)
          g.set_blocked(s.vertical ? aco::Cell{s.at, k} : aco::Cell{k, s.at}, false);
        opened = true;
      }
    }
  return g;
}

}  // namespace mapgen
