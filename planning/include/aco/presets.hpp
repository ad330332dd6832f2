#pragma once
// Named presets: config files in data/presets (installed: share/aco/presets), one per pipeline
// worth naming: the recommended ones (robust, terrain), each paper's (paper000 ... paper004) and
// the classic Ant System setting of the paper experiments (ant-system). acoplan and acosim take
// --preset NAME, experiment and scenario files `preset: NAME`; each is `--config` of its file.
#include <filesystem>
#include <string>
#include <vector>

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

}  // namespace aco
