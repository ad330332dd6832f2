// Writes the pictures of a voxel world for the tests and the docs: the 3D page and the SVG.
//   aco_voxel_sample small|city PAGE.html PICTURE.svg
// small: 16 x 12 x 8, a ground, a wall across the world and a pillar, and a known path over the
// wall (tests/voxel_page_in_chromium.sh checks its screenshot). city: 64 x 64 x 32, a ground and
// towers of pseudo-random heights (a fixed generator: the same bytes every time), the size the
// docs quote.
#include <cstdint>
#include <iostream>
#include <string>

#include "aco/voxel.hpp"
#include "aco/drawing/voxel_html.hpp"
#include "aco/drawing/voxel_svg.hpp"

namespace {

void block(aco::VoxelMap& world, int x0, int x1, int y0, int y1, int z0, int z1) {
  for (int z = z0; z <= z1; ++z)
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) world.set_blocked({x, y, z}, true);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || (std::string(argv[1]) != "small" && std::string(argv[1]) != "city")) {
    std::cerr << "usage: aco_voxel_sample small|city PAGE.html PICTURE.svg\n";
    return 2;
  }
  const bool small = std::string(argv[1]) == "small";
  aco::VoxelMap world(small ? 16 : 64, small ? 12 : 64, small ? 8 : 32, small ? "small voxel world" : "voxel city");
  aco::VoxelWorldView view{world};
  aco::VoxelSvgStyle style;
  if (small) {
    block(world, 0, 15, 0, 11, 0, 0);  // the ground
    block(world, 8, 8, 0, 11, 1, 4);  // a wall across the world, 4 layers high
    block(world, 3, 4, 2, 3, 1, 6);  // a pillar
    view.start = aco::Cell{2, 6, 1};
    view.goal = aco::Cell{13, 6, 1};
    view.grid_path = {{2, 6, 1}, {3, 6, 2}, {4, 6, 3},  {5, 6, 4},  {6, 6, 5},  {7, 6, 5},
                      {8, 6, 5}, {9, 6, 5}, {10, 6, 4}, {11, 6, 3}, {12, 6, 2}, {13, 6, 1}};
    view.path = {{2, 6, 1}, {6, 6, 5}, {9, 6, 5}, {13, 6, 1}};
    for (const auto& c : view.grid_path) view.pheromone.push_back({c, 1.0 + c.x});
    view.title = "small voxel world: over the wall";
    style.slices = {1, 5};
  } else {
    block(world, 0, 63, 0, 63, 0, 0);
    std::uint32_t state = 42;
    auto next = [&state] { return state = state * 1664525u + 1013904223u; };
    for (int by = 2; by < 62; by += 8)
      for (int bx = 2; bx < 62; bx += 8) {
        const int top = 1 + static_cast<int>(next() >> 16) % 30;  // a tower 1 to 30 layers high
        if ((next() >> 16) % 4 == 0) continue;  // a square with no tower
        block(world, bx, bx + 4, by, by + 4, 1, top);
      }
    view.start = aco::Cell{0, 0, 1};
    view.goal = aco::Cell{63, 63, 20};
    view.path = {{0, 0, 1}, {7, 7, 10}, {39, 41, 12}, {63, 63, 20}};
    style.slices = aco::spread_layers(world.depth(), 4);
  }
  aco::write_voxel_html(argv[2], view);
  aco::write_voxel_svg(argv[3], view, style);
  const auto surface = aco::VoxelSurface(world, aco::VoxelHtmlOptions{}.max_cubes);
  std::cout << world.width() << "x" << world.height() << "x" << world.depth() << ": " << world.blocked_count()
            << " blocked voxels, " << surface.surface_voxels() << " on the surface\n";
}
