#include "aco/studies/report.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>
#include <variant>

#include "aco/error.hpp"
#include "aco/plugin_record.hpp"
#include "aco/run_spec.hpp"
#include "aco/studies/experiment.hpp"
#include "aco/studies/plots.hpp"
#include "report_analysis.hpp"
#include "aco/studies/report_document.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/statistics.hpp"

namespace aco::studies {
namespace {

std::string number(double v, int digits = 4) {
  if (!std::isfinite(v)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

struct Column {
  std::string title;
  std::function<std::string(const Result&)> value;
};

std::vector<Column> columns() {
  return {
      {"runs", [](const Result& r) { return std::to_string(r.runs.size()); }},
      {"success", [](const Result& r) { return fixed(100 * r.success, 0) + " %"; }},
      {"mean", [](const Result& r) { return fixed(r.length.mean, 3); }},
      {"sd", [](const Result& r) { return fixed(r.length.stddev, 3); }},
      {"median", [](const Result& r) { return fixed(r.length.median, 3); }},
      {"IQR", [](const Result& r) { return fixed(r.length.iqr, 3); }},
      {"95 % CI",
       [](const Result& r) {
         return std::isfinite(r.length.ci_low)
                    ? "[" + fixed(r.length.ci_low, 2) + ", " + fixed(r.length.ci_high, 2) + "]"
                    : "-";
       }},
      {"gap %", [](const Result& r) { return fixed(r.gap, 2); }},
      {"over any-angle %", [](const Result& r) { return fixed(r.over_any_angle, 2); }},
      {"optimal corridor %", [](const Result& r) { return fixed(100 * r.optimal_corridor, 0); }},
      {"other corridor: never walked / left",
       [](const Result& r) {
         return r.corridor_left < 0 ? std::string("-")
                                    : std::to_string(r.corridor_never_walked) + " / " + std::to_string(r.corridor_left);
       }},
      {"turns", [](const Result& r) { return fixed(r.turns, 1); }},
      {"best it.", [](const Result& r) { return fixed(r.best_iteration, 1); }},
      {"time ms", [](const Result& r) { return number(r.time_ms, 3); }},
      {"p (Holm)", [](const Result& r) { return number(r.p_holm, 3); }},
      {"A12",
       [](const Result& r) {
         return std::isfinite(r.a12) ? fixed(r.a12, 2) + " " + std::string(to_string(effect_size(r.a12))) : "-";
       }},
  };
}

// Problems from one scenario file share a set name: "arena#40" belongs to "arena".
std::string problem_set(const std::string& problem) { return problem.substr(0, problem.find('#')); }

// The problem sets in the order of their first problem, each with its problems' indices.
std::vector<std::pair<std::string, std::vector<std::size_t>>> problem_sets(const Analysis& a) {
  std::vector<std::pair<std::string, std::vector<std::size_t>>> sets;
  for (std::size_t p = 0; p < a.problems.size(); ++p) {
    const std::string set = problem_set(a.problems[p].name);
    const auto it = std::find_if(sets.begin(), sets.end(), [&](const auto& s) { return s.first == set; });
    (it == sets.end() ? sets.emplace_back(set, std::vector<std::size_t>{}) : *it).second.push_back(p);
  }
  return sets;
}

// Per problem set and configuration (when a set has several problems): solved share, gap and
// time over all its runs; and the gap by difficulty bucket where the problems carry buckets.
// The simulation problems' own measures (acosim scenarios as problems), or no table if none.
std::vector<Table> simulation_tables(const Analysis& a) {
  Table t{"Simulations",
          "Problems that are acosim scenarios: share of runs that reached the goal, runs that ended in a collision, "
          "mean simulated time to the goal (reached runs), mean of each run's smallest clearance, mean replans, "
          "and how the other runs ended. The length columns of these problems are the distance driven.",
          {"problem", "configuration", "runs", "reached", "collisions", "time to goal s", "clearance", "replans",
           "other outcomes"},
          {}};
  for (std::size_t p = 0; p < a.problems.size(); ++p)
    for (const Result& r : a.results[p]) {
      std::vector<double> times, clearances, replans;
      std::map<std::string, int> outcomes;
      int simulated = 0, reached = 0, collisions = 0;
      for (const auto* trial : r.runs) {
        if (!trial->simulation) continue;
        const SimulationRecord& sim = *trial->simulation;
        ++simulated;
        if (trial->solved)
          ++reached, times.push_back(sim.time_to_goal);
        else
          ++outcomes[sim.outcome];
        collisions += sim.collisions;
        if (std::isfinite(sim.clearance)) clearances.push_back(sim.clearance);
        replans.push_back(sim.replans);
      }
      if (simulated == 0) continue;
      std::string other;
      for (const auto& [outcome, count] : outcomes)
        other += (other.empty() ? "" : ", ") + outcome + " " + std::to_string(count);
      t.rows.push_back({a.problems[p].name, a.configs[r.config].second.name, std::to_string(simulated),
                        fixed(100.0 * reached / simulated, 1) + " %", std::to_string(collisions),
                        fixed(mean_of(times), 1), fixed(mean_of(clearances), 3), fixed(mean_of(replans), 2),
                        other.empty() ? "-" : other});
    }
  if (t.rows.empty()) return {};
  return {t};
}

// Trials that failed (a plugin's exception, crash, time-out or memory overrun): how many per
// configuration and kind (runs.stopped_by), and the first message.
std::vector<Table> failure_tables(const Analysis& a) {
  const std::vector<std::string> kinds{"error", "crashed", "timed out", "out of memory"};
  Table t{"Failed trials",
          "Trials that ended without a result: an exception (from a plugin or the host), a crash, a time-out "
          "(--trial-timeout) or a memory overrun (--trial-memory) in their worker process. They count as unsolved "
          "above; the experiment went on without them.",
          {"configuration", "failed", "runs", "exception", "crashed", "timed out", "out of memory", "first failure"},
          {}};
  for (std::size_t c = 0; c < a.configs.size(); ++c) {
    std::size_t failed = 0, runs = 0;
    std::map<std::string, std::size_t> by_kind;
    std::string first;
    for (std::size_t p = 0; p < a.problems.size(); ++p)
      for (const auto* trial : a.results[p][c].runs) {
        ++runs;
        if (trial->error.empty()) continue;
        ++by_kind[trial->stopped_by];
        if (failed++ == 0) first = trial->error;
      }
    if (failed == 0) continue;
    std::vector<std::string> row{a.configs[c].second.name, std::to_string(failed), std::to_string(runs)};
    for (const auto& kind : kinds) row.push_back(std::to_string(by_kind[kind]));
    row.push_back(first);
    t.rows.push_back(row);
  }
  if (t.rows.empty()) return {};
  return {t};
}

// A configuration's settings without its null model: what a twin shares with its subject.
std::string settings_without_null_model(const ConfigRecord& config, std::string* null_model) {
  auto j = nlohmann::json::parse(config.settings_json);
  nlohmann::json& run = j["run"];
  const std::string model = run.contains("null-model") ? run["null-model"].get<std::string>() : "none";
  if (null_model) *null_model = model;
  run.erase("null-model");
  j.erase("keys");  // the twin's keys add null-model; the resolved run says all
  return j.dump();
}

// Each configuration against its null models (docs/learning.md), found by their settings: a
// twin is a configuration whose resolved settings equal the subject's but for null-model.
std::vector<Table> pheromone_tables(const Analysis& a) {
  Table t{"Does the pheromone matter?",
          "Each configuration against its null models, over every run of every problem with a known optimum that both "
          "ran: the "
          "no-learning twin (the same pipeline with the pheromone ignored and never updated) and the restart twin (the "
          "same number of walks as independent one-iteration runs); docs/learning.md defines them. Solved runs, mean "
          "and largest gap % of the solved runs, the ratio of the mean gaps; p is the two-sided Mann-Whitney U test of "
          "the configuration's gaps against the twin's over all runs (an unsolved run ranks as the largest gap), "
          "Holm-corrected across the rows; A12 < 0.5 means smaller gaps than the twin. "
          "'problems better / worse': problems where the configuration's lengths differ from the twin's (Mann-Whitney, "
          "Holm-corrected across all problems and rows, p < 0.05) in its favour / against it.",
          {"configuration", "twin", "solved", "mean gap %", "twin's", "ratio", "max gap %", "twin's", "p (Holm)", "A12",
           "problems better / worse", "verdict"},
          {}};
  std::vector<std::string> subject_key(a.configs.size()), model(a.configs.size());
  for (std::size_t c = 0; c < a.configs.size(); ++c)
    subject_key[c] = settings_without_null_model(a.configs[c].second, &model[c]);
  struct Pair {
    std::size_t subject, twin;
    std::vector<double> gaps, twin_gaps;  // solved runs
    std::vector<double> ranked, twin_ranked;  // every run, an unsolved one as the largest gap: for the test and A12
    std::size_t solved = 0, twin_solved = 0, runs = 0, twin_runs = 0;
  };
  std::vector<Pair> pairs;
  for (std::size_t s = 0; s < a.configs.size(); ++s)
    for (std::size_t w = 0; model[s] == "none" && w < a.configs.size(); ++w)
      if (model[w] != "none" && subject_key[w] == subject_key[s]) pairs.push_back({s, w, {}, {}, {}, {}});
  if (pairs.empty()) return {};

  std::vector<double> pooled_p, per_problem_p;
  std::vector<std::pair<std::size_t, bool>> per_problem;  // (pair, subject shorter) per comparison
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    Pair& pair = pairs[i];
    for (std::size_t p = 0; p < a.problems.size(); ++p) {
      const Result& r = a.results[p][pair.subject];
      const Result& w = a.results[p][pair.twin];
      // Only problems both ran: a study stopped part-way must not pool one side's problems alone.
      if (r.runs.empty() || w.runs.empty()) continue;
      pair.runs += r.runs.size(), pair.twin_runs += w.runs.size();
      pair.solved += r.lengths.size(), pair.twin_solved += w.lengths.size();
      if (!(a.problems[p].optimal_length > 0)) continue;
      pair.gaps.insert(pair.gaps.end(), r.gaps.begin(), r.gaps.end());
      pair.twin_gaps.insert(pair.twin_gaps.end(), w.gaps.begin(), w.gaps.end());
      for (auto [from, to] : {std::pair{&r, &pair.ranked}, std::pair{&w, &pair.twin_ranked}}) {
        to->insert(to->end(), from->gaps.begin(), from->gaps.end());
        to->insert(to->end(), from->runs.size() - from->gaps.size(), std::numeric_limits<double>::max());
      }
      if (r.lengths.empty() || w.lengths.empty()) continue;
      per_problem_p.push_back(mann_whitney_u(r.lengths, w.lengths).p);
      per_problem.emplace_back(i, vargha_delaney_a12(r.lengths, w.lengths) < 0.5);
    }
    pooled_p.push_back(
        pair.ranked.empty() || pair.twin_ranked.empty() ? 1.0 : mann_whitney_u(pair.ranked, pair.twin_ranked).p);
  }
  const auto pooled_holm = holm_adjust(pooled_p);
  const auto per_problem_holm = holm_adjust(per_problem_p);
  std::vector<int> better(pairs.size(), 0), worse(pairs.size(), 0);
  for (std::size_t k = 0; k < per_problem.size(); ++k)
    if (per_problem_holm[k] < 0.05) ++(per_problem[k].second ? better : worse)[per_problem[k].first];

  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pair& pair = pairs[i];
    const bool compared = !pair.ranked.empty() && !pair.twin_ranked.empty();
    const double a12 = compared ? vargha_delaney_a12(pair.ranked, pair.twin_ranked) : NAN;
    const double mean = mean_of(pair.gaps), twin_mean = mean_of(pair.twin_gaps);
    std::string verdict = "no optimum known";
    if (compared)
      verdict = pooled_holm[i] >= 0.05 ? "no evidence of a difference"
                : a12 < 0.5            ? "beats the twin"
                                       : "the twin is better";
    t.rows.push_back({a.configs[pair.subject].second.name, model[pair.twin],
                      std::to_string(pair.solved) + "/" + std::to_string(pair.runs) + " vs " +
                          std::to_string(pair.twin_solved) + "/" + std::to_string(pair.twin_runs),
                      fixed(mean, 3), fixed(twin_mean, 3), twin_mean > 0 ? fixed(mean / twin_mean, 2) : "-",
                      fixed(largest(pair.gaps), 2), fixed(largest(pair.twin_gaps), 2),
                      compared ? number(pooled_holm[i], 3) : "-",
                      compared ? fixed(a12, 2) + " " + std::string(to_string(effect_size(a12))) : "-",
                      std::to_string(better[i]) + " / " + std::to_string(worse[i]), verdict});
  }
  return {t};
}

// Two final lengths this close (relative) are a tie: the same path up to rounding, as when both
// planners find the straight line.
constexpr double kTieTolerance = 1e-9;

// Each OMPL configuration with time-limit-from against the configuration whose time it was given,
// trial by trial (the same problem and repetition): who is shorter at the same time.
std::vector<Table> equal_time_tables(const Analysis& a) {
  Table t{"Same time, who is shorter",
          "Each OMPL configuration whose time limit is another's time (time-limit-from), paired trial by trial with "
          "that configuration (the colony): on each problem and repetition OMPL's solve() had the time the colony's "
          "trial took (OMPL's path simplification comes on top). 'equal time': pairs whose OMPL trial recorded that "
          "time as its limit. Final path lengths are compared (after the smoother; OMPL's continuous paths); lengths "
          "within a relative 1e-9 are a tie. pairs = both solved + only colony + only OMPL + neither; both solved = "
          "colony shorter + OMPL shorter + ties. Ratio: colony length / OMPL length over the pairs both solved "
          "(< 1: the colony shorter), its mean and its worst (largest).",
          {"colony", "OMPL", "problem set", "pairs", "equal time", "both solved", "only colony", "only OMPL", "neither",
           "colony shorter", "OMPL shorter", "ties", "mean ratio", "worst ratio"},
          {},
          "lll"};
  const auto sets = problem_sets(a);
  for (std::size_t ompl = 0; ompl < a.configs.size(); ++ompl) {
    const auto settings = nlohmann::json::parse(a.configs[ompl].second.settings_json, nullptr, false);
    if (!settings.is_object() || !settings.contains("run") || !settings["run"].contains(kTimeLimitFrom)) continue;
    const std::string from = settings["run"][kTimeLimitFrom].get<std::string>();
    const auto colony = static_cast<std::size_t>(
        std::find_if(a.configs.begin(), a.configs.end(), [&](const auto& c) { return c.second.name == from; }) -
        a.configs.begin());
    if (colony == a.configs.size()) continue;
    struct Counts {
      std::size_t pairs = 0, equal_time = 0, both = 0, only_colony = 0, only_ompl = 0, neither = 0, colony_shorter = 0,
                  ompl_shorter = 0, ties = 0;
      std::vector<double> ratios;
      Counts& operator+=(const Counts& o) {
        pairs += o.pairs, equal_time += o.equal_time, both += o.both, only_colony += o.only_colony;
        only_ompl += o.only_ompl, neither += o.neither, colony_shorter += o.colony_shorter;
        ompl_shorter += o.ompl_shorter, ties += o.ties;
        ratios.insert(ratios.end(), o.ratios.begin(), o.ratios.end());
        return *this;
      }
    };
    const auto add_row = [&](const std::string& set, const Counts& n) {
      t.rows.push_back({from, a.configs[ompl].second.name, set, std::to_string(n.pairs), std::to_string(n.equal_time),
                        std::to_string(n.both), std::to_string(n.only_colony), std::to_string(n.only_ompl),
                        std::to_string(n.neither), std::to_string(n.colony_shorter), std::to_string(n.ompl_shorter),
                        std::to_string(n.ties), fixed(mean_of(n.ratios), 3), fixed(largest(n.ratios), 3)});
    };
    Counts all;
    for (const auto& [set, members] : sets) {
      Counts n;
      for (const std::size_t p : members) {
        std::map<int, const TrialRecord*> colony_runs;
        for (const auto* run : a.results[p][colony].runs) colony_runs[run->repetition] = run;
        for (const auto* o : a.results[p][ompl].runs) {
          const auto found = colony_runs.find(o->repetition);
          if (found == colony_runs.end()) continue;
          const TrialRecord& c = *found->second;
          ++n.pairs;
          const auto limit = o->properties.find("time_limit");
          if (limit != o->properties.end() && numeric(limit->second) == c.time_s) ++n.equal_time;
          if (!c.solved || !o->solved) {
            ++(c.solved ? n.only_colony : o->solved ? n.only_ompl : n.neither);
            continue;
          }
          ++n.both;
          if (std::abs(c.length - o->length) <= kTieTolerance * std::max(c.length, o->length))
            ++n.ties;
          else
            ++(c.length < o->length ? n.colony_shorter : n.ompl_shorter);
          if (o->length > 0.0) n.ratios.push_back(c.length / o->length);
        }
      }
      add_row(set, n);
      all += n;
    }
    if (sets.size() > 1) add_row("all", all);
  }
  if (t.rows.empty()) return {};
  return {t};
}

// Per configuration, each numeric property of its runs over all problems: the planners' own
// (ant_steps, evaluations) and the figures its plugins recorded.
std::vector<Table> property_tables(const Analysis& a) {
  Table t{"Run properties and plugin figures",
          "Per configuration, over its runs of every problem that have it: each numeric property of a run, the "
          "planner's own (ant_steps of the colony, evaluations of ifwa and pso) and the figures its plugins "
          "recorded (\"<slot>/<plugin>.<name>\", Context::record() and add()). runs.csv holds every run's values.",
          {"configuration", "property", "runs", "median", "min", "max", "mean"},
          {}};
  for (std::size_t c = 0; c < a.configs.size(); ++c) {
    std::map<std::string, std::vector<double>> values;
    for (std::size_t p = 0; p < a.problems.size(); ++p)
      for (const auto* trial : a.results[p][c].runs)
        for (const auto& [name, value] : trial->properties)
          if (const auto number = numeric(value)) values[name].push_back(*number);
    for (const auto& [name, v] : values) {
      const Summary s = summarize(v);
      t.rows.push_back({a.configs[c].second.name, name, std::to_string(s.n), number(s.median, 6), number(s.min, 6),
                        number(s.max, 6), number(s.mean, 6)});
    }
  }
  if (t.rows.empty()) return {};
  return {t};
}

// One slot's plugin binary as a configuration last ran it.
struct PluginUse {
  std::string slot, name, version, build, sha256, file;
};

// The binaries of a configuration's slots: as its last run recorded them, or for a database
// stored before that (format 4 or earlier) the name, version and hash its settings keep.
std::vector<PluginUse> plugin_uses(const ConfigRecord& config) {
  const bool recorded = !config.plugins_json.empty();
  const auto plugins = recorded
                           ? nlohmann::json::parse(config.plugins_json)
                           : nlohmann::json::parse(config.settings_json).value("plugins", nlohmann::json::object());
  std::vector<PluginUse> uses;
  for (const auto& [slot, p] : plugins.items())
    uses.push_back({slot, p.value("name", "?"), p.value("version", "?"), p.value("build", "not recorded"),
                    p.value("sha256", "?"), p.value("file", "not recorded")});
  return uses;
}

std::vector<Table> provenance_tables(const Analysis& a) {
  Table t{"Plugins",
          "The plugin binary of each slot of each configuration, as its last run found it: file, version, build "
          "(unoptimised: a Debug build, whose times mean little) and SHA-256 of the file. Trials were run by " +
              (a.host_version.empty() ? std::string("an acobench that did not record its version") : a.host_version) +
              (a.host_build.empty() ? "" : ", " + a.host_build) + ".",
          {"configuration", "slot", "plugin", "version", "build", "SHA-256", "file"},
          {}};
  for (const auto& [id, config] : a.configs)
    for (const PluginUse& use : plugin_uses(config))
      t.rows.push_back({config.name, use.slot, use.name, use.version, use.build, use.sha256, use.file});
  if (t.rows.empty()) return {};
  return {t};
}

// Unoptimised (Debug) builds the trials ran: the host, and each plugin binary with the
// configurations that ran it.
std::vector<std::string> build_warnings(const Analysis& a) {
  std::vector<std::string> warnings;
  if (aco::unoptimised(a.host_build))
    warnings.push_back("the trials were run by an unoptimised build of acobench (" + a.host_version +
                       "): their times mean little; run them again with a Release build (cmake --preset release)");
  std::map<std::string, std::vector<std::string>> debug_plugins;  // "slot/name (file)" -> configurations
  for (const auto& [id, config] : a.configs) {
    // Another planner than the colony runs only the smoother of its pipeline (and acosim the local planner).
    const auto run = nlohmann::json::parse(config.settings_json).value("run", nlohmann::json::object());
    const bool colony = run.value("planner", "aco") == "aco";
    for (const PluginUse& use : plugin_uses(config))
      if (aco::unoptimised(use.build) && (colony || use.slot == "smoother" || use.slot == "local"))
        debug_plugins[use.slot + "/" + use.name + " (" + use.file + ")"].push_back(config.name);
  }
  for (const auto& [plugin, configs] : debug_plugins) {
    std::string names;
    for (const auto& name : configs) names += (names.empty() ? "'" : ", '") + name + "'";
    warnings.push_back("plugin " + plugin + " is an unoptimised build (configurations " + names +
                       "): their times mean little; build it with CMAKE_BUILD_TYPE=Release and run them again");
  }
  return warnings;
}

std::vector<Table> summary_tables(const Analysis& a) {
  std::vector<Table> tables = failure_tables(a);
  for (Table& t : property_tables(a)) tables.push_back(std::move(t));
  for (Table& t : simulation_tables(a)) tables.push_back(std::move(t));
  for (Table& t : pheromone_tables(a)) tables.push_back(std::move(t));
  for (Table& t : equal_time_tables(a)) tables.push_back(std::move(t));
  const auto sets = problem_sets(a);
  if (sets.size() == a.problems.size()) return tables;
  Table totals{"Summary by problem set",
               "Over every run of every problem of the set: solved share, gap of the solved runs' grid paths to the "
               "exact grid optimum "
               "(mean and largest), and time per run.",
               {"problem set", "configuration", "problems", "runs", "solved", "mean gap %", "max gap %", "mean time ms",
                "max time ms"},
               {}};
  const auto gaps_of = [](const Result& r, std::vector<double>& gaps) {
    gaps.insert(gaps.end(), r.gaps.begin(), r.gaps.end());
  };
  for (const auto& [set, members] : sets)
    for (std::size_t c = 0; c < a.configs.size(); ++c) {
      std::vector<double> gaps, times;
      std::size_t runs = 0, solved = 0;
      for (std::size_t p : members) {
        const Result& r = a.results[p][c];
        runs += r.runs.size();
        solved += r.lengths.size();
        for (const auto* t : r.runs) times.push_back(t->time_s * 1000.0);
        gaps_of(r, gaps);
      }
      totals.rows.push_back({set, a.configs[c].second.name, std::to_string(members.size()), std::to_string(runs),
                             runs ? fixed(100.0 * solved / runs, 1) + " %" : "-", fixed(mean_of(gaps), 2),
                             fixed(largest(gaps), 2), number(mean_of(times), 3), number(largest(times), 3)});
    }
  tables.push_back(totals);
  Table by_bucket{
      "Gap by difficulty bucket",
      "Each problem set's scenarios in four groups of about equal size by Moving AI bucket (scenario column 1, "
      "optimal length / 4): mean gap % of the solved runs, and the solved share where below 100 %.",
      {"problem set", "buckets", "problems"},
      {}};
  for (std::size_t c = 0; c < a.configs.size(); ++c) by_bucket.header.push_back(a.configs[c].second.name);
  for (const auto& [set, members] : sets) {
    std::vector<std::size_t> ps = members;
    if (ps.size() < 4 || std::any_of(ps.begin(), ps.end(), [&](std::size_t p) { return a.buckets[p] < 0; })) continue;
    std::stable_sort(ps.begin(), ps.end(), [&](std::size_t x, std::size_t y) { return a.buckets[x] < a.buckets[y]; });
    for (std::size_t g = 0; g < 4; ++g) {
      const std::size_t from = g * ps.size() / 4, to = (g + 1) * ps.size() / 4;
      std::vector<std::string> row{set,
                                   std::to_string(a.buckets[ps[from]]) + "-" + std::to_string(a.buckets[ps[to - 1]]),
                                   std::to_string(to - from)};
      for (std::size_t c = 0; c < a.configs.size(); ++c) {
        std::vector<double> gaps;
        std::size_t runs = 0, solved = 0;
        for (std::size_t i = from; i < to; ++i) {
          const Result& r = a.results[ps[i]][c];
          runs += r.runs.size();
          solved += r.lengths.size();
          gaps_of(r, gaps);
        }
        std::string cell = fixed(mean_of(gaps), 2);
        if (solved < runs) cell += " (" + fixed(runs ? 100.0 * solved / runs : 0.0, 0) + " % solved)";
        row.push_back(cell);
      }
      by_bucket.rows.push_back(row);
    }
  }
  if (!by_bucket.rows.empty()) tables.push_back(by_bucket);
  return tables;
}

std::string target_name(double target) { return "gap <= " + fixed(target, 0) + " %"; }

std::string unmeasured_note(const Analysis& a) {
  if (a.unmeasured == 0) return "";
  return " " + std::to_string(a.unmeasured) +
         " runs stored by an older acobench (format 3 or earlier) have no measured "
         "times and walks and are left out.";
}

// Per configuration and target: how many of its runs on the problems with a known optimum came
// within the target, and how fast.
std::vector<Table> anytime_tables(const Analysis& a) {
  Table t{
      "Anytime: fixed targets",
      "Over every (problem, run) pair of the problems with a known optimum: the share of runs whose best-so-far grid "
      "path came within the target gap to the optimum, the median wall time (since the search began) and walks "
      "(candidate paths built) at which the runs that did got there, and the expected running time ERT = (time the "
      "runs spent until they reached the target, or in all if they never did) / runs that reached it." +
          unmeasured_note(a),
      {"configuration", "target", "runs", "reached", "median time s", "median walks", "ERT s"},
      {}};
  const auto all = reaches(a);
  for (std::size_t c = 0; c < a.configs.size(); ++c)
    for (std::size_t k = 0; k < kTargets.size(); ++k) {
      const auto& runs = all[c];
      if (runs.empty()) continue;
      std::vector<double> seconds, walks, hits, spent;
      for (const Reach& r : runs) {
        hits.push_back(r.seconds[k]);
        spent.push_back(r.seconds_spent);
        if (!std::isfinite(r.seconds[k])) continue;
        seconds.push_back(r.seconds[k]);
        walks.push_back(r.walks[k]);
      }
      t.rows.push_back({a.configs[c].second.name, target_name(kTargets[k]), std::to_string(runs.size()),
                        fixed(100.0 * double(seconds.size()) / double(runs.size()), 1) + " %",
                        number(summarize(seconds).median, 3), number(summarize(walks).median, 6),
                        number(expected_running_time(hits, spent), 3)});
    }
  // Without rows the table still says why, if older runs are the reason.
  if (t.rows.empty() && a.unmeasured == 0) return {};
  return {t};
}

// The report's figures: each drawn inline in report.html and also written alone as
// plots/<file>, so that a page (the project's docs/results.md) can show one as an image.
class FigureFiles {
 public:
  // A figure whose file name is made of `name` (characters unsafe in a file name become '-', a
  // name already taken gets -2, -3, ...).
  Figure add(const std::string& name, std::string svg) {
    std::string safe;
    for (const char c : name) safe += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' ? c : '-';
    std::string unique = safe;
    for (int n = 2; !taken_.insert(unique).second; ++n) unique = safe + "-" + std::to_string(n);
    return {unique + ".svg", std::move(svg), ""};
  }

