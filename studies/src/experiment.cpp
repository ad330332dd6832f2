#include "aco/studies/experiment.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <set>

#include "aco/engine/colony.hpp"
#include "aco/error.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/engine/pipeline.hpp"
#include "aco/planning/presets.hpp"
#include "aco/rng.hpp"
#include "aco/planning/planning.hpp"
#include "aco/value_parsers.hpp"
#include "aco/planning/yaml_keys.hpp"

namespace aco::studies {
namespace {

using aco::yaml::cell;
using aco::yaml::fail;
using aco::yaml::integer;
using aco::yaml::names_pipeline;
using aco::yaml::only_keys;
using aco::yaml::scalar;
using aco::yaml::where;

Configuration overlay(const Configuration& base, const Configuration& changes, const std::string& name) {
  Configuration c;
  static_cast<aco::KeyedValues&>(c) = aco::overlay(base, changes);
  c.name = name;
  return c;
}

// The recommended preset for the experiment's maps, for configurations that name none: robust on
// 2D maps, terrain on height maps. Simulation problems keep their scenario's own pipeline.
Configuration default_pipeline(const std::filesystem::path& file, const YAML::Node& doc,
                               const std::vector<Problem>& problems) {
  std::set<std::string> kinds;
  for (const Problem& p : problems) {
    if (p.simulation) return Configuration();
    kinds.insert(aco::default_preset(p.map));
  }
  if (kinds.size() > 1 && kinds.count("voxel"))
    fail(file, doc["problems"],
         "the problems mix voxel worlds and 2D maps, whose graphs no run shares (6, 18 or 26 moves in a voxel "
         "world): study them in experiments of their own");
  if (kinds.size() > 1)
    fail(file, doc["problems"],
         "the problems mix 2D maps and height maps, whose recommended pipelines differ: name one "
         "(settings: {preset: robust}, or terrain, or config: FILE)");
  Configuration c;
  static_cast<aco::KeyedValues&>(c) =
      aco::preset_keys(kinds.empty() ? aco::recommended_preset(aco::MapKind::grid) : *kinds.begin());
  return c;
}

// A configuration written as keys (see aco::yaml::read_run_keys: slots as mappings, `config:`).
Configuration read_keys(const std::filesystem::path& file, const YAML::Node& node) {
  Configuration c;
  static_cast<aco::KeyedValues&>(c) = aco::yaml::read_run_keys(file, node, {"name"});
  return c;
}

std::vector<Problem> read_problems(const std::filesystem::path& file, const YAML::Node& list,
                                   aco::PluginRegistry& registry) {
  if (!list || !list.IsSequence() || list.size() == 0)
    fail(file, list ? list : YAML::Node(), "'problems' must be a non-empty list");
  const auto dir = file.parent_path();
  std::vector<Problem> problems;
  for (const auto& entry : list) {
    // Before any entry["key"]: yaml-cpp throws its own exception for a subscript of a scalar.
    if (!entry.IsMap())
      fail(file, entry,
           "a problem is a mapping ({map: FILE, start: [x, y], goal: [x, y]}, {scen: FILE} or "
           "{simulation: FILE}), not a single value");
    if (entry["simulation"]) {
      only_keys(file, entry, {"simulation", "variations", "name"}, "a simulation problem");
      const std::string scenario = scalar(file, entry["simulation"], "simulation");
      Problem p;
      try {
        p.simulation =
            std::make_shared<const aco::simulation::Scenario>(aco::simulation::load_scenario(dir / scenario, registry));
      } catch (const aco::Error& e) {
        fail(file, entry["simulation"], e.what());
      }
      p.map = p.simulation->run.problem.map;
      p.start = p.simulation->start;
      p.goal = p.simulation->goal;
      if (entry["variations"]) p.variations = aco::yaml::boolean(file, entry["variations"], "variations");
      p.name = entry["name"] ? scalar(file, entry["name"], "name") : std::filesystem::path(scenario).stem().string();
      problems.push_back(std::move(p));
    } else if (entry["scen"]) {
      only_keys(file, entry, {"scen", "count", "indices", "name"}, "a scenario problem");
      const auto scen = dir / scalar(file, entry["scen"], "scen");
      std::vector<aco::Scenario> scenarios;
      try {
        scenarios = aco::load_scenarios(scen);
      } catch (const aco::Error& e) {
        fail(file, entry["scen"], e.what());
      }
      const std::string prefix = entry["name"] ? scalar(file, entry["name"], "name") : scen.stem().stem().string();
      std::vector<std::size_t> indices;
      if (entry["indices"]) {
        // Chosen scenarios (0-based, in the file's order).
        if (entry["count"]) fail(file, entry["indices"], "give 'count' or 'indices', not both");
        if (!entry["indices"].IsSequence() || entry["indices"].size() == 0)
          fail(file, entry["indices"], "'indices' must be a non-empty list of scenario numbers");
        for (const auto& item : entry["indices"]) {
          const int index = integer(file, item, "indices", 0);
          if (index >= static_cast<int>(scenarios.size()))
            fail(file, item,
                 "index " + std::to_string(index) + " is past the last of the " + std::to_string(scenarios.size()) +
                     " scenarios of " + scen.string() + " (0-based)");
          indices.push_back(static_cast<std::size_t>(index));
        }
      } else {
        const int count =
            entry["count"] ? integer(file, entry["count"], "count", 1) : static_cast<int>(scenarios.size());
        if (count > static_cast<int>(scenarios.size()))
          fail(file, entry["count"],
               "count " + std::to_string(count) + " exceeds the " + std::to_string(scenarios.size()) +
                   " scenarios of " + scen.string());
        // Evenly spread over the file, which Moving AI orders by difficulty (bucket).
        for (int i = 0; i < count; ++i) indices.push_back(static_cast<std::size_t>(i) * scenarios.size() / count);
      }
      for (const std::size_t index : indices) {
        const aco::Scenario& s = scenarios[index];
        Problem p;
        p.name = prefix + "#" + std::to_string(index);
        p.map = aco::scenario_map_file(scen);
        p.start = s.start;
        p.goal = s.goal;
        p.bucket = s.bucket;
        problems.push_back(std::move(p));
      }
    } else {
      // map-format and a map plugin's map.NAME keys choose and set up the map's reader.
      std::vector<std::string> allowed = {"map", "map-format", "start", "goal", "name"};
      aco::Keys reader_keys;
      for (const auto& key : entry)
        if (const std::string name = key.first.Scalar(); name.rfind("map.", 0) == 0) {
          allowed.push_back(name);
          reader_keys[name.substr(4)] = scalar(file, key.second, name);
        }
      only_keys(file, entry, allowed, "a problem");
      if (!entry["map"] || !entry["start"] || !entry["goal"])
        fail(file, entry, "a problem needs map, start and goal (or scen)");
      const std::string map = scalar(file, entry["map"], "map");
      Problem p;
      p.map = dir / map;
      try {
        std::tie(p.map_format, p.map_parameters) = aco::resolve_map_format(
            p.map, entry["map-format"] ? scalar(file, entry["map-format"], "map-format") : "", reader_keys, registry);
      } catch (const aco::Error& e) {
        fail(file, entry, e.what());
      }
      const std::optional<bool> with_z = aco::cells_have_z(p.map, p.map_format);
      p.start = cell(file, entry["start"], "start", with_z, /*texts=*/true);
      p.goal = cell(file, entry["goal"], "goal", with_z, /*texts=*/true);
      p.name = entry["name"] ? scalar(file, entry["name"], "name") : std::filesystem::path(map).stem().string();
      problems.push_back(std::move(p));
    }
  }
  std::set<std::string> names;
  for (const auto& p : problems)
    if (!names.insert(p.name).second) fail(file, list, "two problems are named '" + p.name + "'; give them a name");
  return problems;
}

// Full factorial over `factors` (key -> values), each combination overlaid on the baseline.
std::vector<Configuration> factorial(const std::filesystem::path& file, const YAML::Node& node,
                                     const Configuration& base) {
  if (!node.IsMap()) fail(file, node, "'factorial' must map keys to lists of values");
  std::vector<std::pair<std::string, std::vector<std::string>>> factors;
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();
    if (!entry.second.IsSequence() || entry.second.size() == 0)
      fail(file, entry.first, "factor '" + key + "' must be a non-empty list of values");
    std::vector<std::string> values;
    for (const auto& v : entry.second) values.push_back(scalar(file, v, key));
    factors.emplace_back(key, std::move(values));
  }
  std::vector<Configuration> configs{Configuration{}};
  for (const auto& [key, values] : factors) {
    std::vector<Configuration> next;
    for (const auto& partial : configs)
      for (const auto& value : values) {
        Configuration c = partial;
        c.name += (c.name.empty() ? "" : ",") + key + "=" + value;
        c.keys[key] = value;
        c.origins[key] = where(file, node[key]);
        next.push_back(std::move(c));
      }
    configs = std::move(next);
  }
  for (auto& c : configs) c = overlay(base, c, c.name);
  return configs;
}

// The configurations whose twins `null-models` asks for (docs/learning.md): true = every colony
// configuration that is not itself a null model, false = none, or a list of names.
std::vector<const Configuration*> null_model_subjects(const std::filesystem::path& file, const YAML::Node& node,
                                                      const std::vector<Configuration>& configs) {
  const auto is_twin = [](const Configuration& c) { return c.run->colony.null_model != aco::NullModel::none; };
  std::vector<const Configuration*> subjects;
  if (node.IsScalar()) {
    if (aco::yaml::boolean(file, node, "null-models"))
      for (const auto& c : configs)
        if (c.run->planner == "aco" && !is_twin(c)) subjects.push_back(&c);
    return subjects;
  }
  if (!node.IsSequence()) fail(file, node, "'null-models' is true, false or a list of configuration names");
  for (const auto& entry : node) {
    const std::string name = scalar(file, entry, "null-models");
    const auto it = std::find_if(configs.begin(), configs.end(), [&](const auto& c) { return c.name == name; });
    if (it == configs.end()) fail(file, entry, "null-models: '" + name + "' is not a configuration of this file");
    if (it->run->planner != "aco")
      fail(file, entry,
           "null-models: '" + name + "' runs the planner '" + it->run->planner + "'; only a colony has twins");
    if (is_twin(*it)) fail(file, entry, "null-models: '" + name + "' is itself a null model (it sets null-model)");
    if (std::find(subjects.begin(), subjects.end(), &*it) != subjects.end())
      fail(file, entry, "null-models: '" + name + "' is named twice");
    subjects.push_back(&*it);
  }
  return subjects;
}

// The no-learning and restart twins of `subject`: its keys with null-model set.
std::vector<Configuration> twins(const Configuration& subject, const std::string& origin) {
  std::vector<Configuration> result;
  for (const auto& [model, label] :
       {std::pair{"no-learning", " (no learning)"}, std::pair{"restarts", " (restarts)"}}) {
    Configuration twin = subject;
    twin.name += label;
    twin.keys["null-model"] = model;
    twin.origins["null-model"] = origin;
    twin.run.reset();
    result.push_back(std::move(twin));
  }
  return result;
}

// Checks every time-limit-from and sets it to the name of the configuration it takes the time
// from, so that the database and the report find the pair by name whatever was written.
void tie_time_limits(Experiment& e) {
  const auto fail_tie = [](const Configuration& c, const std::string& message) {
    return aco::Error(c.origin(kTimeLimitFrom) + "configuration '" + c.name + "': " + kTimeLimitFrom + ": " + message);
  };
  // In the settings or the baseline it would tie every configuration, the colony's too.
  if (!e.baseline.time_limit_from().empty())
    throw aco::Error(e.baseline.origin(kTimeLimitFrom) + std::string(kTimeLimitFrom) +
                     " belongs to an OMPL configuration under 'configurations', not to the settings or the baseline");
  if (e.ablation_target && !e.ablation_target->time_limit_from().empty())
    throw fail_tie(*e.ablation_target, "an ablation target's time limit cannot be another configuration's time");
  const auto colonies = [&e] {
    std::vector<std::string> names;
    for (const auto& c : e.configurations)
      if (c.run->planner == "aco" && c.run->colony.null_model == aco::NullModel::none && c.time_limit_from().empty())
        names.push_back(c.name);
    return names;
  }();
  for (auto& c : e.configurations) {
    const std::string wanted = c.time_limit_from();
    if (wanted.empty()) continue;
    if (std::any_of(e.problems.begin(), e.problems.end(), [](const Problem& p) { return p.simulation != nullptr; }))
      throw fail_tie(c, "a simulation problem's time is the drive's, not the planner's: planning problems only");
    if (c.run->planner != "ompl")
      throw fail_tie(c,
                     "only an OMPL configuration (planner: ompl) takes its time limit from another; this one runs '" +
                         c.run->planner + "'");
    auto target = std::find_if(e.configurations.begin(), e.configurations.end(),
                               [&](const Configuration& other) { return other.name == wanted; });
    if (target == e.configurations.end() && wanted != "colony")
      throw fail_tie(c, "'" + wanted + "' is not a configuration of this file");
    if (target == e.configurations.end()) {
      if (colonies.empty())
        throw fail_tie(c, "colony: the experiment has no colony configuration (planner: aco) to take the time from");
      if (colonies.size() > 1) {
        std::string list;
        for (const auto& name : colonies) list += (list.empty() ? "'" : ", '") + name + "'";
        throw fail_tie(c, "colony: the experiment has " + std::to_string(colonies.size()) + " colony configurations (" +
                              list + "): name one");
      }
      target = std::find_if(e.configurations.begin(), e.configurations.end(),
                            [&](const Configuration& other) { return other.name == colonies.front(); });
    }
    if (target->name == c.name) throw fail_tie(c, "a configuration cannot take its time limit from itself");
    // A chain would need its trials in rounds; one round of ties is what a head-to-head needs.
    if (!target->time_limit_from().empty())
      throw fail_tie(c, "'" + target->name + "' takes its own time limit from another configuration");
    c.keys[kTimeLimitFrom] = target->name;
  }
}

}  // namespace

