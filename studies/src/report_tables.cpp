#include "report_tables.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "aco/plugin_record.hpp"
#include "aco/studies/statistics.hpp"
#include "report_comparisons.hpp"
#include "report_numbers.hpp"

namespace aco::studies {
namespace {

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
                    ? std::string("[") + fixed(r.length.ci_low, 2) + ", " + fixed(r.length.ci_high, 2) + "]"
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

std::string target_name(double target) { return "gap <= " + fixed(target, 0) + " %"; }

std::string unmeasured_note(const Analysis& a) {
  if (a.unmeasured == 0) return "";
  return std::string(" ") + std::to_string(a.unmeasured) +
         " runs stored by an older acobench (format 3 or earlier) have no measured "
         "times and walks and are left out.";
}

}  // namespace

Table problem_table(const Analysis& a, std::size_t p) {
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
  return t;
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

std::vector<Table> ranking_tables(const Analysis& a) {
  if (a.average_rank.empty()) return {};
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
  return {ranking};
}

std::vector<Table> ablation_tables(const Analysis& a) {
  if (a.ablation_path.empty()) return {};
  Table steps{
      "Ablation path",
      "From the baseline towards the target, one component at a time, keeping the best flip (Fawcett and Hoos). "
      "Mean gap over all problems:",
      {"step", "configuration", "mean gap %"},
      {},
      "rl"};
  const std::vector<double> gaps = ablation_gaps(a);
  for (std::size_t s = 0; s < a.ablation_path.size(); ++s)
    steps.rows.push_back({std::to_string(s), a.ablation_path[s], fixed(gaps[s], 2)});
  return {steps};
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

}  // namespace aco::studies