 private:
  std::set<std::string> taken_;
};

// IOHanalyzer's fixed-target ECDF, one chart per target: per configuration, the share of its
// (problem, run) pairs within the target by each time.
std::vector<Figure> ecdf_charts(const Analysis& a, FigureFiles& files) {
  const auto all = reaches(a);
  double low = INFINITY, high = 0.0;
  for (const auto& t : a.trials)
    if (a.problems[t.problem].optimal_length > 0 && !t.elapsed_s.empty() && t.elapsed_s.front() > 0) {
      low = std::min(low, t.elapsed_s.front());
      high = std::max(high, t.elapsed_s.back());
    }
  if (!(high >= low)) return {};
  std::vector<Figure> figures;
  for (std::size_t k = 0; k < kTargets.size(); ++k) {
    LineChart chart;
    chart.title = "runs within " + fixed(kTargets[k], 0) + " % of the optimum, by time (ECDF)";
    chart.x_label = "wall time since the search began, s (log scale)";
    chart.y_label = "share of (problem, run) pairs";
    chart.css_class = "ecdf";
    chart.log_x = chart.steps = true;
    chart.y_range = std::pair(0.0, 1.0);
    for (std::size_t c = 0; c < a.configs.size(); ++c) {
      if (all[c].empty()) continue;
      std::vector<double> hits;
      for (const Reach& r : all[c]) hits.push_back(r.seconds[k]);
      chart.series.push_back(ecdf_series(a.configs[c].second.name, hits, low, high));
      chart.series.back().style = c;
    }
    figures.push_back(files.add("ecdf-" + fixed(kTargets[k], 0) + "pct", line_chart_svg(chart)));
  }
  return figures;
}

// The mean best-so-far gap of each configuration's measured runs on problem p, against wall time
// and against walks (log scales, 100 points between the first iteration's end and the last's).
std::vector<Figure> anytime_charts(const Analysis& a, std::size_t p, FigureFiles& files) {
  const double optimal = a.problems[p].optimal_length;
  if (!(optimal > 0)) return {};
  struct Effort {
    const char* file;
    const char* title;
    const char* label;
    std::function<std::vector<double>(const TrialRecord&)> of;
  };
  const Effort efforts[] = {
      {"anytime-time-", "best-so-far gap against time (mean of the runs): ",
       "wall time since the search began, s (log scale)", [](const TrialRecord& t) { return t.elapsed_s; }},
      {"anytime-walks-", "best-so-far gap against walks (mean of the runs): ",
       "walks: candidate paths built (log scale)", [](const TrialRecord& t) { return as_reals(t.walks); }},
  };
  std::vector<Figure> figures;
  for (const Effort& effort : efforts) {
    std::vector<std::pair<int, std::vector<StepCurve>>> by_config;
    double low = INFINITY, high = 0.0;
    for (const Result& r : a.results[p]) {
      std::vector<StepCurve> curves;
      for (const TrialRecord* t : r.runs) {
        if (t->elapsed_s.empty()) continue;
        curves.push_back({effort.of(*t), gap_curve(*t, optimal)});
        low = std::min(low, curves.back().x.front());
        high = std::max(high, curves.back().x.back());
      }
      if (!curves.empty()) by_config.emplace_back(r.config, std::move(curves));
    }
    if (by_config.empty() || !(low > 0)) continue;
    LineChart chart;
    chart.title = effort.title + a.problems[p].name;
    chart.x_label = effort.label;
    chart.y_label = "gap to the optimum %";
    chart.css_class = "anytime";
    chart.log_x = true;
    for (const auto& [config, curves] : by_config) {
      chart.series.push_back(mean_series(a.configs[config].second.name, curves, log_spaced(low, high, 100), true));
      chart.series.back().style = static_cast<std::size_t>(config);
      // No confidence band: early on, while only one or two runs have a path, it spans hundreds of %.
      chart.series.back().band_low.clear();
      chart.series.back().band_high.clear();
    }
    figures.push_back(files.add(effort.file + a.problems[p].name, line_chart_svg(chart)));
  }
  return figures;
}

// The keys of the problem's map as the configuration's trials planned on it: the file, reader and
// map parameters the problem recorded, with the terrain options of the configuration's run
// (max-slope decides which cells of a height map are blocked, cell-size where a path's points lie).
aco::Keys problem_map_keys(const Analysis& a, const ProblemRecord& problem, const ConfigRecord& config) {
  const auto setup = nlohmann::json::parse(problem.setup_json);
  aco::Keys keys{{"map", (a.experiment_dir / setup.at("map").get<std::string>()).string()}};
  if (setup.contains("map-format")) keys["map-format"] = setup.at("map-format").get<std::string>();
  // Held by name: items() of a temporary would dangle in the loop.
  const nlohmann::json map_parameters = setup.value("map-parameters", nlohmann::json::object());
  for (const auto& [name, value] : map_parameters.items()) keys["map." + name] = value.get<std::string>();
  const auto run = nlohmann::json::parse(config.settings_json).value("run", nlohmann::json::object());
  for (const aco::ParamSpec& terrain : aco::problem_parameters())
    if (run.contains(terrain.name) && run.at(terrain.name).is_number())
      keys[terrain.name] = run.at(terrain.name).dump();
  keys.erase("scen-index");
  return keys;
}

// Whether two maps draw alike: the same cells blocked, the same cell size.
bool same_picture(const aco::Map& x, const aco::Map& y) {
  if (x.width() != y.width() || x.height() != y.height() || x.depth() != y.depth() ||
      x.position({1, 0}) != y.position({1, 0}))
    return false;
  for (int row = 0; row < x.height(); ++row)
    for (int column = 0; column < x.width(); ++column)
      if (x.passable({column, row}) != y.passable({column, row})) return false;
  return true;
}

// The problem's map with each configuration's best path: one picture per map the configurations
// planned on (terrain options that block other cells of a height map make another). Each set of
// map keys is loaded once: configurations with the same terrain options share the map.
std::vector<Figure> path_pictures(const Analysis& a, std::size_t p, FigureFiles& files) {
  struct Picture {
    std::vector<aco::Keys> keys;  // every set of map keys that loads a map drawn alike
    std::unique_ptr<aco::Map> map;
    std::vector<MapPath> paths;
  };
  std::vector<Picture> pictures;
  const auto picture_of = [&](const ConfigRecord& config) -> Picture& {
    aco::Keys keys = problem_map_keys(a, a.problems[p], config);
    for (Picture& picture : pictures)
      if (std::find(picture.keys.begin(), picture.keys.end(), keys) != picture.keys.end()) return picture;
    auto map = aco::load_problem_map(aco::resolve_problem(keys, *a.registry), a.registry);
    for (Picture& picture : pictures)
      if (same_picture(*picture.map, *map)) {
        picture.keys.push_back(std::move(keys));
        return picture;
      }
    return pictures.emplace_back(Picture{{std::move(keys)}, std::move(map), {}});
  };
  std::vector<std::pair<const ConfigRecord*, MapPath>> paths;
  for (const Result& r : a.results[p]) {
    if (!r.best) continue;
    MapPath path{
        a.configs[r.config].second.name + " " + fixed(r.best->length, 2), static_cast<std::size_t>(r.config), {}, {}};
    for (const auto& point : nlohmann::json::parse(r.best->path_json)) {
      path.points.push_back({point[0].get<double>(), point[1].get<double>()});
      if (point.size() == 3) path.layers.push_back(point[2].get<double>());
    }
    paths.emplace_back(&a.configs[r.config].second, std::move(path));
  }
  try {
    for (auto& [config, path] : paths) picture_of(*config).paths.push_back(std::move(path));
    // A problem no configuration solved still shows its map.
    if (pictures.empty() && !a.configs.empty()) picture_of(a.configs.front().second);
  } catch (const std::exception& e) {
    return {{"", "", "map not drawn: " + std::string(e.what())}};
  }
  std::vector<Figure> figures;
  for (const Picture& picture : pictures)
    figures.push_back(files.add("paths-" + a.problems[p].name, map_paths_svg(*picture.map, picture.paths)));
  return figures;
}

// Per problem: every configuration's summary, then its pictures.
void add_problem(const Analysis& a, std::size_t p, FigureFiles& files, std::vector<Block>& blocks) {
  const double optimal = a.problems[p].optimal_length;
  const std::string& problem = a.problems[p].name;
  const double any_angle = a.problems[p].anyangle_length;
  Table t{
      problem + " (optimal " + fixed(optimal, 4) + (any_angle > 0 ? ", any-angle " + fixed(any_angle, 4) : "") + ")",
      "",
      {"configuration"},
      {},
      "l"};
  const auto cols = columns();
  for (const auto& c : cols) t.header.push_back(c.title);
  for (const auto& r : a.results[p]) {
    std::vector<std::string> row{a.configs[r.config].second.name};
    for (const auto& c : cols) row.push_back(c.value(r));
    t.rows.push_back(std::move(row));
  }
  blocks.emplace_back(std::move(t));

  BoxPlot box{"final path length: " + problem, "path length", {}, optimal > 0 ? std::optional(optimal) : std::nullopt};
  LineChart chart;
  chart.title = "best-so-far length (mean, 95 % CI): " + problem;
  chart.y_label = "path length";
  if (optimal > 0) chart.reference = optimal;
  for (const auto& r : a.results[p]) {
    const std::string& name = a.configs[r.config].second.name;
    box.samples.push_back({name, r.lengths});
    std::vector<std::vector<double>> curves;
    for (const auto* trial : r.runs)
      if (!trial->best_so_far.empty()) curves.push_back(trial->best_so_far);
    if (!curves.empty()) {
      chart.series.push_back(convergence_series(name, curves));
      chart.series.back().style = static_cast<std::size_t>(r.config);
    }
  }
  blocks.emplace_back(files.add("box-" + problem, box_plot_svg(box)));
  if (!chart.series.empty()) blocks.emplace_back(files.add("convergence-" + problem, line_chart_svg(chart)));
  for (Figure& figure : anytime_charts(a, p, files)) blocks.emplace_back(std::move(figure));
  for (Figure& figure : path_pictures(a, p, files)) blocks.emplace_back(std::move(figure));
}

// The runs of OMPL benchmark logs appended to the database (ompl_benchmark_statistics -a), per
// experiment and planner, in the measures every planner has.
std::vector<Table> appended_tables(const Analysis& a) {
  Table t{"Planners of appended OMPL logs",
          "Runs that OMPL's own benchmark wrote and `ompl_benchmark_statistics -a` appended to this database: "
          "each OMPL experiment is its own problem. Length is OMPL's solution_length of solved runs.",
          {"OMPL experiment", "planner", "runs", "solved %", "mean time s", "mean length", "longest"},
          {},
          "llrrrrr"};
  for (std::size_t first = 0; first < a.appended.size();) {
    std::size_t end = first;
    std::vector<double> times, lengths;
    int solved = 0;
    for (; end < a.appended.size() && a.appended[end].experiment == a.appended[first].experiment &&
           a.appended[end].planner == a.appended[first].planner;
         ++end) {
      const AppendedRun& run = a.appended[end];
      times.push_back(run.time_s);
      solved += run.solved;
      if (run.solved && std::isfinite(run.length)) lengths.push_back(run.length);
    }
    const auto runs = static_cast<double>(end - first);
    t.rows.push_back({a.appended[first].experiment, a.appended[first].planner, std::to_string(end - first),
                      fixed(100.0 * solved / runs, 1), fixed(mean_of(times), 4),
                      lengths.empty() ? "" : fixed(mean_of(lengths), 3),
                      lengths.empty() ? "" : fixed(largest(lengths), 3)});
    first = end;
  }
  if (t.rows.empty()) return {};
  return {t};
}

// The whole report: what the analysis found, in the order a reader wants it.
ReportDocument report_document(const Analysis& a, const std::filesystem::path& database) {
  ReportDocument d{"acobench report: " + a.name, "acobench: " + a.name, {}};
  std::vector<Block>& blocks = d.blocks;
  blocks.emplace_back(Paragraph{
      "Database `" + database.filename().string() + "`: " + std::to_string(a.trials.size()) + " runs, " +
      std::to_string(a.configs.size()) + " configurations, " + std::to_string(a.problems.size()) +
      " problems. Lengths are final path lengths of solved runs (after the smoother: any-angle when it "
      "shortcuts); gap is "
      "the mean excess of the grid path (before smoothing) over the exact A* optimum on the baseline's "
      "graph, so that both "
      "are lengths on the same grid; over any-angle is the mean excess of the final path over the exact "
      "any-angle optimum (touching obstacles allowed, a lower bound of every path: docs/maps.md), the "
      "yardstick of smoothed and continuous paths; p is the two-sided Mann-Whitney U test against the baseline (`" +
      (a.configs.empty() ? "" : a.configs[0].second.name) +
      "`), Holm-corrected across all comparisons; A12 < 0.5 means shorter paths than the baseline."});
  for (std::string& warning : build_warnings(a)) blocks.emplace_back(Warning{std::move(warning)});
  FigureFiles files;
  for (Table& t : summary_tables(a)) blocks.emplace_back(std::move(t));
  for (Table& t : anytime_tables(a)) {
    const bool reached = !t.rows.empty();
    blocks.emplace_back(std::move(t));
    if (reached)
      blocks.emplace_back(
          Paragraph{"report.html plots the share of runs within each target against time (the ECDF) and, "
                    "per problem, the mean best-so-far gap against time and against walks.",
                    true});
    for (Figure& figure : ecdf_charts(a, files)) blocks.emplace_back(std::move(figure));
  }
  for (Table& t : appended_tables(a)) blocks.emplace_back(std::move(t));
  for (std::size_t p = 0; p < a.problems.size(); ++p) add_problem(a, p, files, blocks);
  if (!a.average_rank.empty()) {
    Table ranking{"Ranking across problems",
                  "Average rank of the mean length (1 = best; Friedman/Demšar).",
                  {"rank", "configuration", "average rank"},
                  {},
                  "rl"};
    std::vector<std::size_t> order(a.configs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](auto x, auto y) { return a.average_rank[x] < a.average_rank[y]; });
    for (std::size_t i = 0; i < order.size(); ++i)
      ranking.rows.push_back(
          {std::to_string(i + 1), a.configs[order[i]].second.name, fixed(a.average_rank[order[i]], 2)});
    blocks.emplace_back(std::move(ranking));
  }
  if (!a.ablation_path.empty()) {
    Table steps{
        "Ablation path",
        "From the baseline towards the target, one component at a time, keeping the best flip (Fawcett and Hoos). "
        "Mean gap over all problems:",
        {"step", "configuration", "mean gap %"},
        {},
        "rl"};
    Series gaps;
    gaps.name = "mean gap %";
    gaps.value = ablation_gaps(a);
    for (std::size_t s = 0; s < a.ablation_path.size(); ++s)
      steps.rows.push_back({std::to_string(s), a.ablation_path[s], fixed(gaps.value[s], 2)});
    blocks.emplace_back(std::move(steps));
    LineChart chart;
    chart.title = "ablation path: mean gap to the optimum";
    chart.x_label = "step";
    chart.y_label = "gap %";
    chart.series = {gaps};
    blocks.emplace_back(files.add("ablation", line_chart_svg(chart)));
  }
  for (Table& t : provenance_tables(a)) blocks.emplace_back(std::move(t));
  return d;
}

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw aco::Error("cannot write " + file.string());
}

}  // namespace

