#pragma once
// Run keys written in YAML, as acobench's experiment files and acosim's scenario files write
// them, with the file and line of every key for error messages. Also the small readers both
// files use: a scalar, a whole number, a boolean, a cell, a mapping with known keys.
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <map>
#include <string>
#include <vector>

#include "aco/map.hpp"
#include "aco/planning/run_spec.hpp"

namespace aco::yaml {

// A YAML file (`what`: "experiment", "scenario"), checked as an input file; errors name the file
// and, for malformed YAML, the line.
YAML::Node load_file(const std::filesystem::path& file, const std::string& what);

std::string where(const std::filesystem::path& file, const YAML::Node& node);  // "file:line"
[[noreturn]] void fail(const std::filesystem::path& file, const YAML::Node& node, const std::string& message);
std::string scalar(const std::filesystem::path& file, const YAML::Node& node, const std::string& key);
int integer(const std::filesystem::path& file, const YAML::Node& node, const std::string& key, int low);
bool boolean(const std::filesystem::path& file, const YAML::Node& node, const std::string& key);  // true or false
// [x, y]. An experiment's problem gives `with_z`, whether its map's cells have one
// (cells_have_z()): [x, y, z] in a voxel world, [x, y] on a 2D map, either where a map plugin's
// file does not say; and there also the command line's "x,y" or "x,y,z".
Cell cell(const std::filesystem::path& file, const YAML::Node& node, const std::string& key,
          std::optional<bool> with_z = false, bool texts = false);
// Fails on a key of `map` that is not allowed, naming the nearest allowed one.
void only_keys(const std::filesystem::path& file, const YAML::Node& map, const std::vector<std::string>& allowed,
               const std::string& what);

// The run keys of a mapping; a slot may be given as {plugin: NAME, param: value, ...}, and
// `config: FILE` (relative to `file`) or `preset: NAME` starts from an acoplan config file's keys,
// which the mapping's own keys override. Keys listed in `skip` are not run keys (a configuration's name).
aco::KeyedValues read_run_keys(const std::filesystem::path& file, const YAML::Node& node,
                               const std::vector<std::string>& skip);
// Whether a mapping of run keys names its pipeline (`config:` or `preset:`); one that does not
// runs the recommended preset.
bool names_pipeline(const YAML::Node& node);

}  // namespace aco::yaml
