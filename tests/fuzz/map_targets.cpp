#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "aco/engine/map_io.hpp"
#include "targets.hpp"

namespace fuzz {
namespace {

class Scratch {
 public:
  Scratch() {
    std::string pattern = (std::filesystem::temp_directory_path() / "aco-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder");
    root_ = pattern;
    std::filesystem::create_directory(root_ / "experiments");
    for (const char* folder : {"maps", "scenarios", "presets", "terrain"})
      std::filesystem::create_directory_symlink(std::filesystem::path(ACO_FUZZ_DATA_DIR) / folder, root_ / folder);
  }
  ~Scratch() {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  const std::filesystem::path& root() const { return root_; }

 private:
  std::filesystem::path root_;
};

std::istringstream stream(std::string_view input) { return std::istringstream(std::string(input)); }

void movingai_map(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_movingai_map(in, "fuzz.map");
  });
}

void movingai_scen(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_scenarios(in, "fuzz.map.scen");
  });
}

void matrix_map(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_matrix_map(in, "fuzz.txt");
  });
}

void ros_map(std::string_view input) {
  const auto split = input.find(kRosSeparator);
  const std::string_view yaml = input.substr(0, split);
  const std::string_view pgm =
      split == std::string_view::npos ? std::string_view() : input.substr(split + kRosSeparator.size());
  write_scratch_file("map.pgm", pgm);
  const auto file = write_scratch_file("map.yaml", yaml);
  expect_no_crash([&] { aco::load_ros_map(file); });
}

void esri_ascii(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_esri_ascii(in, "fuzz.asc", {});
  });
}

void pgm_heights(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_height_pgm(in, "fuzz.pgm", {});
  });
}

void movingai_voxels(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_movingai_voxels(in, "fuzz.3dmap");
  });
}

void voxel_scen(std::string_view input) {
  expect_no_crash([&] {
    auto in = stream(input);
    aco::read_voxel_scenarios(in, "fuzz.3dmap.3dscen");
  });
}

constexpr Target kTargets[] = {
    {"movingai_map", movingai_map},       {"movingai_scen", movingai_scen},
    {"matrix_map", matrix_map},           {"ros_map", ros_map},
    {"esri_ascii", esri_ascii},           {"pgm_heights", pgm_heights},
    {"movingai_voxels", movingai_voxels}, {"voxel_scen", voxel_scen},
};

}  // namespace

std::filesystem::path write_scratch_file(const std::string& relative, std::string_view bytes) {
  static const Scratch scratch;
  const auto file = scratch.root() / relative;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + file.string());
  return file;
}

std::span<const Target> map_targets() { return kTargets; }

const Target& find_target(const std::string& name, std::span<const Target> targets) {
  for (const Target& t : targets)
    if (name == t.name) return t;
  throw std::invalid_argument("no fuzz target '" + name + "'");
}

}  // namespace fuzz
