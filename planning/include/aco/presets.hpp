#pragma once
// Named presets: config files in data/presets (installed: share/aco/presets), one per pipeline
// worth naming: the recommended ones (robust, terrain), each paper's (paper000 ... paper004) and
// the classic Ant System setting of the paper experiments (ant-system). acoplan and acosim take
// --preset NAME, experiment and scenario files `preset: NAME`; each is `--config` of its file.
#include <filesystem>
#include <string>
#include <vector>

#include "aco/run_spec.hpp"

namespace aco {

// The folder the presets are in.
std::filesystem::path preset_folder();

// The file of a named preset; an unknown name is an Error listing the known ones.
std::filesystem::path preset_file(const std::string& name);

struct PresetInfo {
  std::string name;
  std::string summary;  // the file's first comment line, without the '#'
};
// Every preset, by name.
std::vector<PresetInfo> list_presets();

// A config file's keys as experiment and scenario files take them (each key's origin: the file),
// and a named preset's.
KeyedValues config_file_keys(const std::filesystem::path& file);
KeyedValues preset_keys(const std::string& name);

// A pipeline file's keys (a preset's, a --config file's) under `changes`, by aco::overlay's rule
// with a slot the file leaves unset counting as its default plugin: where `changes` give a slot
// another plugin, the file's parameters of that slot are dropped, so `--preset robust
// --heuristic distance` is not refused for robust's heuristic.floor.
KeyedValues over_pipeline_file(const KeyedValues& file, const KeyedValues& changes);

// What a command without --config or --preset runs (the recommended pipeline for the map's
// kind): "terrain" for a height map (.asc, .pgm; a Moving AI .scen file by the map it names),
// "robust" for any other map, or none given.
std::string default_preset(const std::filesystem::path& map_or_scenario);

}  // namespace aco
