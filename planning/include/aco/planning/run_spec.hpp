#pragma once
// One run's whole configuration as typed, resolved values: the problem, the graph, the planner
// and its parameters, the colony settings, and one plugin per slot with its parameters. Hosts
// only produce keys (acoplan from its command line and config file, acobench from experiment
// files); resolve_run() checks every key and value, once. Nothing after it parses text.
//
// Keys are acoplan's options without the dashes, and the same everywhere (INI of
// --print-config, --json, acobench's experiment files and database): "map", "start",
// "max-slope", "neighbourhood", "planner", "ants", "update", "update.rho", "ifwa.radius".
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "aco/engine/colony.hpp"
#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/map.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/terrain.hpp"

namespace aco {

struct ProblemSpec {
  std::filesystem::path map;  // empty: none given (acoplan then plans its bundled demo)
  std::filesystem::path scen;  // Moving AI scenario file; empty: start and goal are cells
  int scen_index = 0;
  std::optional<Cell> start;
  std::optional<Cell> goal;
  TerrainOptions terrain;
  // The map's reader (aco/engine/map_formats.hpp): map-format as given, or the map plugin claiming the
  // file's ending; "" for a built-in format chosen by the ending (so that runs on bundled maps
  // keep the keys they had). A map plugin's parameters (map.NAME keys), every one; else empty.
  std::string map_format;
  ParameterValues map_parameters;
};

struct RunSpec {
  ProblemSpec problem;
  GraphOptions graph;
  std::string planner = "aco";
  ParameterValues planner_parameters;  // the planner's own table (empty for aco and astar)
  ColonySettings colony;
  PipelineSpec pipeline;  // every slot of kSlots
};

using Keys = std::map<std::string, std::string>;

// The owner of a map plugin's parameter keys (map.resolution): the plugins' slot "map".
inline constexpr const char* kMapSlot = "map";

// Keys with where each was written ("file:line", or a config file's path), for messages.
struct KeyedValues {
  Keys keys;
  std::map<std::string, std::string> origins;
  std::string origin(const std::string& key) const;  // "file:line: ", or "" if unknown
};

// Removes a slot's choice and its parameters ("smoother", "smoother.*") from keys.
void drop_slot(Keys& keys, const std::string& slot);

// `changes` over `base`; another plugin for a slot drops the base's parameters of that slot.
KeyedValues overlay(const KeyedValues& base, const KeyedValues& changes);

// The problem keys: map, map-format, scen, scen-index, start, goal (text), max-slope, height-scale,
// cell-size, and a map plugin's map.NAME.
std::span<const ParamSpec> problem_parameters();
// The graph keys: neighbourhood, corner-cutting.
std::span<const ParamSpec> graph_parameters();
// The planner key, its values from planner_names().
const ParamSpec& planner_parameter();

// The problem keys alone -> ProblemSpec, checked as resolve_run() checks them; any other key is a
// KeyError. Start and goal may be missing (a map to look at needs none); load_problem() asks for them.
ProblemSpec resolve_problem(const Keys& keys, PluginRegistry& registry, const KeySpelling& spelling = {});

// Keys -> RunSpec. Every key must be known and every value valid for its table; slots default
// to default_plugin(), every other key to its table's default. `spelling` writes keys in messages
// ("--ants" for acoplan, "ants" for YAML, Python's keywords); a failure throws KeyError naming the key (the nearest
// valid key when it is unknown).
RunSpec resolve_run(const Keys& keys, PluginRegistry& registry, const KeySpelling& spelling = {});

// Every key of a run with its resolved value, defaults included, in a readable order (problem,
// graph, planner, colony, slots, each slot's parameters after it); resolve_run() of them gives
// the same RunSpec. Problem keys that are not set (no map, no scen...) are left out.
std::vector<std::pair<std::string, ParamValue>> run_values(const RunSpec& spec);
Keys to_keys(const RunSpec& spec);  // the same as text

// The keys of run_values() whose value differs from the engine's default for the same problem:
// a planner or plugin other than the default, and every other key that differs from its table's
// default (a plugin's parameters from that plugin's own table, whichever plugin the slot has), in
// run_values()'s order. Presets and config files are no reference: robust's q0 = 0.7 is a change.
std::vector<std::pair<std::string, ParamValue>> changed_values(const RunSpec& spec, PluginRegistry& registry);

// The RunSpec as one JSON object with typed values ({"ants": 50, "update": "acs",
// "update.rho": 0.3, ...}, the keys of to_keys()), and back (checked by resolve_run()).
std::string to_json(const RunSpec& spec);
RunSpec run_spec_from_json(const std::string& json, PluginRegistry& registry);

// Which plugin binary fills each slot of the run, as one JSON object
// ({"update": {"name": "acs", "version": "1.0", "file": "...", "sha256": "...", "build": "optimised"},
// ...}; build: ACO_BUILD_OPTIMISATION as the plugin was compiled): what a run's output records so
// that a result can be traced to the code that made it.
std::string plugins_json(const RunSpec& spec, const PluginRegistry& registry);

// One "key = value" line of a config file; under a [section] line the key is "section.key".
struct ConfigSetting {
  std::string key;
  std::string value;
  int line;  // 1-based
};

// The settings of a config file as acoplan --config reads it, in file order, unchecked:
// key = value lines, [section] lines, blank lines, '#' comments (to the end of any line) and
// ';' comment lines. Any other line is an Error naming the file and the line.
std::vector<ConfigSetting> read_config_settings(const std::string& path);

// The same as keys for resolve_run(), which checks them; a key set twice is an Error.
Keys read_config_file(const std::string& path);

struct LoadedProblem {
  std::unique_ptr<Map> map;
  Cell start;
  Cell goal;
};
// The map file's reader and its parameters: `format` if given, else the file's ending's
// (aco::map_format_of(); "" for a built-in format so chosen); `keys` the map.NAME values without
// "map.", checked against the map plugin's table (a built-in format takes none). Errors are
// KeyErrors naming the key as `spelling` writes it.
std::pair<std::string, ParameterValues> resolve_map_format(const std::filesystem::path& file, const std::string& format,
                                                           const Keys& keys, PluginRegistry& registry,
                                                           const KeySpelling& spelling = {});

// The problem's map (its file, or its scenario's) read by its reader with its terrain options (map
// plugins from `registry`; without one, built-in formats only). Every loader of a problem's map goes
// through here: a run, an acobench trial, the report's pictures, Python's Map.load(). Messages name
// keys as `spelling` writes them.
std::unique_ptr<Map> load_problem_map(const ProblemSpec& problem, PluginRegistry* registry = nullptr,
                                      const KeySpelling& spelling = "--");

// Loads the map with the terrain options and its reader (map plugins from `registry`; without
// one, built-in formats only), takes start and goal from the scenario (whose map it is unless
// `map` is set) or the cells, and checks both cells: an Error says which cell is outside or
// blocked, and why. `check_map`, if given, sees the map first (aco::PlanRequest::check_map).
LoadedProblem load_problem(const ProblemSpec& problem, PluginRegistry* registry = nullptr,
                           const std::function<void(const Map&)>& check_map = {}, const KeySpelling& spelling = "--");
// Throws an Error if `cell` ("start", "goal") is outside the map or blocked, naming the reason.
void check_cell(const Map& map, Cell cell, const std::string& what);
// Both ends of a problem on its map, "start" then "goal", after `check_map` if given: what
// load_problem() checks, for a map the caller made (aco::PlanRequest::map).
void check_ends(const Map& map, Cell start, Cell goal, const std::function<void(const Map&)>& check_map = {});

// "X,Y" -> cell; throws naming `key`.
Cell parse_cell(const std::string& text, const std::string& key);

}  // namespace aco
