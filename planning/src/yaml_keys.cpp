#include "aco/planning/yaml_keys.hpp"

#include <algorithm>
#include <charconv>
#include <limits>

#include "aco/error.hpp"
#include "aco/engine/input_file.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/presets.hpp"
#include "aco/planning/run_spec.hpp"

namespace aco::yaml {

YAML::Node load_file(const std::filesystem::path& file, const std::string& what) {
  check_input_file(file, what);
  try {
    return YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    throw Error(file.string() + ": cannot open the " + what + " file");
  } catch (const YAML::Exception& e) {
    throw Error(file.string() + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + e.msg);
  }
}

std::string where(const std::filesystem::path& file, const YAML::Node& node) {
  return file.string() + ":" + std::to_string(node.Mark().line + 1);
}

void fail(const std::filesystem::path& file, const YAML::Node& node, const std::string& message) {
  throw Error(where(file, node) + ": " + message);
}

std::string scalar(const std::filesystem::path& file, const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar()) fail(file, node, "'" + key + "' must be a single value");
  return node.Scalar();
}

int integer(const std::filesystem::path& file, const YAML::Node& node, const std::string& key, int low) {
  const std::string text = scalar(file, node, key);
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < low)
    fail(file, node,
         "'" + key + "' must be a whole number from " + std::to_string(low) + " to " +
             std::to_string(std::numeric_limits<int>::max()) + ", not '" + text + "'");
  return value;
}

bool boolean(const std::filesystem::path& file, const YAML::Node& node, const std::string& key) {
  const std::string text = scalar(file, node, key);
  if (text == "true") return true;
  if (text == "false") return false;
  fail(file, node, "'" + key + "' must be true or false, not '" + text + "'");
}

Cell cell(const std::filesystem::path& file, const YAML::Node& node, const std::string& key, std::optional<bool> with_z,
          bool texts) {
  const std::string wanted = with_z == std::optional<bool>(false) ? "[x, y]"
                             : with_z                             ? "[x, y, z]"
                                                                  : "[x, y] (or [x, y, z] in a voxel world)";
  std::optional<Cell> c;
  std::size_t axes = 0;
  if (node.IsSequence() && (node.size() == 2 || node.size() == 3)) {
    axes = node.size();
    c = Cell{integer(file, node[0], key + "[0]", 0), integer(file, node[1], key + "[1]", 0),
             axes == 3 ? integer(file, node[2], key + "[2]", 0) : 0};
  } else if (texts && node.IsScalar()) {
    try {
      c = parse_cell(node.Scalar(), key);
      axes = static_cast<std::size_t>(std::count(node.Scalar().begin(), node.Scalar().end(), ',')) + 1;
    } catch (const Error&) {}
  }
  if (!c) fail(file, node, "'" + key + "' must be a cell " + wanted);
  // A voxel world's cell without its z would silently be layer 0; a 2D map's has none.
  if (with_z && *with_z && axes != 3)
    fail(file, node, "'" + key + "' has no z, but the problem's map is a voxel world: give its cells as " + wanted);
  if (with_z && !*with_z && axes != 2)
    fail(file, node,
         "'" + key + "' has a z, but the problem's map is a 2D map: give its cells as " + wanted +
             " (a voxel world's cells have a z)");
  return *c;
}

void only_keys(const std::filesystem::path& file, const YAML::Node& map, const std::vector<std::string>& allowed,
               const std::string& what) {
  if (!map.IsMap()) fail(file, map, what + " must be a mapping of keys to values");
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string message = "unknown key '" + key + "' in " + what;
      if (const auto near = nearest(key, allowed); !near.empty()) message += "; did you mean '" + near + "'?";
      fail(file, entry.first, message);
    }
  }
}

namespace {

// One key; a slot may be given as {plugin: NAME, param: value, ...}.
void read_key(const std::filesystem::path& file, const YAML::Node& name, const YAML::Node& value,
              aco::KeyedValues& out) {
  const std::string key = name.Scalar();
  if (value.IsMap()) {
    if (std::find(kSlots.begin(), kSlots.end(), key) == kSlots.end()) {
      std::string slots;
      for (const char* slot : kSlots) slots += (slots.empty() ? "" : ", ") + std::string(slot);
      fail(file, name,
           "'" + key + "' is not a slot; only slots (" + slots + ") take a {plugin: ..., parameter: ...} mapping");
    }
    for (const auto& inner : value) {
      const std::string param = inner.first.Scalar();
      const std::string full = param == "plugin" ? key : key + "." + param;
      out.keys[full] = scalar(file, inner.second, full);
      out.origins[full] = where(file, inner.first);
    }
    if (!value["plugin"]) fail(file, name, "slot '" + key + "' needs a 'plugin' key");
    return;
  }
  out.keys[key] = scalar(file, value, key);
  out.origins[key] = where(file, name);
}

}  // namespace

aco::KeyedValues read_run_keys(const std::filesystem::path& file, const YAML::Node& node,
                               const std::vector<std::string>& skip) {
  if (!node.IsMap()) fail(file, node, "a configuration must be a mapping of keys to values");
  aco::KeyedValues own;
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();
    if (key != "config" && key != "preset" && std::find(skip.begin(), skip.end(), key) == skip.end())
      read_key(file, entry.first, entry.second, own);
  }
  if (!names_pipeline(node)) return own;
  if (node["config"] && node["preset"]) fail(file, node["preset"], "'config' and 'preset': give one of them");
  const YAML::Node named = node["config"] ? node["config"] : node["preset"];
  aco::KeyedValues preset;
  try {
    preset = node["preset"] ? PipelineSource::named(scalar(file, named, "preset"), "").keys()
                            : PipelineSource::named(
                                  "", (file.parent_path() / scalar(file, named, "config")).lexically_normal().string())
                                  .keys();
  } catch (const Error& e) {
    fail(file, named, e.what());
  }
  return overlay(preset, own);
}

bool names_pipeline(const YAML::Node& node) { return node && node.IsMap() && (node["config"] || node["preset"]); }

}  // namespace aco::yaml
