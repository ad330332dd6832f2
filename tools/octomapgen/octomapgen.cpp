// aco_octomapgen: the sample OctoMap of data/maps/octomap, made with the OctoMap library itself.
//
//   aco_octomapgen --out data/maps/octomap/hall.bt     # binary: every leaf free or occupied
//   aco_octomapgen --out data/maps/octomap/hall.ot     # full: the leaves' occupancy probabilities
//
// The scene, "hall": 8 x 6 x 3 metres at 0.25 m per voxel (32 x 24 x 12 voxels), x in [-4, 4),
// y in [-3, 3), z in [0, 3) in OctoMap's frame (z up):
//   floor     z in [0, 0.25) everywhere                                     occupied (768 voxels)
//   wall      x in [-1, -0.5), every y, z in [0.25, 3) ...                  occupied (504)
//   window    ... but for y in [-0.5, 0.5), z in [1.25, 2): a gap to fly through
//   box       x in [1, 2), y in [-2, -1), z in [0.25, 1.5)                  occupied (80)
//   tower     x in [1.5, 2.5), y in [1, 2), z in [0.25, 2.25)               occupied (128)
//   pillar    x in [-3, -2.5), y in [1.5, 2), z in [0.25, 3)                occupied (44)
//   foliage   x in [-3, -2), y in [-2, -1.5), z in [0.25, 0.75)             probability 0.6 (16)
//   shadow    x in [2.5, 4), y in [1, 3), z in [0.25, 3): behind the tower,  unknown (528; no leaf)
//   the rest  free (7148)
// With OctoMap's occupancy threshold 0.5 the foliage is occupied: 1540 occupied voxels. The
// binary file keeps only free or occupied (OctoMap's writeBinary() rounds each leaf to its maximum
// likelihood); the full file keeps the foliage's 0.6, so a threshold above it reads it as free.
//
// Deterministic: voxels set by their keys (no ray casting, no clock), so two runs write the same
// bytes.
#include <octomap/OcTree.h>

#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

namespace {

constexpr double kResolution = 0.25;
constexpr int kColumns = 32, kRows = 24, kLayers = 12;  // x, y, z
constexpr double kMinX = -4.0, kMinY = -3.0, kMinZ = 0.0;

struct Box {  // voxel indices, [lo, hi) on each axis
  int x0, x1, y0, y1, z0, z1;
  bool contains(int x, int y, int z) const { return x >= x0 && x < x1 && y >= y0 && y < y1 && z >= z0 && z < z1; }
};

constexpr Box kFloor{0, 32, 0, 24, 0, 1};
constexpr Box kWall{12, 14, 0, 24, 1, 12};
constexpr Box kWindow{12, 14, 10, 14, 5, 8};
constexpr Box kBox{20, 24, 4, 8, 1, 6};
constexpr Box kTower{22, 26, 16, 20, 1, 9};
constexpr Box kPillar{4, 6, 18, 20, 1, 12};
constexpr Box kFoliage{4, 8, 4, 6, 1, 3};
constexpr Box kShadow{26, 32, 16, 24, 1, 12};

octomap::OcTree hall() {
  octomap::OcTree tree(kResolution);
  const float occupied = tree.getClampingThresMaxLog(), free = tree.getClampingThresMinLog();
  const float foliage = octomap::logodds(0.6);
  for (int z = 0; z < kLayers; ++z)
    for (int y = 0; y < kRows; ++y)
      for (int x = 0; x < kColumns; ++x) {
        if (kShadow.contains(x, y, z)) continue;  // never observed: no leaf
        const octomap::point3d centre(float(kMinX + (x + 0.5) * kResolution), float(kMinY + (y + 0.5) * kResolution),
                                      float(kMinZ + (z + 0.5) * kResolution));
        octomap::OcTreeKey key;
        if (!tree.coordToKeyChecked(centre, key)) throw std::runtime_error("a voxel outside OctoMap's range");
        float value = free;
        if (kFoliage.contains(x, y, z))
          value = foliage;
        else if (kFloor.contains(x, y, z) || (kWall.contains(x, y, z) && !kWindow.contains(x, y, z)) ||
                 kBox.contains(x, y, z) || kTower.contains(x, y, z) || kPillar.contains(x, y, z))
          value = occupied;
        tree.setNodeValue(key, value, true);
      }
  tree.updateInnerOccupancy();
  tree.prune();
  return tree;
}

bool ends_with(const std::string& text, const std::string& ending) {
  return text.size() >= ending.size() && text.compare(text.size() - ending.size(), ending.size(), ending) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 || std::strcmp(argv[1], "--out") != 0 || !(ends_with(argv[2], ".bt") || ends_with(argv[2], ".ot"))) {
    std::cerr << "usage: aco_octomapgen --out FILE.bt|FILE.ot   (the scene 'hall'; see the source)\n";
    return 2;
  }
  try {
    const std::filesystem::path out = argv[2];
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    octomap::OcTree tree = hall();
    std::ofstream file(out, std::ios::binary);
    const bool written = ends_with(argv[2], ".bt") ? tree.writeBinary(file) : tree.write(file);
    file.close();
    if (!written || !file) throw std::runtime_error("cannot write " + out.string());
    std::cout << out.string() << ": " << tree.size() << " nodes, " << tree.getNumLeafNodes() << " leaves, "
              << std::filesystem::file_size(out) << " bytes\n";
  } catch (const std::exception& e) {
    std::cerr << "aco_octomapgen: error: " << e.what() << "\n";
    return 1;
  }
}
