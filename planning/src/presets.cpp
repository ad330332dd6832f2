#include "aco/planning/presets.hpp"

#include <algorithm>
#include <fstream>

#include "aco/error.hpp"
#include "aco/engine/install_layout.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/run_spec.hpp"

namespace aco {

std::filesystem::path preset_folder() { return install_layout().data / "presets"; }

std::vector<PresetInfo> list_presets() {
  std::vector<PresetInfo> presets;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(preset_folder(), error)) {
    if (entry.path().extension() != ".ini") continue;
    PresetInfo info{entry.path().stem().string(), ""};
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      if (line.rfind('#', 0) != 0) continue;
      info.summary = line.substr(std::min(line.size(), line.find_first_not_of("# ")));
      break;
    }
    presets.push_back(std::move(info));
  }
  std::sort(presets.begin(), presets.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return presets;
}

MapKind map_kind(const std::filesystem::path& map_or_scenario) {
  std::filesystem::path map = map_or_scenario;
  if (map.extension() == ".scen" || map.extension() == ".3dscen") map.replace_extension();
  const std::string extension = map.extension().string();
  if (extension == ".3dmap" || extension == ".bt" || extension == ".ot") return MapKind::voxel;
  return extension == ".asc" || extension == ".pgm" ? MapKind::terrain : MapKind::grid;
}

std::optional<bool> cells_have_z(const std::filesystem::path& map_or_scenario, const std::string& map_format) {
  if (map_kind(map_or_scenario) == MapKind::voxel) return true;
  if (map_format.empty()) return false;
  return std::nullopt;
}

std::string recommended_preset(MapKind kind) {
  switch (kind) {
    case MapKind::terrain:
      return "terrain";
    case MapKind::voxel:
      return "voxel";
    case MapKind::grid:
      break;
  }
  return "robust";
}

std::string default_preset(const std::filesystem::path& map_or_scenario) {
  return recommended_preset(map_kind(map_or_scenario));
}

PipelineSource PipelineSource::named(const std::string& preset, const std::string& config,
                                     const KeySpelling& spelling) {
  if (!preset.empty() && !config.empty())
    throw Error(spelling("config") + " and " + spelling("preset") + ": give one of them");
  PipelineSource source;
  source.preset = preset;
  source.config = config;
  return source;
}

PipelineSource PipelineSource::choose(const std::string& preset, const std::string& config, MapKind kind,
                                      const KeySpelling& spelling) {
  PipelineSource source = named(preset, config, spelling);
  if (preset.empty() && config.empty()) {
    source.preset = recommended_preset(kind);
    source.recommended = true;
  }
  return source;
}

std::filesystem::path PipelineSource::file() const {
  if (!config.empty()) return config;
  return preset.empty() ? std::filesystem::path() : preset_file(preset);
}

KeyedValues PipelineSource::keys() const {
  if (!config.empty()) return config_file_keys(config);
  return preset.empty() ? KeyedValues() : preset_keys(preset);
}

std::string PipelineSource::name(const KeySpelling& spelling) const {
  return config.empty() ? preset : "none (" + spelling("config") + " " + config.string() + ")";
}

std::string PipelineSource::description(const KeySpelling& spelling) const {
  if (!recommended) return name(spelling);
  const std::string kind = preset == "terrain" ? "height maps" : preset == "voxel" ? "voxel worlds" : "2D maps";
  return preset + " (the default for " + kind + "; " + spelling("preset") + " NAME for another, " +
         spelling("list-presets") + " for the papers')";
}

std::filesystem::path preset_file(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& preset : list_presets()) {
    if (preset.name == name) return preset_folder() / (name + ".ini");
    names.push_back(preset.name);
  }
  std::string message = "unknown preset '" + name + "'";
  if (const auto near = nearest(name, names); !near.empty()) message += "; did you mean '" + near + "'?";
  message += names.empty() ? " (no presets found" : " (available:";
  for (const auto& n : names) message += " " + n;
  throw Error(message + "; in " + preset_folder().string() + ")");
}

KeyedValues config_file_keys(const std::filesystem::path& file) {
  KeyedValues values;
  values.keys = read_config_file(file.string());
  for (const auto& [key, value] : values.keys) values.origins[key] = file.string();
  return values;
}

KeyedValues preset_keys(const std::string& name) { return config_file_keys(preset_file(name)); }

KeyedValues over_pipeline_file(const KeyedValues& file, const KeyedValues& changes) {
  KeyedValues in_file = file;
  for (const char* slot : kSlots)
    if (changes.keys.count(slot)) in_file.keys.emplace(slot, default_plugin(slot));
  return overlay(in_file, changes);
}

}  // namespace aco
