#include "experiment.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <nlohmann/json.hpp>
#include <set>

#include "aco/colony.hpp"
#include "aco/error.hpp"
#include "aco/map_io.hpp"
#include "aco/pipeline.hpp"
#include "aco/rng.hpp"
#include "aco/planning.hpp"

namespace acobench {
namespace {

std::string where(const std::filesystem::path& file, const YAML::Node& node) {
  return file.string() + ":" + std::to_string(node.Mark().line + 1);
}

[[noreturn]] void fail(const std::filesystem::path& file, const YAML::Node& node, const std::string& message) {
  throw aco::Error(where(file, node) + ": " + message);
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
    fail(file, node, "'" + key + "' must be a whole number >= " + std::to_string(low) + ", not '" + text + "'");
  return value;
}

void only_keys(const std::filesystem::path& file, const YAML::Node& map, const std::vector<std::string>& allowed,
               const std::string& what) {
  if (!map.IsMap()) fail(file, map, what + " must be a mapping of keys to values");
  for (const auto& entry : map) {
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string message = "unknown key '" + key + "' in " + what;
      if (const auto near = aco::nearest(key, allowed); !near.empty()) message += "; did you mean '" + near + "'?";
      fail(file, entry.first, message);
    }
  }
}

aco::Cell cell(const std::filesystem::path& file, const YAML::Node& node, const std::string& key) {
  if (node.IsSequence() && node.size() == 2)
    return {integer(file, node[0], key + "[0]", 0), integer(file, node[1], key + "[1]", 0)};
  fail(file, node, "'" + key + "' must be a cell [x, y]");
}

// One key of a configuration; a slot may be given as {plugin: NAME, param: value, ...}.
void read_key(const std::filesystem::path& file, const YAML::Node& name, const YAML::Node& value, Configuration& config) {
  const std::string key = name.Scalar();
  if (value.IsMap()) {
    if (std::find(aco::kSlots.begin(), aco::kSlots.end(), key) == aco::kSlots.end())
      fail(file, name, "'" + key + "' is not a slot; only slots (" + std::string("init, heuristic, update, deadlock, smoother") +
                           ") take a {plugin: ..., parameter: ...} mapping");
    for (const auto& inner : value) {
      const std::string param = inner.first.Scalar();
      const std::string full = param == "plugin" ? key : key + "." + param;
      config.keys[full] = scalar(file, inner.second, full);
      config.origins[full] = where(file, inner.first);
    }
    if (!value["plugin"]) fail(file, name, "slot '" + key + "' needs a 'plugin' key");
    return;
  }
  config.keys[key] = scalar(file, value, key);
  config.origins[key] = where(file, name);
}

Configuration overlay(const Configuration& base, const Configuration& changes, const std::string& name);

// A configuration written as keys. `config: FILE` (relative to the experiment file) starts from
// the keys of an acoplan config file, such as a preset; the configuration's other keys override
// them, as acoplan's command line overrides its --config file.
Configuration read_keys(const std::filesystem::path& file, const YAML::Node& node) {
  if (!node.IsMap()) fail(file, node, "a configuration must be a mapping of keys to values");
  Configuration config;
  for (const auto& entry : node)
    if (entry.first.Scalar() != "name" && entry.first.Scalar() != "config") read_key(file, entry.first, entry.second, config);
  if (!node["config"]) return config;
  const std::filesystem::path ini = (file.parent_path() / scalar(file, node["config"], "config")).lexically_normal();
  Configuration preset;
  try {
    preset.keys = aco::read_config_file(ini.string());
  } catch (const aco::Error& e) {
    fail(file, node["config"], e.what());
  }
  for (const auto& [key, value] : preset.keys) preset.origins[key] = ini.string();
  return overlay(preset, config, "");
}

Configuration overlay(const Configuration& base, const Configuration& changes, const std::string& name) {
  Configuration c = base;
  c.name = name;
  c.run.reset();
  // A new plugin for a slot drops the old plugin's parameters.
  for (const auto& [key, value] : changes.keys)
    if (std::find(aco::kSlots.begin(), aco::kSlots.end(), key) != aco::kSlots.end() && c.keys.count(key) &&
        c.keys.at(key) != value)
      std::erase_if(c.keys, [&key](const auto& kv) { return kv.first.rfind(key + ".", 0) == 0; });
  for (const auto& [key, value] : changes.keys) {
    c.keys[key] = value;
    c.origins[key] = changes.origins.count(key) ? changes.origins.at(key) : "";
  }
  return c;
}

std::vector<Problem> read_problems(const std::filesystem::path& file, const YAML::Node& list) {
  if (!list || !list.IsSequence() || list.size() == 0) fail(file, list ? list : YAML::Node(), "'problems' must be a non-empty list");
  const auto dir = file.parent_path();
  std::vector<Problem> problems;
  for (const auto& entry : list) {
    if (entry["scen"]) {
      only_keys(file, entry, {"scen", "count", "name"}, "a scenario problem");
      const auto scen = dir / scalar(file, entry["scen"], "scen");
      std::vector<aco::Scenario> scenarios;
      try {
        scenarios = aco::load_scenarios(scen);
      } catch (const aco::Error& e) {
        fail(file, entry["scen"], e.what());
      }
      const int count = entry["count"] ? integer(file, entry["count"], "count", 1) : static_cast<int>(scenarios.size());
      if (count > static_cast<int>(scenarios.size()))
        fail(file, entry["count"], "count " + std::to_string(count) + " exceeds the " + std::to_string(scenarios.size()) +
                                       " scenarios of " + scen.string());
      const std::string prefix = entry["name"] ? scalar(file, entry["name"], "name") : scen.stem().stem().string();
      // Evenly spread over the file, which Moving AI orders by difficulty (bucket).
      for (int i = 0; i < count; ++i) {
        const std::size_t index = static_cast<std::size_t>(i) * scenarios.size() / count;
        const aco::Scenario& s = scenarios[index];
        problems.push_back({prefix + "#" + std::to_string(index), aco::scenario_map_file(scen), s.start, s.goal, s.bucket});
      }
    } else {
      only_keys(file, entry, {"map", "start", "goal", "name"}, "a problem");
      if (!entry["map"] || !entry["start"] || !entry["goal"]) fail(file, entry, "a problem needs map, start and goal (or scen)");
      const std::string map = scalar(file, entry["map"], "map");
      Problem p;
      p.map = dir / map;
      p.start = cell(file, entry["start"], "start");
      p.goal = cell(file, entry["goal"], "goal");
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
std::vector<Configuration> factorial(const std::filesystem::path& file, const YAML::Node& node, const Configuration& base) {
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

std::string key_origin(const Configuration& config, const std::string& key) {
  const auto it = config.origins.find(key);
  return it != config.origins.end() && !it->second.empty() ? it->second + ": " : "";
}

}  // namespace

aco::RunSpec resolve(const Configuration& config, aco::PluginRegistry& registry) {
  const auto fail_key = [&config](const std::string& key, const std::string& message) {
    return aco::Error(key_origin(config, key) + "configuration '" + config.name + "': " + message);
  };
  for (const char* key : {"map", "scen", "scen-index", "start", "goal"})
    if (config.keys.count(key))
      throw fail_key(key, "'" + std::string(key) + "' belongs to the problems: list them under 'problems'");
  if (config.keys.count("seed")) throw fail_key("seed", "'seed' is set per trial from the experiment's seed, not per configuration");
  try {
    return aco::resolve_run(config.keys, registry);
  } catch (const aco::KeyError& e) {
    throw fail_key(e.key(), e.what());
  }
}

Experiment load_experiment(const std::filesystem::path& file, aco::PluginRegistry& registry) {
  YAML::Node doc;
  try {
    doc = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    throw aco::Error(file.string() + ": cannot open the experiment file");
  } catch (const YAML::Exception& e) {
    throw aco::Error(file.string() + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + e.msg);
  }
  if (!doc.IsMap()) throw aco::Error(file.string() + ": an experiment file is a YAML mapping (name, problems, ...)");
  only_keys(file, doc, {"name", "seed", "repetitions", "problems", "settings", "baseline", "configurations", "factorial", "ablation"},
            "the experiment");
  Experiment e;
  e.file = file;
  e.name = doc["name"] ? scalar(file, doc["name"], "name") : file.stem().string();
  if (doc["seed"]) e.seed = static_cast<std::uint64_t>(integer(file, doc["seed"], "seed", 0));
  if (doc["repetitions"]) e.repetitions = integer(file, doc["repetitions"], "repetitions", 1);
  e.problems = read_problems(file, doc["problems"]);

  const Configuration common = doc["settings"] ? read_keys(file, doc["settings"]) : Configuration();
  const Configuration own = doc["baseline"] ? read_keys(file, doc["baseline"]) : Configuration();
  e.baseline = overlay(common, own, doc["baseline"] && doc["baseline"]["name"] ? scalar(file, doc["baseline"]["name"], "name") : "baseline");
  e.configurations.push_back(e.baseline);
  if (doc["configurations"]) {
    if (!doc["configurations"].IsSequence()) fail(file, doc["configurations"], "'configurations' must be a list");
    for (const auto& node : doc["configurations"]) {
      if (!node.IsMap() || !node["name"]) fail(file, node, "every configuration needs a 'name'");
      e.configurations.push_back(overlay(e.baseline, read_keys(file, node), scalar(file, node["name"], "name")));
    }
  }
  if (doc["factorial"])
    for (auto& c : factorial(file, doc["factorial"], e.baseline)) e.configurations.push_back(std::move(c));
  if (doc["ablation"]) {
    only_keys(file, doc["ablation"], {"target"}, "'ablation'");
    const YAML::Node target = doc["ablation"]["target"];
    if (!target) fail(file, doc["ablation"], "'ablation' needs a 'target' configuration name");
    const std::string name = scalar(file, target, "target");
    const auto it = std::find_if(e.configurations.begin(), e.configurations.end(), [&](const auto& c) { return c.name == name; });
    if (it == e.configurations.end()) fail(file, target, "the ablation target '" + name + "' is not a configuration of this file");
    e.ablation_target = *it;
  }
  std::set<std::string> names;
  for (auto& c : e.configurations) {
    if (!names.insert(c.name).second) throw aco::Error(file.string() + ": two configurations are named '" + c.name + "'");
    c.run = resolve(c, registry);
  }
  e.baseline.run = e.configurations.front().run;
  return e;
}

std::string Experiment::fingerprint() const {
  nlohmann::json j;
  j["format"] = 1;
  j["repetitions"] = repetitions;
  j["seed"] = seed;
  for (const auto& p : problems)
    j["problems"].push_back({{"name", p.name}, {"map", p.map.lexically_relative(file.parent_path()).generic_string()},
                             {"start", {p.start.x, p.start.y}}, {"goal", {p.goal.x, p.goal.y}}});
  for (const auto& c : configurations) j["configurations"].push_back({{"name", c.name}, {"keys", c.keys}});
  if (ablation_target) j["ablation_target"] = ablation_target->name;
  return j.dump();
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

Configuration flip(const Configuration& config, const Configuration& target, const std::vector<std::string>& component) {
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

}  // namespace acobench