std::string Configuration::time_limit_from() const {
  const auto it = keys.find(kTimeLimitFrom);
  return it == keys.end() ? "" : it->second;
}

Configuration run_keys(const Configuration& config) {
  Configuration c = config;
  c.keys.erase(kTimeLimitFrom);
  return c;
}

std::string run_json(const Configuration& config, const aco::RunSpec& run) {
  const std::string text = aco::to_json(run);
  if (config.time_limit_from().empty()) return text;
  auto j = nlohmann::ordered_json::parse(text);
  j[kTimeLimitFrom] = config.time_limit_from();
  return j.dump();
}

aco::RunSpec resolve(const Configuration& config, aco::PluginRegistry& registry) {
  const auto fail_key = [&config](const std::string& key, const std::string& message) {
    return aco::Error(config.origin(key) + "configuration '" + config.name + "': " + message);
  };
  for (const char* key : {"map", "scen", "scen-index", "start", "goal"})
    if (config.keys.count(key))
      throw fail_key(key, "'" + std::string(key) + "' belongs to the problems: list them under 'problems'");
  if (config.keys.count("seed"))
    throw fail_key("seed", "'seed' is set per trial from the experiment's seed, not per configuration");
  try {
    return aco::resolve_run(run_keys(config).keys, registry);
  } catch (const aco::KeyError& e) {
    throw fail_key(e.key(), e.what());
  }
}

