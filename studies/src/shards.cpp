#include "aco/studies/shards.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <tuple>

#include "aco/error.hpp"
#include "aco/studies/growth.hpp"
#include "aco/studies/results_db.hpp"

namespace aco::studies {
namespace {

using aco::Error;

std::optional<int> whole_number(const std::string& text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// What a trial measured, its times aside: two copies of a trial must agree on it. Its walks are
// left out too: a copy stored by an acobench of format 3 has none, and they follow from the same
// seeded search as the best-so-far curve, which is compared.
std::string results_text(const TrialRecord& t) {
  std::ostringstream text;
  text.precision(17);
  text << t.seed << ' ' << t.solved << ' ' << t.length << ' ' << t.grid_length << ' ' << t.turns << ' ' << t.iterations
       << ' ' << t.best_iteration << ' ' << t.ant_steps << ' ' << t.stopped_by << ' ' << t.path_json << ' ' << t.error;
  for (const double b : t.best_so_far) text << ' ' << b;
  if (t.simulation)
    text << ' ' << t.simulation->outcome << ' ' << t.simulation->time_to_goal << ' ' << t.simulation->collisions << ' '
         << t.simulation->replans << ' ' << t.simulation->clearance << ' ' << t.simulation->control_steps;
  return text.str();
}

// A trial by what names it in every database of the experiment: problem name, configuration
// name, repetition (ids and problem positions differ between databases of a grown experiment).
using TrialKey = std::tuple<std::string, std::string, int>;

struct Input {
  std::filesystem::path file;
  std::string name, fingerprint;
  std::optional<Shard> shard;
  std::map<int, ConfigRecord> configs;  // by the input's id
  std::vector<ProblemRecord> problems;  // in the input's order
};

Input read_input(const std::filesystem::path& file) {
  const ResultsDb db(file);
  Input input{file, db.meta("experiment_name"), db.meta("fingerprint"), std::nullopt, {}, db.problems()};
  if (const auto shard = db.find_meta("shard")) input.shard = parse_shard(*shard);
  for (auto& [id, config] : db.configs()) input.configs.emplace(id, std::move(config));
  return input;
}

std::string label(const TrialKey& key) {
  return "trial (problem '" + std::get<0>(key) + "', configuration '" + std::get<1>(key) + "', repetition " +
         std::to_string(std::get<2>(key)) + ")";
}

}  // namespace

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  const auto index = whole_number(text.substr(0, slash)),
             count = slash == std::string::npos ? std::nullopt : whole_number(text.substr(slash + 1));
  if (!index || !count || *count < 1 || *index < 1 || *index > *count)
    throw Error("--shard '" + text + "': expected K/N, shard K of N with 1 <= K <= N (e.g. 2/8)");
  return {*index, *count};
}

std::string to_string(const Shard& shard) { return std::to_string(shard.index) + "/" + std::to_string(shard.count); }

std::size_t shard_size(const Shard& shard, std::size_t trials) {
  const auto count = static_cast<std::size_t>(shard.count), before = static_cast<std::size_t>(shard.index - 1);
  return trials / count + (before < trials % count ? 1 : 0);
}

std::size_t fixed_trial_index(std::size_t config_position, std::size_t problem, std::size_t repetition,
                              std::size_t problems, std::size_t repetitions) {
  return (config_position * problems + problem) * repetitions + repetition;
}

MergeSummary merge_databases(const std::vector<std::filesystem::path>& inputs, const std::filesystem::path& output) {
  if (inputs.empty()) throw Error("acobench merge: no databases to merge");
  std::vector<Input> read;
  for (const auto& file : inputs) {
    if (std::filesystem::exists(output) && std::filesystem::exists(file) && std::filesystem::equivalent(file, output))
      throw Error(file.string() + " is both an input and the output of the merge");
    read.push_back(read_input(file));
  }
  const Input& first = read.front();
  std::optional<int> shard_count;
  std::map<std::string, std::string> shard_files;  // "K/N" -> file
  // Databases of one experiment at different sizes merge (a grown experiment's): what they hold
  // of each other's must be the same runs.
  std::string fingerprint = first.fingerprint;
  std::vector<ProblemRecord> problems = first.problems;
  std::map<std::string, std::string> settings;  // configuration name -> the first input's settings
  for (const Input& input : read) {
    if (input.name != first.name)
      throw Error("cannot merge " + input.file.string() + " (experiment '" + input.name + "') with " +
                  first.file.string() + " (experiment '" + first.name + "'): they hold different experiments");
    auto conflicts = fingerprint_conflicts(fingerprint, input.fingerprint);
    for (auto& line : problem_conflicts(problems, input.problems)) conflicts.push_back(std::move(line));
    for (const auto& [id, config] : input.configs) {
      const auto [held, fresh] = settings.emplace(config.name, config.settings_json);
      if (!fresh)
        for (auto& line : config_conflicts(config.name, held->second, config.settings_json))
          conflicts.push_back(std::move(line));
    }
    if (!conflicts.empty()) {
      std::string lines;
      for (const auto& line : conflicts) lines += "\n  " + line;
      throw Error("cannot merge " + input.file.string() + " with " + first.file.string() + ": experiment '" +
                  first.name +
                  "' was run with other trials, from another experiment file or other plugin binaries (taking the "
                  "databases before it as stored):" +
                  lines);
    }
    fingerprint = merged_fingerprint(fingerprint, input.fingerprint);
    for (const auto& p : input.problems)
      if (std::none_of(problems.begin(), problems.end(), [&](const ProblemRecord& q) { return q.name == p.name; }))
        problems.push_back(p);
    if (!input.shard) continue;
    if (shard_count && *shard_count != input.shard->count)
      throw Error("cannot merge " + input.file.string() + " (shard " + to_string(*input.shard) + ") with shards of " +
                  std::to_string(*shard_count) + ": the shards of one split have the same count");
    shard_count = input.shard->count;
    const auto [given, fresh] = shard_files.emplace(to_string(*input.shard), input.file.string());
    if (!fresh)
      throw Error("shard " + to_string(*input.shard) + " is given twice: " + given->second + " and " +
                  input.file.string());
  }

  // Before anything is written: every trial found, and two copies of one checked to agree.
  std::map<TrialKey, std::pair<std::size_t, std::string>> results;  // -> (input, its results_text)
  MergeSummary summary;
  const auto check = [&](const TrialKey& key, std::size_t input, const std::string& text, const std::string& where) {
    const auto [held, fresh] = results.emplace(key, std::make_pair(input, text));
    if (fresh) return;
    if (held->second.second != text)
      throw Error("cannot merge: " + label(key) + " is in " + where + " and in " +
                  read[held->second.first].file.string() +
                  " with different results; the same binaries gave two answers (another machine's libraries?), so "
                  "neither is kept; nothing was written");
    ++summary.duplicates;
  };
  const auto key_of = [](const TrialRecord& t, const std::vector<ProblemRecord>& ps, const std::string& config) {
    return TrialKey{ps.at(static_cast<std::size_t>(t.problem)).name, config, t.repetition};
  };
  for (std::size_t i = 0; i < read.size(); ++i)
    for (const auto& t : ResultsDb(read[i].file).trials())
      check(key_of(t, read[i].problems, read[i].configs.at(t.config).name), i, results_text(t), read[i].file.string());

  ResultsDb out(output, first.name, fingerprint, problems);
  std::map<int, std::string> out_names;  // by the output's id
  for (const auto& [id, config] : out.configs()) out_names.emplace(id, config.name);
  std::set<TrialKey> present;
  for (const auto& t : out.trials()) {
    const TrialKey key = key_of(t, problems, out_names.at(t.config));
    present.insert(key);
    const auto held = results.find(key);
    if (held != results.end() && held->second.second != results_text(t))
      throw Error("cannot merge: " + label(key) + " is in " + output.string() + " and in " +
                  read[held->second.first].file.string() + " with different results; nothing was written");
    if (held != results.end()) ++summary.duplicates;
  }

  for (std::size_t i = 0; i < read.size(); ++i) {
    std::map<int, int> to_out;
    for (const auto& [id, config] : read[i].configs) {
      const int out_id = out.add_config(config);
      to_out.emplace(id, out_id);
      out_names.emplace(out_id, config.name);
    }
    for (auto t : ResultsDb(read[i].file).trials()) {
      const TrialKey key = key_of(t, read[i].problems, read[i].configs.at(t.config).name);
      if (results.at(key).first != i || present.contains(key)) continue;
      t.config = to_out.at(t.config);
      const std::string& problem = std::get<0>(key);
      t.problem = static_cast<int>(
          std::find_if(problems.begin(), problems.end(), [&](const ProblemRecord& p) { return p.name == problem; }) -
          problems.begin());
      out.store(t);
      ++summary.copied;
    }
  }
  const ResultsDb first_db(first.file);
  for (const char* key : {"experiment_file", "ablation_path", "host_version", "host_build"})
    if (const auto value = first_db.find_meta(key)) out.set_meta(key, *value);
  out.record_limits(first_db.limits());

  // Which of the configurations' trials no input holds, by the shard that should have.
  const auto experiment = nlohmann::json::parse(fingerprint);
  const auto repetitions = experiment.at("repetitions").get<std::size_t>();
  const auto& configurations = experiment.at("configurations");
  summary.ablation_left = experiment.contains("ablation_target") && !first_db.find_meta("ablation_path");
  std::map<int, std::pair<std::size_t, std::size_t>> by_shard;  // shard index (0: no shards) -> (missing, of)
  std::set<TrialKey> stored;
  for (const auto& t : out.trials()) stored.insert(key_of(t, problems, out_names.at(t.config)));
  for (std::size_t c = 0; c < configurations.size(); ++c)
    for (std::size_t p = 0; p < problems.size(); ++p)
      for (std::size_t r = 0; r < repetitions; ++r) {
        const std::size_t index = fixed_trial_index(c, p, r, problems.size(), repetitions);
        const int shard = shard_count ? static_cast<int>(index % static_cast<std::size_t>(*shard_count)) + 1 : 0;
        auto& [missing, of] = by_shard[shard];
        ++of;
        ++summary.expected;
        if (stored.contains({problems[p].name, configurations[c].at("name").get<std::string>(), static_cast<int>(r)}))
          continue;
        ++missing;
        ++summary.missing;
      }
  for (const auto& [shard, counts] : by_shard) {
    if (counts.first == 0) continue;
    const std::string name = shard ? to_string(Shard{shard, *shard_count}) : "";
    summary.missing_by_shard.push_back((shard ? "shard " + name + ": " : "") + std::to_string(counts.first) + " of " +
                                       std::to_string(counts.second) + " trials missing" +
                                       (shard_files.contains(name) ? " (" + shard_files.at(name) + " is not complete)"
                                        : shard                    ? " (not given)"
                                                                   : ""));
  }
  return summary;
}

}  // namespace aco::studies
