// Keys -> RunSpec and back: every key checked once (resolve_run()), and the run as keys and JSON.
#include "aco/planning/run_spec.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <nlohmann/json.hpp>

#include "aco/engine/input_file.hpp"
#include "aco/engine/map_formats.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/planning.hpp"
#include "aco/planning/presets.hpp"
#include "aco/settings_table.hpp"

namespace aco {
namespace {

// Problem keys whose values are text, not a table's parameter: files and cells.
const std::vector<std::string> kProblemTexts = {"map", "map-format", "scen", "start", "goal"};

constexpr ParamSpec kScenIndex = {"scen-index", ParamType::integer, "0", "0:1000000000",
                                  "which problem of --scen to plan (0-based)"};

const SettingsTable<TerrainOptions>& terrain_table() {
  using T = TerrainOptions;
  static const SettingsTable<T> table({
      field("max-slope", &T::max_slope_deg, "0:90",
            "terrain maps (.asc, .pgm): steepest slope in degrees a step or a cell may have; 90 = no limit"),
      field("height-scale", &T::height_scale, "(0:1e12]", "PGM height images: height = grey value * X"),
      field("cell-size", &T::cell_size, "(0:1e12]",
            "PGM height images: horizontal size of a cell, in the heights' units (.asc files give their own)"),
  });
  return table;
}

const SettingsTable<GraphOptions>& graph_table() {
  using G = GraphOptions;
  static const SettingsTable<G> table({
      choice("neighbourhood", &G::neighbourhood, {"4", "8", "16", "6", "18", "26"},
             {Neighbourhood::four, Neighbourhood::eight, Neighbourhood::sixteen, Neighbourhood::six,
              Neighbourhood::eighteen, Neighbourhood::twenty_six},
             "moves per cell: 4 straight, 8 with diagonals, 16 with knight moves; in a voxel world 6 (faces), "
             "18 (and edges), 26 (and corners)"),
      field("corner-cutting", &G::corner_cutting, "",
            "let a diagonal step pass between two blocked side cells (the MATLAB code's rule; off = Moving AI rule)"),
  });
  return table;
}

bool is_slot(const std::string& key) { return std::find(kSlots.begin(), kSlots.end(), key) != kSlots.end(); }

bool in_table(std::span<const ParamSpec> table, const std::string& key) {
  return std::any_of(table.begin(), table.end(), [&](const ParamSpec& p) { return key == p.name; });
}

// Every key a run can have, for "did you mean" (plugin parameters of the chosen plugins).
std::vector<std::string> known_keys(const RunSpec& spec, PluginRegistry& registry) {
  std::vector<std::string> keys = kProblemTexts;
  keys.push_back(kScenIndex.name);
  keys.push_back(planner_parameter().name);
  for (auto table : {terrain_table().parameters(), graph_table().parameters(), colony_parameters()})
    for (const auto& p : table) keys.push_back(p.name);
  for (const char* slot : kSlots) {
    keys.push_back(slot);
    for (const auto& p : registry.load(slot, spec.pipeline.at(slot).plugin).parameters())
      keys.push_back(std::string(slot) + "." + p.name);
  }
  for (const auto& planner : planners_with_parameters())
    for (const auto& p : planner_parameters(planner)) keys.push_back(planner + "." + p.name);
  for (const auto& [name, value] : spec.problem.map_parameters.all())
    keys.push_back(std::string(kMapSlot) + "." + name);
  return keys;
}

}  // namespace

std::vector<std::pair<std::string, ParamValue>> run_values(const RunSpec& spec) {
  std::vector<std::pair<std::string, ParamValue>> keys;
  const ProblemSpec& p = spec.problem;
  if (!p.map.empty()) keys.emplace_back("map", p.map.string());
  if (!p.map_format.empty()) keys.emplace_back("map-format", p.map_format);
  if (!p.scen.empty()) {
    keys.emplace_back("scen", p.scen.string());
    keys.emplace_back("scen-index", std::int64_t{p.scen_index});
  }
  // Cells as the keys take them: "X,Y", and ",Z" in a voxel world (even on its ground layer, where
  // "X,Y" would be refused) or above the ground layer.
  const bool world = cells_have_z(!p.map.empty() ? p.map : p.scen, p.map_format).value_or(false);
  for (const auto& [key, cell] : {std::pair{"start", p.start}, std::pair{"goal", p.goal}})
    if (cell)
      keys.emplace_back(key, std::to_string(cell->x) + "," + std::to_string(cell->y) +
                                 (cell->z != 0 || world ? "," + std::to_string(cell->z) : ""));
  auto add = [&keys](const std::string& prefix, const ParameterValues& values) {
    for (const auto& [name, value] : values.all()) keys.emplace_back(prefix + name, value);
  };
  add(std::string(kMapSlot) + ".", p.map_parameters);
  add("", terrain_table().write(p.terrain));
  add("", graph_table().write(spec.graph));
  keys.emplace_back("planner", spec.planner);
  add(spec.planner + ".", spec.planner_parameters);
  add("", colony_values(spec.colony));
  for (const char* slot : kSlots) {
    const SlotSpec& choice = spec.pipeline.at(slot);
    keys.emplace_back(slot, choice.plugin);
    add(std::string(slot) + ".", choice.parameters);
  }
  return keys;
}

std::span<const ParamSpec> problem_parameters() {
  static const std::vector<ParamSpec> table = [] {
    std::vector<ParamSpec> t{kScenIndex};
    for (const auto& p : terrain_table().parameters()) t.push_back(p);
    return t;
  }();
  return table;
}

std::span<const ParamSpec> graph_parameters() { return graph_table().parameters(); }

const ParamSpec& planner_parameter() {
  // Values and help from the planner table: "aco,astar,..." and "aco = the colony; astar = ...".
  static const std::pair<std::string, std::string> names_and_help = [] {
    std::string names, help;
    for (const Planner& p : planners()) {
      if (!names.empty()) names += ",", help += "; ";
      names += p.name;
      help.append(p.name).append(" = ").append(p.help);
    }
    return std::pair{names, help};
  }();
  static const ParamSpec spec = {"planner", ParamType::categorical, "aco", names_and_help.first.c_str(),
                                 names_and_help.second.c_str()};
  return spec;
}

namespace {

// The problem keys, sorted from the others by the caller: map.NAME ones in `map_keys` without "map.".
ProblemSpec resolve_problem_keys(const Keys& problem, const Keys& map_keys, PluginRegistry& registry,
                                 const KeySpelling& spelling) {
  ProblemSpec p;
  if (problem.count("map")) p.map = problem.at("map");
  if (problem.count("scen")) p.scen = problem.at("scen");
  if (problem.count("start")) p.start = parse_cell(problem.at("start"), spelling("start"));
  if (problem.count("goal")) p.goal = parse_cell(problem.at("goal"), spelling("goal"));
  if (!p.scen.empty() && (p.start || p.goal))
    throw KeyError(spelling("scen"),
                   "give either " + spelling("scen or ") + spelling("start/") + spelling("goal, not both"));
  if (problem.count("scen-index") && p.scen.empty())
    throw KeyError(spelling("scen-index"), spelling("scen-index needs ") + spelling("scen"));
  // The map file: --map, or the scenario's (a scenario file misnamed is load_problem()'s to say).
  const bool scenario_file = p.scen.extension() == ".scen" || p.scen.extension() == ".3dscen";
  const std::filesystem::path map_file = !p.map.empty()  ? p.map
                                         : scenario_file ? scenario_map_file(p.scen)
                                                         : std::filesystem::path();
  if (!map_file.empty()) {
    const std::string format = problem.count("map-format") ? problem.at("map-format") : "";
    std::tie(p.map_format, p.map_parameters) = resolve_map_format(map_file, format, map_keys, registry, spelling);
    // A voxel world's cell without its z would silently be layer 0; a 2D map's has none.
    if (const std::optional<bool> with_z = cells_have_z(map_file, p.map_format))
      for (const char* end : {"start", "goal"}) {
        if (!problem.count(end)) continue;
        const std::string& text = problem.at(end);
        const bool has_z = std::count(text.begin(), text.end(), ',') == 2;
        if (*with_z && !has_z)
          throw KeyError(spelling(end), spelling(end) + " " + text + " has no z, but " + map_file.string() +
                                            " is a voxel world: give its cells as X,Y,Z");
        if (!*with_z && has_z)
          throw KeyError(spelling(end), spelling(end) + " " + text + " has a z, but " + map_file.string() +
                                            " is a 2D map: give its cells as X,Y (a voxel world's cells have a z)");
      }
  } else if (problem.count("map-format") || !map_keys.empty()) {
    const std::string key = problem.count("map-format") ? "map-format" : kMapSlot + ("." + map_keys.begin()->first);
    throw KeyError(spelling(key), spelling(key) + " needs a map (" + spelling("map or ") + spelling("scen)"));
  }
  Keys numbers;
  for (const auto& [key, value] : problem)
    if (in_table(problem_parameters(), key)) numbers[key] = value;
  const ParameterValues problem_values = resolve(problem_parameters(), numbers, spelling);
  p.scen_index = static_cast<int>(problem_values.integer("scen-index"));
  p.terrain = terrain_table().read(problem_values);
  return p;
}

bool is_problem_key(const std::string& key) {
  return std::find(kProblemTexts.begin(), kProblemTexts.end(), key) != kProblemTexts.end() ||
         in_table(problem_parameters(), key);
}

}  // namespace

ProblemSpec resolve_problem(const Keys& keys, PluginRegistry& registry, const KeySpelling& spelling) {
  Keys problem, map_keys;
  for (const auto& [key, value] : keys) {
    if (key.starts_with(std::string(kMapSlot) + ".")) {
      map_keys[key.substr(std::string(kMapSlot).size() + 1)] = value;
    } else if (is_problem_key(key)) {
      problem[key] = value;
    } else {
      std::vector<std::string> known(kProblemTexts.begin(), kProblemTexts.end());
      for (const auto& p : problem_parameters()) known.push_back(p.name);
      std::string message = "'" + spelling(key) + "' is not a key of a problem";
      if (const auto near = nearest(key, known); !near.empty()) message += "; did you mean '" + spelling(near) + "'?";
      throw KeyError(spelling(key), message);
    }
  }
  return resolve_problem_keys(problem, map_keys, registry, spelling);
}

RunSpec resolve_run(const Keys& keys, PluginRegistry& registry, const KeySpelling& spelling) {
  RunSpec spec;
  // Sorted by owner: the plugins first, since their tables decide which dotted keys exist.
  Keys problem, graph, colony, planner, map_keys;
  std::map<std::string, Keys> slots;
  if (const auto it = keys.find("planner"); it != keys.end())
    spec.planner = std::get<std::string>(parse_value(planner_parameter(), it->second, spelling("planner")));
  for (const char* slot : kSlots) {
    const auto it = keys.find(slot);
    spec.pipeline[slot].plugin = it != keys.end() ? it->second : default_plugin(slot);
    try {
      registry.load(slot, spec.pipeline[slot].plugin);
    } catch (const Error& e) {
      throw KeyError(spelling(slot), spelling(slot) + ": " + e.what());
    }
  }
  auto unknown = [&](const std::string& key, std::string message) {
    if (const auto near = nearest(key, known_keys(spec, registry)); !near.empty())
      message += "; did you mean '" + spelling(near) + "'?";
    throw KeyError(spelling(key), message);
  };
  for (const auto& [key, value] : keys) {
    if (key == "planner" || is_slot(key)) continue;
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
      const std::string owner = key.substr(0, dot), name = key.substr(dot + 1);
      if (is_slot(owner)) {
        slots[owner][name] = value;
      } else if (owner == kMapSlot) {
        map_keys[name] = value;
      } else if (const auto with = planners_with_parameters();
                 std::find(with.begin(), with.end(), owner) != with.end()) {
        if (owner != spec.planner)
          throw KeyError(spelling(key), spelling(key) + " is a parameter of the planner '" + owner +
                                            "', but the planner is '" + spec.planner + "'");
        planner[name] = value;
      } else {
        unknown(key, "unknown key '" + spelling(key) + "'");
      }
    } else if (is_problem_key(key)) {
      problem[key] = value;
    } else if (in_table(graph_parameters(), key)) {
      graph[key] = value;
    } else if (in_table(colony_parameters(), key)) {
      colony[key] = value;
    } else {
      unknown(key, "unknown key '" + spelling(key) + "'");
    }
  }

