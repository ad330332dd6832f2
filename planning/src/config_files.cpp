// Keys from files: a config file's settings, and keys laid over others.
#include <algorithm>
#include <fstream>

#include "aco/engine/input_file.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/planning.hpp"
#include "aco/planning/run_spec.hpp"

namespace aco {

std::string KeyedValues::origin(const std::string& key) const {
  const auto it = origins.find(key);
  return it != origins.end() && !it->second.empty() ? it->second + ": " : "";
}

KeyedValues overlay(const KeyedValues& base, const KeyedValues& changes) {
  KeyedValues c = base;
  for (const auto& [key, value] : changes.keys)
    if (std::find(kSlots.begin(), kSlots.end(), key) != kSlots.end() && c.keys.count(key) && c.keys.at(key) != value)
      drop_slot(c.keys, key);  // its choice is set again below
  for (const auto& [key, value] : changes.keys) {
    c.keys[key] = value;
    c.origins[key] = changes.origins.count(key) ? changes.origins.at(key) : "";
  }
  // A pipeline's smoother (robust's taut) is for grid paths: a continuous planner the changes
  // choose takes the rest of the pipeline without it. Naming a smoother with it stays an error.
  const auto planner = changes.keys.find("planner");
  const auto known = aco::planners();
  const auto continuous = [&](const std::string& name) {
    return std::any_of(known.begin(), known.end(), [&](const Planner& p) { return p.name == name && p.continuous; });
  };
  if (planner != changes.keys.end() && !changes.keys.count("smoother") && continuous(planner->second))
    drop_slot(c.keys, "smoother");
  return c;
}

void drop_slot(Keys& keys, const std::string& slot) {
  const std::string prefix = slot + ".";
  std::erase_if(keys, [&](const auto& kv) { return kv.first == slot || kv.first.rfind(prefix, 0) == 0; });
}

// Our own reader, not Boost.ProgramOptions' parse_config_file: its error for a bad line gives
// no line number, and its what() loops forever on a line that contains "%invalid_line%".
std::vector<ConfigSetting> read_config_settings(const std::string& path) {
  check_input_file(path, "config");
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open the config file");
  const auto trim = [](std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return std::string();
    return std::string(s.substr(first, s.find_last_not_of(" \t\r") - first + 1));
  };
  std::vector<ConfigSetting> settings;
  std::string section;  // "update." under [update]
  int number = 0;
  for (std::string text; std::getline(in, text);) {
    ++number;
    const std::string line = trim(std::string_view(text).substr(0, text.find('#')));
    if (line.empty() || line.front() == ';') continue;
    const auto fail = [&](const std::string& what) {
      throw Error(path + ":" + std::to_string(number) + ": '" + line + "' " + what);
    };
    if (line.front() == '[' && line.back() == ']') {
      section = trim(std::string_view(line).substr(1, line.size() - 2));
      if (section.empty()) fail("names no section");
      if (section.back() != '.') section += '.';
      continue;
    }
    const auto equals = line.find('=');
    if (equals == std::string::npos) fail("is not a 'key = value' line");
    const std::string key = trim(std::string_view(line).substr(0, equals));
    if (key.empty()) fail("has no key before the '='");
    settings.push_back({section + key, trim(std::string_view(line).substr(equals + 1)), number});
  }
  return settings;
}

Keys read_config_file(const std::string& path) {
  Keys keys;
  std::map<std::string, int> first_line;
  for (const auto& setting : read_config_settings(path)) {
    if (const auto [first, fresh] = first_line.emplace(setting.key, setting.line); !fresh)
      throw Error(path + ":" + std::to_string(setting.line) + ": '" + setting.key + "' is set twice (first on line " +
                  std::to_string(first->second) + ")");
    keys.emplace(setting.key, setting.value);
  }
  return keys;
}

}  // namespace aco