aco::RunSpec resolve(const Configuration& config, const std::vector<Problem>& problems, aco::PluginRegistry& registry) {
  const bool all_simulations = !problems.empty() && std::all_of(problems.begin(), problems.end(), [](const Problem& p) {
    return p.simulation != nullptr;
  });
  if (!all_simulations) return resolve(config, registry);
  try {
    return aco::simulation::with_run_keys(*problems.front().simulation, run_keys(config), registry).run;
  } catch (const aco::Error& e) {
    throw aco::Error("configuration '" + config.name + "' over " + problems.front().simulation->file.string() + ": " +
                     e.what());
  }
}

namespace {

Experiment read_experiment(const YAML::Node& doc, const std::filesystem::path& file, aco::PluginRegistry& registry) {
  if (!doc.IsMap()) throw aco::Error(file.string() + ": an experiment file is a YAML mapping (name, problems, ...)");
  only_keys(file, doc,
            {"name", "seed", "repetitions", "problems", "settings", "baseline", "configurations", "factorial",
             "ablation", "null-models", "trial-timeout", "trial-memory"},
            "the experiment");
  Experiment e;
  e.file = file;
  e.name = doc["name"] ? scalar(file, doc["name"], "name") : file.stem().string();
  if (doc["seed"]) e.seed = static_cast<std::uint64_t>(integer(file, doc["seed"], "seed", 0));
  if (doc["repetitions"]) e.repetitions = integer(file, doc["repetitions"], "repetitions", 1);
  try {
    if (doc["trial-timeout"])
      e.trial_timeout_s = aco::parse_seconds(scalar(file, doc["trial-timeout"], "trial-timeout"), "trial-timeout");
    if (doc["trial-memory"])
      e.trial_memory_bytes = aco::parse_memory_size(scalar(file, doc["trial-memory"], "trial-memory"), "trial-memory");
  } catch (const aco::Error& error) {
    fail(file, doc["trial-timeout"] && !e.trial_timeout_s ? doc["trial-timeout"] : doc["trial-memory"], error.what());
  }
  e.problems = read_problems(file, doc["problems"], registry);

  const Configuration common = doc["settings"] ? read_keys(file, doc["settings"]) : Configuration();
  const Configuration own = doc["baseline"] ? read_keys(file, doc["baseline"]) : Configuration();
  const std::string baseline_name =
      doc["baseline"] && doc["baseline"]["name"] ? scalar(file, doc["baseline"]["name"], "name") : "baseline";
  // A configuration that names no pipeline (config or preset, in itself, the baseline or the
  // settings) runs the recommended one, as acoplan does.
  const Configuration named_baseline = overlay(common, own, baseline_name);
  const bool base_names_one = names_pipeline(doc["settings"]) || names_pipeline(doc["baseline"]);
  e.baseline =
      base_names_one ? named_baseline : overlay(default_pipeline(file, doc, e.problems), named_baseline, baseline_name);
  e.configurations.push_back(e.baseline);
  if (doc["configurations"]) {
    if (!doc["configurations"].IsSequence()) fail(file, doc["configurations"], "'configurations' must be a list");
    for (const auto& node : doc["configurations"]) {
      if (!node.IsMap() || !node["name"]) fail(file, node, "every configuration needs a 'name'");
      const Configuration& base = names_pipeline(node) ? named_baseline : e.baseline;
      e.configurations.push_back(overlay(base, read_keys(file, node), scalar(file, node["name"], "name")));
    }
  }
  if (doc["factorial"])
    for (auto& c : factorial(file, doc["factorial"], e.baseline)) e.configurations.push_back(std::move(c));
  if (doc["ablation"]) {
    only_keys(file, doc["ablation"], {"target"}, "'ablation'");
    const YAML::Node target = doc["ablation"]["target"];
    if (!target) fail(file, doc["ablation"], "'ablation' needs a 'target' configuration name");
    const std::string name = scalar(file, target, "target");
    const auto it =
        std::find_if(e.configurations.begin(), e.configurations.end(), [&](const auto& c) { return c.name == name; });
    if (it == e.configurations.end())
      fail(file, target, "the ablation target '" + name + "' is not a configuration of this file");
    e.ablation_target = *it;
  }
  for (auto& c : e.configurations) c.run = resolve(c, e.problems, registry);
  if (doc["null-models"]) {
    std::vector<Configuration> added;
    for (const Configuration* subject : null_model_subjects(file, doc["null-models"], e.configurations))
      for (Configuration& twin : twins(*subject, where(file, doc["null-models"]))) {
        twin.run = resolve(twin, e.problems, registry);
        added.push_back(std::move(twin));
      }
    for (auto& twin : added) e.configurations.push_back(std::move(twin));
  }
  std::set<std::string> names;
  for (const auto& c : e.configurations)
    if (!names.insert(c.name).second)
      throw aco::Error(file.string() + ": two configurations are named '" + c.name + "'");
  tie_time_limits(e);
  e.baseline.run = e.configurations.front().run;
  return e;
}

}  // namespace