  spec.problem = resolve_problem_keys(problem, map_keys, registry, spelling);
  spec.graph = graph_table().read(resolve(graph_parameters(), graph, spelling));
  spec.colony = colony_settings(resolve(colony_parameters(), colony, spelling));
  spec.planner_parameters = resolve(planner_parameters(spec.planner), planner, spelling.within(spec.planner + "."));
  if (const auto check = find_planner(spec.planner).check) {
    try {
      check(spec.planner_parameters);
    } catch (const Error& e) {
      throw KeyError(spelling(spec.planner), e.what());
    }
  }
  if (const std::string& smoother = spec.pipeline.at("smoother").plugin;
      find_planner(spec.planner).continuous && smoother != default_plugin("smoother"))
    throw KeyError(spelling("smoother"), spelling("smoother: the planner '") + spec.planner +
                                             "' plans a continuous path, which takes no smoother (got '" + smoother +
                                             "'; leave smoother at '" + default_plugin("smoother") + "')");
  for (const char* slot : kSlots) {
    SlotSpec& choice = spec.pipeline[slot];
    const auto table = registry.load(slot, choice.plugin).parameters();
    choice.parameters = resolve(table, slots[slot], spelling.within(std::string(slot) + "."));
  }
  return spec;
}

Keys to_keys(const RunSpec& spec) {
  Keys keys;
  for (const auto& [key, value] : run_values(spec)) keys[key] = to_string(value);
  return keys;
}

