#pragma once
// acobench's results database: SQLite in the layout of OMPL's benchmark databases, so that OMPL's
// own tools read it as it is (ompl_benchmark_statistics -p and -v, Planner Arena's queries) and
// an OMPL log appended with ompl_benchmark_statistics -a leaves a database acobench still reads.
//
// Mapping of an acobench experiment onto OMPL's tables (an OMPL "experiment" is one problem):
//   experiments     one row per PROBLEM, in the order given to the constructor: id, name,
//                   totaltime (sum of the stored trials' times, s), timelimit (the trial time
//                   limit, s), memorylimit (the trial memory limit, MiB; both 0: none, or not
//                   recorded before format 7), runcount (repetitions), version ("aco <version>"),
//                   hostname, cpuinfo, date (creation, UTC), seed (the experiment's master seed;
//                   each trial's own is runs.trial_seed), setup (the problem as JSON), plus the
//                   experiment properties optimal_length (exact A* on the baseline's graph) and
//                   anyangle_length (the exact any-angle optimum, aco/any_angle.hpp, on flat maps;
//                   NULL if unknown).
//   plannerConfigs  one row per configuration, OMPL's three columns: id, name, settings (its
//                   resolved settings, JSON).
//   plannerPlugins  plannerid, plugins: per slot the binary the configuration last ran (name,
//                   version, file, sha256, build; JSON), when known.
//   enums           OMPL's table of ENUM values: name (a runs column), value, description; the
//                   rows of every ENUM column (status, stopped_by, outcome, failure).
//   runs            one row per trial: id, experimentid, plannerid, then a column per trial field
//                   of the runs table (trial_fields(), trial_record.hpp, where each says what it
//                   holds; a field added later is added, NULL for the stored rows): repetition and
//                   trial_seed (declared INT: identities, not measurements, which OMPL's script
//                   leaves out), solved, solution_length (after the smoother), grid_length, gap,
//                   optimal_corridor (BOOLEAN: the final path in the any-angle optimum's corridor,
//                   aco/corridor.hpp; added with the first trial on a flat grid),
//                   turns, iterations, best_iteration, time (s), ant_steps, stopped_by (ENUM),
//                   the simulation measures (outcome (ENUM), time_to_goal, collisions, replans,
//                   clearance, control_steps: columns added with the first simulation trial),
//                   failure (ENUM, NULL unless failed; added with the first failed trial), memory (the peak resident
//                   memory of the process that ran the trial, MiB: TrialRecord::peak_memory_mib; NULL if not known),
//                   status (OMPL's planner status, ENUM: Exact solution, Timeout (not solved, or over the time limit),
//                   Crash, Abort (any other failure)); UNIQUE(experimentid, plannerid, repetition). An ENUM column
//                   holds the index of its value, described by the enums rows. A simulation trial's length is the
//                   distance driven, its path the trajectory, its stopped_by the outcome.
//                   solution_length, grid_length and gap are NULL when unsolved; gap is
//                   grid_length / optimal_length - 1 (the relative excess of the grid path over
//                   exact A* on the same graph, as acoplan reports it), NULL if the optimum is
//                   unknown. trial_seed holds the 64-bit seed's bits as SQLite's signed integer.
//   run_texts       runid, path (JSON waypoints), error (why a trial failed: what the plugin or
//                   the host threw; NULL otherwise): free text, out of the runs table whose every
//                   column Planner Arena offers as a measurement.
//   progress        one row per iteration of a trial: runid, time, iteration (a count: the
//                   iterations run, 1 after the first, whose Context::iteration is 0),
//                   best_cost (NULL until an ant arrived), walks. time is OMPL's: seconds since
//                   the search started, measured at the end of the iteration (steady clock);
//                   walks is the candidate paths the planner built by then, cumulative (ants'
//                   walks, one per ant and colony; IFWA's and PSO's evaluations; 1 for A*). Rows
//                   stored by an acobench of format 3 or earlier have walks NULL and an estimated
//                   time (iteration * runs.time / iterations): the report leaves those runs out of
//                   its time and walk charts. The key is (runid, iteration), not OMPL's (runid,
//                   time): the times of two iterations of a very fast run may coincide.
//   properties      one row per property of a trial (aco::PlanOutcome::properties): runid, name,
//                   value (integer, real or text as SQLite stores it). The planners' own
//                   ("ant_steps", "stopped_by" of aco; "evaluations" of ifwa and pso) and the
//                   figures the run's plugins recorded, "<slot>/<plugin>.<name>" (Context::record(),
//                   add()); acobench's "time_limit" (s) of a trial of a time-limit-from
//                   configuration, the limit it was given. Trials of format 4 or earlier have none.
//   acobench_meta   key/value: format_version, experiment_name and fingerprint (a canonical text
//                   from the caller naming everything that defines the trials; of a grown
//                   experiment, of every configuration and problem it held: growth.hpp);
//                   host_version and host_build (ACO_BUILD_OPTIMISATION) of the acobench that ran
//                   the trials last.
//
// Rows of OMPL logs appended with `ompl_benchmark_statistics -a` (experiments whose version is
// not "aco ...", planner configurations whose settings are OMPL's text) are not the
// experiment's: problems(), configs() and trials() leave them out, appended_runs() reads them.
//
// Older formats: a database of format 1 to 6 is migrated to 7 when opened (its runs table rebuilt
// in the new layout in one transaction; limits it did not record are 0); a value the new layout
// cannot hold (a stopped_by no ENUM lists) is an Error naming it, and the file is left as it was.
//
// Resuming: each trial is one transaction (its runs row with all its progress rows) in WAL mode,
// so a process killed at any moment (SIGKILL included) leaves every committed trial whole and no
// partial one; finished() tells a rerun what to skip. synchronous=NORMAL keeps commits across a
// killed process; only a power cut may lose the last few.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "aco/studies/growth.hpp"
#include "aco/studies/provenance.hpp"
#include "aco/studies/trial_record.hpp"

