#include "aco/presets.hpp"

#include <algorithm>
#include <fstream>

#include "aco/error.hpp"
#include "aco/install_layout.hpp"
#include "aco/parameters.hpp"

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
      info.summary = line.substr(line.find_first_not_of("# ") == std::string::npos ? line.size() : line.find_first_not_of("# "));
      break;
    }
    presets.push_back(std::move(info));
  }
  std::sort(presets.begin(), presets.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return presets;
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

}  // namespace aco