std::vector<std::filesystem::path> write_report(const std::filesystem::path& database, const std::filesystem::path& out,
                                                std::vector<std::string>* warnings,
                                                const std::vector<std::filesystem::path>& plugin_dirs) {
  if (!std::filesystem::exists(database)) throw aco::Error(database.string() + ": no such results database");
  const ResultsDb db(database);
  Analysis a = analyse(db);
  aco::PluginRegistry registry(plugin_dirs);
  a.registry = &registry;
  std::filesystem::create_directories(out);
  const ReportDocument document = report_document(a, database);
  std::vector<std::filesystem::path> files = {out / "report.md", out / "report.html", out / "runs.csv"};
  write(files[0], render_markdown(document));
  write(files[1], render_html(document, "<p>All runs: <a href=\"runs.csv\">runs.csv</a></p>\n"));
  write(files[2], runs_csv(a.trials, a.problems, a.configs));
  std::filesystem::create_directories(out / "plots");
  for (const Block& block : document.blocks)
    if (const auto* figure = std::get_if<Figure>(&block); figure && !figure->svg.empty()) {
      files.push_back(out / "plots" / figure->file);
      write(files.back(), figure->svg);
    }
  if (warnings)
    for (std::string& warning : build_warnings(a)) warnings->push_back(std::move(warning));
  return files;
}

}  // namespace aco::studies