namespace aco::studies {

// OMPL's per-experiment limits (experiments.timelimit, memorylimit, runcount, seed).
struct ExperimentLimits {
  double time_limit_s = 0.0;  // 0: none
  double memory_limit_mib = 0.0;  // 0: none
  int runs = 0;  // repetitions per configuration
  std::uint64_t seed = 0;  // the master seed
};

// A run of an OMPL benchmark log appended to the database (ompl_benchmark_statistics -a).
struct AppendedRun {
  std::string experiment, planner;
  bool solved = false;
  double time_s = 0.0;
  double length = std::nan("");  // solution_length; NaN if none
};

// A stored row that does not hold what its table declares (the trial fields' types and ranges,
// trial_record.hpp; ids that name rows): a file edited by hand or by another tool.
struct BadRow {
  std::string table;
  std::int64_t id = 0;  // the row's id (a progress or run_texts row: its run's)
  std::string column;
  std::string problem;  // what the column holds and why it cannot be read
};
// "runs row 17, column solution_length: the text 'abc', not a number"
std::string describe(const BadRow& row);

class ResultsDb {
 public:
  // Creates the database, or reopens one of the same experiment. The experiment may have grown
  // (growth.hpp): its new problems get their rows (problems are matched by name), and stored
  // problems it no longer names are left out of finished(), failed() and trials(). A database
  // holding another experiment (another name, or trials the experiment now runs otherwise: the
  // refusal lists each conflict on a line), a file that is not an acobench database, or one of
  // another format version is an aco::Error naming the file and what differs, and nothing in the
  // file is touched.
  ResultsDb(const std::filesystem::path& file, const std::string& experiment_name, const std::string& fingerprint,
            const std::vector<ProblemRecord>& problems);
  // Opens an existing results database for reading (reports); Error if it is not one.
  explicit ResultsDb(const std::filesystem::path& file);
  ~ResultsDb();
  ResultsDb(const ResultsDb&) = delete;
  ResultsDb& operator=(const ResultsDb&) = delete;

  // The id of the configuration: the existing one if its name is stored with the same settings
  // (compared as JSON values; of acobench's settings, the resolved run and plugin binaries, not
  // the keys that wrote them); an Error listing the differences if the name is stored with other
  // settings. Its plugins, if given, replace the stored ones.
  int add_config(const ConfigRecord& config);

  // (problem, config id, repetition) of every stored trial, sorted: 12 bytes a trial, so that a
  // resumed study of millions of trials holds little more than its database's index. A runs row
  // whose trial cannot be told (a NULL or dangling experiment or planner id, a configuration whose
  // settings are not JSON, a repetition out of range) is an Error naming it: a rerun would run that
  // trial a second time.
  std::vector<std::tuple<int, int, int>> finished() const;
  // (problem, config id, repetition) -> (failure, error) of every stored trial that failed (rows
  // finished() refuses are left out).
  std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> failed() const;
  // What the experiment given to the constructor added to the database (empty if it made it).
  Growth growth() const;

  // Stores one trial and its progress rows in one transaction. Thread-safe. An unknown problem or
  // config, or a curve whose length is not `iterations`, is an Error, and nothing is written; so
  // is a trial already stored, unless `if_stored` is skip: then nothing is written and the result
  // is false (another process running the same experiment into the file stored it first, with the
  // same seed). A trial without anytime curves (copied from an older database) gets the older
  // rows: the estimated time, walks NULL.
  enum class IfStored { error, skip };
  bool store(const TrialRecord& trial, IfStored if_stored = IfStored::error);

  // The experiment's limits, as OMPL records them in each of its rows of the experiments table.
  void record_limits(const ExperimentLimits& limits);
  ExperimentLimits limits() const;  // of the first problem's row

  // For reports.
  std::vector<ProblemRecord> problems() const;
  std::vector<std::pair<int, ConfigRecord>> configs() const;  // (id, record) in insertion order
  // Every trial, ordered by (problem, config, repetition), each row checked against its fields'
  // types and ranges. A row that cannot be read is an Error naming it, or, given `left_out`, is
  // left out and added there.
  std::vector<TrialRecord> trials(std::vector<BadRow>* left_out = nullptr) const;
  // The runs of appended OMPL logs, ordered by experiment and planner.
  std::vector<AppendedRun> appended_runs() const;
  std::string meta(const std::string& key) const;  // Error if the key is not stored
  std::optional<std::string> find_meta(const std::string& key) const;
  // Stores a key of acobench_meta beyond those open() writes (e.g. the ablation path).
  void set_meta(const std::string& key, const std::string& value);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace aco::studies
