#include "aco/studies/growth.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "aco/studies/provenance.hpp"

namespace aco::studies {
namespace {

using nlohmann::json;

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

json parsed(const std::string& text) { return json::parse(text, nullptr, false); }

bool is_fingerprint(const json& j) { return j.is_object() && j.contains("configurations"); }

// A value as the user wrote it: keys are strings (0.1, not "0.1"); absent is the default.
std::string shown(const json* value) {
  if (!value) return "(default)";
  const std::string text = value->is_string() ? value->get<std::string>() : value->dump();
  return text.size() > 60 ? text.substr(0, 57) + "..." : text;
}

// "KEY OLD -> NEW" for each member of two objects that differs, recursing into objects
// ("colony.alpha"), prefixed.
void leaf_differences(const json& a, const json& b, const std::string& prefix, std::vector<std::string>& out) {
  std::set<std::string> keys;
  if (a.is_object())
    for (const auto& [k, v] : a.items()) keys.insert(k);
  if (b.is_object())
    for (const auto& [k, v] : b.items()) keys.insert(k);
  for (const auto& k : keys) {
    const json* va = a.is_object() && a.contains(k) ? &a.at(k) : nullptr;
    const json* vb = b.is_object() && b.contains(k) ? &b.at(k) : nullptr;
    if (va && vb && *va == *vb) continue;
    if (va && vb && va->is_object() && vb->is_object()) {
      leaf_differences(*va, *vb, prefix + k + ".", out);
    } else {
      out.push_back(prefix + k + " " + shown(va) + " -> " + shown(vb));
    }
  }
}

// What makes two configurations (fingerprint entries or stored settings: keys, and when known
// run and plugins) other runs: their resolved runs and plugin binaries when both are known, else
// their keys. Told by the keys when they differ (as the user wrote them), else by the run.
std::vector<std::string> differences(const json& stored, const json& now) {
  const auto member = [](const json& j, const char* key) { return j.contains(key) ? j.at(key) : json(); };
  // The binary's file is where it lies, not what it is.
  const auto binaries = [&](const json& j) {
    json p = member(j, "plugins");
    for (auto& [slot, plugin] : p.items())
      if (plugin.is_object()) plugin.erase("file");
    return p;
  };
  const bool resolved = stored.contains("run") && now.contains("run");
  const bool same = resolved ? stored.at("run") == now.at("run") && binaries(stored) == binaries(now)
                             : member(stored, "keys") == member(now, "keys");
  if (same) return {};
  std::vector<std::string> lines;
  leaf_differences(member(stored, "keys"), member(now, "keys"), "", lines);
  if (lines.empty() && resolved) leaf_differences(stored.at("run"), now.at("run"), "", lines);
  if (resolved) leaf_differences(binaries(stored), binaries(now), "plugin ", lines);
  if (lines.empty()) lines.push_back("its settings changed");
  return lines;
}

// "configuration 'a': X", or one line for a difference several share ("configurations 'a',
// 'b': X"; "every configuration: X" when all of `of` do).
void grouped(const std::map<std::string, std::vector<std::string>>& names_by_line, std::size_t of,
             const std::string& one, const std::string& several, const std::string& every,
             std::vector<std::string>& out) {
  for (const auto& [line, names] : names_by_line) {
    if (names.size() > 1 && names.size() == of) {
      out.push_back(every + ": " + line);
      continue;
    }
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + in_quotes(n);
    out.push_back((names.size() > 1 ? several : one) + " " + list + ": " + line);
  }
}

const json* by_name(const json& list, const std::string& name) {
  for (const auto& entry : list)
    if (entry.value("name", "") == name) return &entry;
  return nullptr;
}

std::vector<std::string> names(const json& list) {
  std::vector<std::string> result;
  for (const auto& entry : list) result.push_back(entry.value("name", ""));
  return result;
}

// `stored`'s entries (replaced by `now`'s of the same name), then `now`'s new ones.
json united(const json& stored, const json& now) {
  json result = json::array();
  for (const auto& entry : stored) {
    const json* newer = by_name(now, entry.value("name", ""));
    result.push_back(newer ? *newer : entry);
  }
  for (const auto& entry : now)
    if (!by_name(stored, entry.value("name", ""))) result.push_back(entry);
  return result;
}

}  // namespace

std::vector<std::string> fingerprint_conflicts(const std::string& stored_text, const std::string& now_text) {
  if (stored_text == now_text) return {};
  const json stored = parsed(stored_text), now = parsed(now_text);
  if (!is_fingerprint(stored) || !is_fingerprint(now)) return {fingerprint_change(stored_text, now_text)};
  std::vector<std::string> lines;
  if (stored.value("seed", json()) != now.value("seed", json()))
    lines.push_back("seed " + shown(&stored.at("seed")) + " -> " + shown(&now.at("seed")) +
                    " (every trial's seed derives from it)");
  if (stored.contains("ablation_target") && now.contains("ablation_target") &&
      stored["ablation_target"] != now["ablation_target"])
    lines.push_back("ablation target " + shown(&stored["ablation_target"]) + " -> " + shown(&now["ablation_target"]) +
                    " (the stored ablation path leads to the other)");
  if (stored.contains("ablation_target")) {
    const Growth g = growth(stored_text, now_text);
    if (!g.added_problems.empty() || g.repetitions_now > g.repetitions_before)
      lines.push_back(
          "ablation: the stored path was chosen on the stored problems and repetitions; with more it "
          "may take another, whose rounds the database cannot hold beside it: add no problems or "
          "repetitions to an experiment with an ablation path");
  }
  if (!stored.contains("plugins") && now.contains("plugins"))
    lines.push_back(fingerprint_change(stored_text, now_text));
  if (stored.contains("plugins") && now.contains("plugins"))
    for (const auto& [plugin, then] : stored.at("plugins").items()) {
      if (!now.at("plugins").contains(plugin) || now.at("plugins").at(plugin) == then) continue;
      const json& later = now.at("plugins").at(plugin);
      lines.push_back("another binary of plugin " + plugin + ": version " + then.value("version", "?") + " sha256 " +
                      then.value("sha256", "?") + " -> version " + later.value("version", "?") + " sha256 " +
                      later.value("sha256", "?") + " (the stored trials ran the first: run it again)");
    }
  std::map<std::string, std::vector<std::string>> names_by_line;
  std::size_t common = 0;
  for (const auto& config : stored.at("configurations")) {
    const std::string name = config.value("name", "");
    const json* later = by_name(now.at("configurations"), name);
    if (!later) continue;
    ++common;
    for (const auto& line : differences(config, *later)) names_by_line[line].push_back(name);
  }
  grouped(names_by_line, common, "configuration", "configurations", "every configuration", lines);
  return lines;
}

std::vector<std::string> problem_conflicts(const std::vector<ProblemRecord>& stored,
                                           const std::vector<ProblemRecord>& now) {
  std::map<std::string, std::vector<std::string>> names_by_line;
  std::size_t common = 0;
  for (const auto& before : stored) {
    const auto later =
        std::find_if(now.begin(), now.end(), [&](const ProblemRecord& p) { return p.name == before.name; });
    if (later == now.end()) continue;
    ++common;
    std::vector<std::string> lines;
    leaf_differences(parsed(before.setup_json), parsed(later->setup_json), "", lines);
    const double optimum = later->optimal_length < 0 ? -1.0 : later->optimal_length;
    if (lines.empty() && before.optimal_length != optimum)
      lines.push_back("optimal length " + std::to_string(before.optimal_length) + " -> " + std::to_string(optimum) +
                      " (the map file's contents changed)");
    for (const auto& line : lines) names_by_line[line].push_back(before.name);
  }
  std::vector<std::string> lines;
  grouped(names_by_line, common, "problem", "problems", "every problem", lines);
  return lines;
}

std::vector<std::string> config_conflicts(const std::string& name, const std::string& stored_settings,
                                          const std::string& now_settings) {
  const json stored = parsed(stored_settings), now = parsed(now_settings);
  if (stored == now) return {};
  // Settings that are not acobench's (keys, run, plugins) are the same only when equal.
  const bool ours = stored.is_object() && now.is_object() && stored.contains("run") && now.contains("run");
  std::vector<std::string> lines;
  for (const auto& line :
       ours ? differences(stored, now) : std::vector<std::string>{stored_settings + " -> " + now_settings})
    lines.push_back("configuration " + in_quotes(name) + ": " + line);
  return lines;
}

std::string merged_fingerprint(const std::string& stored_text, const std::string& now_text) {
  const json stored = parsed(stored_text), now = parsed(now_text);
  if (!is_fingerprint(stored) || !is_fingerprint(now)) return now_text;
  json merged = now;
  merged["configurations"] = united(stored.at("configurations"), now.at("configurations"));
  merged["problems"] = united(stored.value("problems", json::array()), now.value("problems", json::array()));
  merged["repetitions"] = std::max(stored.value("repetitions", 0), now.value("repetitions", 0));
  if (stored.contains("ablation_target") && !now.contains("ablation_target"))
    merged["ablation_target"] = stored["ablation_target"];
  json plugins = stored.value("plugins", json::object());
  const json now_plugins = now.value("plugins", json::object());
  for (const auto& [plugin, binary] : now_plugins.items()) plugins[plugin] = binary;
  merged["plugins"] = plugins;
  return merged.dump();
}

Growth growth(const std::string& stored_text, const std::string& now_text) {
  const json stored = parsed(stored_text), now = parsed(now_text);
  Growth g;
  if (!is_fingerprint(stored) || !is_fingerprint(now)) return g;
  const auto compare = [](const json& before, const json& later, std::vector<std::string>& added,
                          std::vector<std::string>& dropped) {
    for (const auto& name : names(later))
      if (!by_name(before, name)) added.push_back(name);
    for (const auto& name : names(before))
      if (!by_name(later, name)) dropped.push_back(name);
  };
  compare(stored.at("configurations"), now.at("configurations"), g.added_configurations, g.dropped_configurations);
  compare(stored.value("problems", json::array()), now.value("problems", json::array()), g.added_problems,
          g.dropped_problems);
  g.repetitions_before = stored.value("repetitions", 0);
  g.repetitions_now = now.value("repetitions", 0);
  return g;
}

std::string conflicts_message(const std::string& file, const std::string& experiment,
                              const std::vector<std::string>& lines) {
  std::string text =
      file + " holds trials of experiment " + in_quotes(experiment) + " that the experiment file now runs otherwise:";
  for (const auto& line : lines) text += "\n  " + line;
  return text +
         "\nnothing in it was changed: give a changed configuration or problem a new name (its stored trials stay "
         "under the old one), or give another results file (--db). An experiment may gain configurations, "
         "problems and repetitions: only the new trials run.";
}

}  // namespace aco::studies
