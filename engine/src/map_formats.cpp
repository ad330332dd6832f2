#include "aco/engine/map_formats.hpp"

#include <algorithm>

#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/map_reader.hpp"

namespace aco {
namespace {

bool ends_with(const std::string& text, const std::string& ending) {
  return text.size() >= ending.size() && text.compare(text.size() - ending.size(), ending.size(), ending) == 0;
}

bool claims(const std::vector<std::string>& extensions, const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const std::string& e) { return !e.empty() && ends_with(name, e); });
}

std::unique_ptr<Map> read_matrix_file(const std::filesystem::path& file, const TerrainOptions&) {
  return std::make_unique<OccupancyGrid>(load_matrix_map(file));
}

std::unique_ptr<MapReader> make_reader(PluginRegistry& registry, const std::string& name,
                                       const ParameterValues& parameters) {
  return registry.create<MapReader>("map", name, parameters);
}

ParameterValues defaults_of(PluginRegistry& registry, const std::string& name) {
  return resolve(registry.load("map", name).parameters(), {}, "map.");
}

}  // namespace

const std::vector<BuiltinMapFormat>& builtin_map_formats() {
  static const std::vector<BuiltinMapFormat> formats = {
      {"movingai",
       {".map"},
       "Moving AI .map grid ('type octile', '@' blocked)",
       [](const std::filesystem::path& file, const TerrainOptions&) -> std::unique_ptr<Map> {
         return std::make_unique<OccupancyGrid>(load_movingai_map(file));
       }},
      {"movingai3d",
       {".3dmap"},
       "Moving AI .3dmap voxel world ('voxel W H D', then one blocked voxel 'x y z' a line)",
       [](const std::filesystem::path& file, const TerrainOptions&) -> std::unique_ptr<Map> {
         return std::make_unique<VoxelMap>(load_movingai_voxels(file));
       }},
      {"ros",
       {".yaml", ".yml"},
       "ROS map_server YAML and its PGM image (unknown cells blocked)",
       [](const std::filesystem::path& file, const TerrainOptions&) -> std::unique_ptr<Map> {
         return std::make_unique<OccupancyGrid>(load_ros_map(file));
       }},
      {"esri_ascii",
       {".asc"},
       "ESRI ASCII grid of heights (terrain; max-slope applies)",
       [](const std::filesystem::path& file, const TerrainOptions& terrain) -> std::unique_ptr<Map> {
         return std::make_unique<TerrainMap>(load_esri_ascii(file, terrain));
       }},
      {"height_pgm",
       {".pgm"},
       "PGM image of heights (terrain; height-scale, cell-size, max-slope apply)",
       [](const std::filesystem::path& file, const TerrainOptions& terrain) -> std::unique_ptr<Map> {
         return std::make_unique<TerrainMap>(load_height_pgm(file, terrain));
       }},
      {"matrix", {}, "0/1 matrix text, one row per line (any file no other format claims)", &read_matrix_file},
  };
  return formats;
}

const BuiltinMapFormat* find_builtin_map_format(const std::string& name) {
  for (const auto& f : builtin_map_formats())
    if (f.name == name) return &f;
  return nullptr;
}

std::vector<std::string> map_format_names(const PluginRegistry& registry) {
  std::vector<std::string> names;
  for (const auto& f : builtin_map_formats()) names.push_back(f.name);
  for (const auto& name : registry.names("map"))
    if (!find_builtin_map_format(name)) names.push_back(name);
  return names;
}

std::string map_format_of(const std::filesystem::path& file, const std::string& format, PluginRegistry& registry,
                          const KeySpelling& spelling) {
  if (!format.empty()) {
    if (find_builtin_map_format(format) || registry.find("map", format)) return format;
    std::string message = "unknown map format '" + format + "' (formats:";
    for (const auto& name : map_format_names(registry)) message += " " + name;
    message += "; a map plugin adds one: " + spelling.plugin_list() + " shows them as map/NAME)";
    if (const auto near = nearest(format, map_format_names(registry)); !near.empty())
      message += "; did you mean '" + near + "'?";
    throw Error(message);
  }
  std::vector<std::string> claimants;  // "the built-in format movingai", "plugin map/x (FILE)"
  std::string chosen;
  for (const auto& f : builtin_map_formats())
    if (claims(f.extensions, file)) claimants.push_back("the built-in format " + f.name), chosen = f.name;
  for (const auto& plugin : registry.available()) {
    if (plugin.slot != "map" || !plugin.unusable.empty() || registry.find("map", plugin.name) != &plugin) continue;
    if (claims(make_reader(registry, plugin.name, defaults_of(registry, plugin.name))->extensions(), file))
      claimants.push_back("plugin map/" + plugin.name + " (" + plugin.file.string() + ")"), chosen = plugin.name;
  }
  if (claimants.size() > 1) {
    std::string message = file.string() + ": its ending is claimed by ";
    for (std::size_t i = 0; i < claimants.size(); ++i)
      message += (i == 0 ? "" : i + 1 == claimants.size() ? " and " : ", ") + claimants[i];
    const std::string given = spelling.to_give("map-format", "NAME"),
                      in_yaml = KeySpelling().to_give("map-format", "NAME");
    throw Error(message + "; choose one with " + given +
                (given == in_yaml ? "" : " (" + in_yaml + " in experiment and scenario files)"));
  }
  return chosen;
}

std::unique_ptr<Map> load_map(const std::filesystem::path& file, const TerrainOptions& terrain,
                              PluginRegistry& registry, const std::string& format, const ParameterValues& parameters,
                              const KeySpelling& spelling) {
  const std::string name = map_format_of(file, format, registry, spelling);
  if (name.empty()) {
    try {
      return read_matrix_file(file, terrain);
    } catch (const Error& e) {
      const std::string ending = file.extension().string();
      if (ending.empty() || ending == ".txt") throw;
      throw Error(std::string(e.what()) + " (read as a 0/1 matrix: no built-in format or map plugin claims '" + ending +
                  "'; a map plugin reads other formats: " + spelling.plugin_list() + " lists them as map/NAME, " +
                  spelling.to_give("map-format", "NAME") + " chooses one)");
    }
  }
  if (const BuiltinMapFormat* builtin = find_builtin_map_format(name)) return builtin->read(file, terrain);
  auto map = make_reader(registry, name, parameters.all().empty() ? defaults_of(registry, name) : parameters)
                 ->read(file, terrain);
  if (!map) throw Error("plugin map/" + name + " read " + file.string() + " but returned no map");
  return map;
}

std::unique_ptr<Map> load_map(const std::filesystem::path& file, const TerrainOptions& terrain) {
  for (const auto& f : builtin_map_formats())
    if (claims(f.extensions, file)) return f.read(file, terrain);
  return read_matrix_file(file, terrain);
}

}  // namespace aco
