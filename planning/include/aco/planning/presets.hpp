#pragma once
// Named presets: config files in data/presets (installed: share/aco/presets), one per pipeline
// worth naming: the recommended ones (robust, terrain), each paper's (paper000 ... paper004) and
// the classic Ant System setting of the paper experiments (ant-system). acoplan and acosim take
// --preset NAME, experiment and scenario files `preset: NAME`; each is `--config` of its file.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "aco/planning/run_spec.hpp"

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

// The kinds of map whose recommended pipelines differ: occupancy grids, height maps, voxel worlds.
enum class MapKind { grid, terrain, voxel };
// By the file's ending ("terrain" for .asc and .pgm, "voxel" for .3dmap, .bt and .ot; a Moving AI
// .scen or .3dscen file by the map it names).
MapKind map_kind(const std::filesystem::path& map_or_scenario);
// Whether a map file's cells have a z: true for a voxel world (map_kind()), false for a map of a
// built-in 2D format (`map_format` empty), none for a map plugin's other files, whose kind shows
// only once they are read.
std::optional<bool> cells_have_z(const std::filesystem::path& map_or_scenario, const std::string& map_format);

// The preset a run naming no pipeline runs: robust, terrain or voxel.
std::string recommended_preset(MapKind kind);
// The same for a map file (or a scenario's map); "robust" for none given.
std::string default_preset(const std::filesystem::path& map_or_scenario);

// Where a run's pipeline keys come from: the preset or config file the user named, or, when they
// named neither, the recommended preset for the map's kind. Every front end chooses through here
// (acoplan, acosim, Python; acobench's experiments and acosim's scenarios name theirs in YAML).
struct PipelineSource {
  std::string preset;  // the preset run ("" with a config file)
  std::filesystem::path config;  // the config file run, if any
  bool recommended = false;  // named by neither: the map kind's recommended preset

  // `preset` and `config` as given ("" = not given; giving both is an Error naming them
  // as `spelling` writes keys); `kind` picks the preset when neither is given.
  static PipelineSource choose(const std::string& preset, const std::string& config, MapKind kind,
                               const KeySpelling& spelling = {});
  // The named one alone (acosim's --preset and --config go over a scenario's own pipeline):
  // nothing named gives no keys.
  static PipelineSource named(const std::string& preset, const std::string& config, const KeySpelling& spelling = {});

  std::filesystem::path file() const;  // the preset's or config file; empty if nothing named
  KeyedValues keys() const;  // the file's keys; none if nothing named
  // "robust", "paper001", or "none (--config FILE)" with acoplan's spelling "--".
  std::string name(const KeySpelling& spelling = {}) const;
  // name(), and for a recommended preset why it runs: "robust (the default for 2D maps; --preset
  // NAME for another, --list-presets for the papers')", acoplan's "preset:" line.
  std::string description(const KeySpelling& spelling = {}) const;
};

}  // namespace aco