Experiment load_experiment(const std::filesystem::path& file, aco::PluginRegistry& registry) {
  return read_experiment(aco::yaml::load_file(file, "experiment"), file, registry);
}

Experiment load_experiment_text(const std::string& text, const std::filesystem::path& file,
                                aco::PluginRegistry& registry) {
  YAML::Node doc;
  try {
    doc = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw aco::Error(file.string() + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + e.msg);
  }
  return read_experiment(doc, file, registry);
}

std::string Experiment::relative_to_file(const std::filesystem::path& path) const {
  const auto absolute = std::filesystem::absolute(path).lexically_normal();
  const auto relative = absolute.lexically_relative(std::filesystem::absolute(file).parent_path().lexically_normal());
  return (relative.empty() ? absolute : relative).generic_string();
}

std::vector<int> cell_json(aco::Cell c) {
  if (c.z == 0) return {c.x, c.y};
  return {c.x, c.y, c.z};
}

std::string Experiment::fingerprint(const aco::PluginRegistry& registry) const {
  nlohmann::json j;
  j["format"] = 1;
  j["repetitions"] = repetitions;
  j["seed"] = seed;
  for (const auto& p : problems) {
    nlohmann::json problem = {
        {"name", p.name}, {"map", relative_to_file(p.map)}, {"start", cell_json(p.start)}, {"goal", cell_json(p.goal)}};
    if (!p.map_format.empty()) problem["map-format"] = p.map_format;
    for (const auto& [name, value] : p.map_parameters.all()) problem["map." + name] = aco::to_string(value);
    // A scenario's world is its file's: the file named, not its contents (as a map is).
    if (p.simulation) {
      problem["simulation"] = relative_to_file(p.simulation->file);
      problem["variations"] = p.variations;
    }
    j["problems"].push_back(problem);
  }
  // Each configuration's resolved run too: a database keeps a configuration's trials as long as
  // its run is the same, whatever keys wrote it (growth.hpp).
  for (const auto& c : configurations) {
    nlohmann::json entry = {{"name", c.name}, {"keys", c.keys}};
    if (c.run) {
      entry["run"] = nlohmann::json::parse(run_json(c, *c.run));
      // A run over scenarios holds the first scenario's map, as the path it was loaded by: the same
      // file named from another working folder (acobench's workers load the experiment by its
      // absolute path) is the same experiment.
      for (const char* key : {"map", "scen"})
        if (entry["run"].contains(key) && entry["run"][key].is_string() &&
            !entry["run"][key].get<std::string>().empty())
          entry["run"][key] = relative_to_file(entry["run"][key].get<std::string>());
    }
    j["configurations"].push_back(entry);
  }
  if (ablation_target) j["ablation_target"] = ablation_target->name;
  // The binaries that run the trials (an ablation's flips mix the baseline's and the target's
  // plugins, a scenario's keys fill what a configuration leaves): rebuilt code is another
  // experiment. By content, not by file: a moved build is the same.
  std::vector<const aco::RunSpec*> runs;
  for (const auto& c : configurations)
    if (c.run) runs.push_back(&*c.run);
  if (ablation_target && ablation_target->run) runs.push_back(&*ablation_target->run);
  for (const auto& p : problems)
    if (p.simulation) runs.push_back(&p.simulation->run);
  for (const auto* run : runs)
    for (const char* slot : aco::kSlots) {
      const auto p = registry.provenance(slot, run->pipeline.at(slot).plugin);
      j["plugins"][p.slot + "/" + p.name] = {{"version", p.version}, {"sha256", p.sha256}};
    }
  return j.dump();
}