std::vector<std::pair<std::string, ParamValue>> changed_values(const RunSpec& spec, PluginRegistry& registry) {
  // The reference: the same problem, planner and plugins, every other key left to its default.
  Keys choices;
  for (const auto& [key, value] : to_keys(spec))
    if (key == "planner" || is_slot(key) || key == kScenIndex.name ||
        std::find(kProblemTexts.begin(), kProblemTexts.end(), key) != kProblemTexts.end())
      choices[key] = value;
  Keys defaults = to_keys(resolve_run(choices, registry));
  defaults["planner"] = planner_parameter().default_value;
  for (const char* slot : kSlots) defaults[slot] = default_plugin(slot);
  std::vector<std::pair<std::string, ParamValue>> changed;
  for (const auto& [key, value] : run_values(spec))
    if (const auto it = defaults.find(key); it == defaults.end() || it->second != to_string(value))
      changed.emplace_back(key, value);
  return changed;
}

std::string to_json(const RunSpec& spec) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [key, value] : run_values(spec))
    j[key] = std::visit([](const auto& v) { return nlohmann::ordered_json(v); }, value);
  return j.dump();
}

std::string plugins_json(const RunSpec& spec, const PluginRegistry& registry) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const char* slot : kSlots) {
    const auto p = registry.provenance(slot, spec.pipeline.at(slot).plugin);
    j[slot] = {{"name", p.name}, {"version", p.version}, {"file", p.file}, {"sha256", p.sha256}, {"build", p.build}};
  }
  return j.dump();
}

RunSpec run_spec_from_json(const std::string& text, PluginRegistry& registry) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(std::string("a run's configuration is not valid JSON: ") + e.what());
  }
  if (!j.is_object()) throw Error("a run's configuration must be a JSON object of keys");
  Keys keys;
  for (const auto& [key, value] : j.items()) {
    if (value.is_string())
      keys[key] = value.get<std::string>();
    else if (value.is_boolean())
      keys[key] = value.get<bool>() ? "true" : "false";
    else if (value.is_number_integer())
      keys[key] = std::to_string(value.get<std::int64_t>());
    else if (value.is_number())
      keys[key] = to_string(ParamValue(value.get<double>()));
    else
      throw KeyError(key, "key '" + key + "' must be a string, a number or a boolean");
  }
  return resolve_run(keys, registry);
}

}  // namespace aco
