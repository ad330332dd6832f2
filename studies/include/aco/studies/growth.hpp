#pragma once
// Experiments that grow: a results database holds the trials of an experiment's fingerprint
// (Experiment::fingerprint); an experiment file that gains configurations, problems or
// repetitions runs only the new trials into it, as long as every trial the database holds is
// still the same run. What would make a stored trial another run is a conflict, one line each:
// a configuration of the same name with other resolved settings, a problem of the same name set
// up otherwise, another seed, another plugin binary, another ablation target.
#include <string>
#include <vector>

#include "aco/studies/trial_record.hpp"

namespace aco::studies {

// The conflicts between the fingerprint a database holds and the experiment's now, one line
// each ("configuration 'elite': update.rho 0.1 -> 0.2"); empty when the stored trials are all
// still valid. Texts that are not acobench's JSON fingerprints conflict unless equal.
std::vector<std::string> fingerprint_conflicts(const std::string& stored, const std::string& now);

// The same for problems of the same name (their setups and optimal lengths).
std::vector<std::string> problem_conflicts(const std::vector<ProblemRecord>& stored,
                                           const std::vector<ProblemRecord>& now);

// The same for configurations' settings as the database stores them (settings_json): the same
// when their resolved runs and plugin binaries are, whatever keys wrote them.
std::vector<std::string> config_conflicts(const std::string& name, const std::string& stored_settings,
                                          const std::string& now_settings);

// The fingerprint of a database that held `stored` and took the trials of `now` (no conflicts):
// every configuration and problem of either (stored first, in their order), the larger
// repetitions, every plugin binary.
std::string merged_fingerprint(const std::string& stored, const std::string& now);

// What `now` adds to `stored`, and what it no longer names (its stored trials stay, are not run
// and are reported): for a run's summary. Empty for texts that are not JSON fingerprints.
struct Growth {
  std::vector<std::string> added_configurations, added_problems;
  int repetitions_before = 0, repetitions_now = 0;
  std::vector<std::string> dropped_configurations, dropped_problems;  // in the database, not in the file
  bool grew() const {
    return !added_configurations.empty() || !added_problems.empty() || repetitions_now > repetitions_before;
  }
};
Growth growth(const std::string& stored, const std::string& now);

// How to read a refusal: the database file, the lines, what to do.
std::string conflicts_message(const std::string& file, const std::string& experiment,
                              const std::vector<std::string>& lines);

}  // namespace aco::studies