std::vector<std::pair<std::string, std::string>> Experiment::same_runs() const {
  std::vector<std::pair<std::string, std::string>> pairs;
  std::map<std::string, std::string> first_with;  // resolved run (JSON) -> the first configuration
  for (const auto& c : configurations) {
    if (!c.run) continue;
    const auto [first, fresh] = first_with.emplace(run_json(c, *c.run), c.name);
    if (!fresh) pairs.emplace_back(first->second, c.name);
  }
  return pairs;
}

std::uint64_t trial_seed(std::uint64_t master_seed, const std::string& problem, int repetition) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a of the problem's name
  for (unsigned char ch : problem) h = (h ^ ch) * 0x100000001b3ull;
  return aco::Rng::stream(master_seed, h, static_cast<std::uint64_t>(repetition)).next() >> 1;  // a valid colony seed
}

std::vector<std::vector<std::string>> ablation_components(const Configuration& from, const Configuration& to) {
  std::set<std::string> keys;
  for (const auto& [k, v] : from.keys) keys.insert(k);
  for (const auto& [k, v] : to.keys) keys.insert(k);
  const auto value = [](const Configuration& c, const std::string& k) {
    const auto it = c.keys.find(k);
    return it == c.keys.end() ? std::optional<std::string>() : it->second;
  };
  std::map<std::string, std::vector<std::string>> groups;
  for (const auto& k : keys) {
    const auto dot = k.find('.');
    const std::string owner = dot == std::string::npos ? k : k.substr(0, dot);
    const bool slot = std::find(aco::kSlots.begin(), aco::kSlots.end(), owner) != aco::kSlots.end();
    // A slot whose plugin changes moves as one component with all its parameters.
    const bool plugin_changes = slot && value(from, owner) != value(to, owner);
    if (plugin_changes) {
      groups[owner].push_back(k);
    } else if (value(from, k) != value(to, k)) {
      groups[k].push_back(k);
    }
  }
  std::vector<std::vector<std::string>> components;
  for (auto& [name, ks] : groups) components.push_back(std::move(ks));
  return components;
}

Configuration flip(const Configuration& config, const Configuration& target,
                   const std::vector<std::string>& component) {
  Configuration c = config;
  c.run.reset();
  for (const auto& k : component) {
    if (target.keys.count(k)) {
      c.keys[k] = target.keys.at(k);
    } else {
      c.keys.erase(k);
    }
  }
  return c;
}

}  // namespace aco::studies
