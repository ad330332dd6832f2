#include "report_comparisons.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "aco/studies/experiment.hpp"
#include "aco/studies/statistics.hpp"
#include "report_numbers.hpp"

namespace aco::studies {
namespace {

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

// Two final lengths this close (relative) are a tie: the same path up to rounding, as when both
// planners find the straight line.
constexpr double kTieTolerance = 1e-9;

}  // namespace

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

}  // namespace aco::studies
