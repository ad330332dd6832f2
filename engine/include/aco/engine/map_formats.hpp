#pragma once
// Which reader reads a map file: one of the built-in formats (aco/engine/map_io.hpp) or a map plugin
// (slot map, aco/map_reader.hpp). A file's reader is the format named (--map-format NAME), else
// the one claiming the file's ending, else the 0/1 matrix. Two claiming one ending is an Error
// naming both; nothing is chosen silently.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "aco/map.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/terrain.hpp"

namespace aco {

struct BuiltinMapFormat {
  std::string name;  // as --map-format takes it, and listed as map/NAME
  std::vector<std::string> extensions;  // the file endings it claims (none: matrix, the fallback)
  std::string summary;
  std::unique_ptr<Map> (*read)(const std::filesystem::path& file, const TerrainOptions& terrain);
};

// movingai (.map), movingai3d (.3dmap), ros (.yaml, .yml), esri_ascii (.asc), height_pgm (.pgm), matrix.
const std::vector<BuiltinMapFormat>& builtin_map_formats();
const BuiltinMapFormat* find_builtin_map_format(const std::string& name);

// The format that reads `file`: `format` if not empty (a built-in's or a map plugin's name; an
// Error listing both kinds if it is neither), else the built-in format or map plugin claiming the
// file's ending (map plugins are asked with their default parameters), else "" (the 0/1 matrix).
// Messages name the keys as `spelling` writes them.
std::string map_format_of(const std::filesystem::path& file, const std::string& format, PluginRegistry& registry,
                          const KeySpelling& spelling = "--");

// Every map format's name, built-in first, then the map plugins found.
std::vector<std::string> map_format_names(const PluginRegistry& registry);

// The map in `file`, read by `format` (map_format_of()) with `parameters` (a map plugin's table,
// resolved; a built-in's is empty). A file no format claims is read as the 0/1 matrix, and if it
// is none, the Error says that map plugins read other formats.
std::unique_ptr<Map> load_map(const std::filesystem::path& file, const TerrainOptions& terrain,
                              PluginRegistry& registry, const std::string& format = "",
                              const ParameterValues& parameters = {}, const KeySpelling& spelling = "--");

}  // namespace aco
