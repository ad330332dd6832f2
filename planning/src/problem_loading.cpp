// A problem's map, start and goal: cells read and checked, the map read by its reader.
#include <charconv>

#include "aco/engine/map_formats.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/planning/run_spec.hpp"

namespace aco {

Cell parse_cell(const std::string& text, const std::string& key) {
  // "X,Y", or "X,Y,Z" in a voxel world.
  std::vector<int> values;
  std::string_view rest(text);
  bool valid = true;
  for (;;) {
    const auto comma = rest.find(',');
    const std::string_view part = rest.substr(0, comma);
    int v = 0;
    auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    valid = valid && !part.empty() && ec == std::errc() && p == part.data() + part.size();
    values.push_back(v);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  if (!valid || values.size() < 2 || values.size() > 3)
    throw KeyError(key, key + ": '" + text + "' is not a cell; expected X,Y such as 3,7 (X,Y,Z in a voxel world)");
  return {values[0], values[1], values.size() == 3 ? values[2] : 0};
}

void check_cell(const Map& map, Cell c, const std::string& what) {
  if (!map.contains(c)) {
    std::string size = std::to_string(map.width()) + "x" + std::to_string(map.height());
    size += map.volumetric() ? std::string("x") + std::to_string(map.depth()) + " voxel world " : " map ";
    throw Error(what + " " + map.describe(c) + " is outside the " + size + map.name());
  }
  if (!map.passable(c))
    throw Error(what + " " + map.describe(c) + " is blocked: " + map.blocked_reason(c) + " (" + map.name() + ")");
}

void check_ends(const Map& map, Cell start, Cell goal, const std::function<void(const Map&)>& check_map) {
  if (check_map) check_map(map);
  check_cell(map, start, "start");
  check_cell(map, goal, "goal");
}

std::pair<std::string, ParameterValues> resolve_map_format(const std::filesystem::path& file, const std::string& format,
                                                           const Keys& keys, PluginRegistry& registry,
                                                           const KeySpelling& spelling) {
  const std::string option = spelling("map-format");
  std::string chosen;
  try {
    chosen = map_format_of(file, format, registry, spelling);
  } catch (const Error& e) {
    throw KeyError(format.empty() ? spelling("map") : option, format.empty() ? e.what() : option + ": " + e.what());
  }
  if (chosen.empty() || find_builtin_map_format(chosen)) {
    if (!keys.empty())
      throw KeyError(spelling(std::string(kMapSlot) + "." + keys.begin()->first),
                     spelling(std::string(kMapSlot) + "." + keys.begin()->first) + ": the built-in map format '" +
                         (chosen.empty() ? "matrix" : chosen) + "' of " + file.string() +
                         " takes no parameters (map.NAME keys are a map plugin's)");
    return {format, {}};
  }
  const auto table = registry.load(kMapSlot, chosen).parameters();
  return {chosen, resolve(table, keys, spelling.within(std::string(kMapSlot) + "."))};
}

std::unique_ptr<Map> load_problem_map(const ProblemSpec& spec, PluginRegistry* registry, const KeySpelling& spelling) {
  const std::filesystem::path file = spec.map.empty() && !spec.scen.empty() ? scenario_map_file(spec.scen) : spec.map;
  if (file.empty()) throw Error("a problem needs a map with start and goal, or a scenario");
  if (registry) return load_map(file, spec.terrain, *registry, spec.map_format, spec.map_parameters, spelling);
  if (!spec.map_format.empty() && !find_builtin_map_format(spec.map_format))
    throw Error(file.string() + ": map format '" + spec.map_format +
                "' is a map plugin, and no plugin registry was given");
  if (const auto* builtin = find_builtin_map_format(spec.map_format)) return builtin->read(file, spec.terrain);
  return load_map(file, spec.terrain);
}

LoadedProblem load_problem(const ProblemSpec& spec, PluginRegistry* registry,
                           const std::function<void(const Map&)>& check_map, const KeySpelling& spelling) {
  LoadedProblem p;
  if (!spec.scen.empty()) {
    const auto scenarios = load_scenarios(spec.scen);
    if (spec.scen_index >= static_cast<int>(scenarios.size()))
      throw Error("scen-index " + std::to_string(spec.scen_index) + " is out of range: " + spec.scen.string() +
                  " has " + std::to_string(scenarios.size()) + " scenarios");
    const Scenario& s = scenarios[spec.scen_index];
    p.map = load_problem_map(spec, registry, spelling);
    if (s.volumetric != p.map->volumetric())
      throw Error(spec.scen.string() + ": its scenarios are for " + (s.volumetric ? "a voxel world" : "a 2D map") +
                  ", but " + p.map->name() + " is " + (p.map->volumetric() ? "a voxel world" : "a 2D map"));
    if (!s.volumetric && (p.map->width() != s.width || p.map->height() != s.height))
      throw Error(spec.scen.string() + ": scenario " + std::to_string(spec.scen_index) + " is for a " +
                  std::to_string(s.width) + "x" + std::to_string(s.height) + " map, but " + p.map->name() + " is " +
                  std::to_string(p.map->width()) + "x" + std::to_string(p.map->height()));
    p.start = s.start;
    p.goal = s.goal;
  } else {
    if (spec.map.empty() || !spec.start || !spec.goal)
      throw Error("a problem needs a map with start and goal, or a scenario");
    p.map = load_problem_map(spec, registry, spelling);
    p.start = *spec.start;
    p.goal = *spec.goal;
  }
  check_ends(*p.map, p.start, p.goal, check_map);
  return p;
}

}  // namespace aco
