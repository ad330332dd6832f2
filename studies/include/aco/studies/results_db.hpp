#pragma once
// acobench's results database: SQLite in the layout of OMPL's benchmark databases, so the tools
// written for those (ompl_benchmark_statistics.py, Planner Arena) read it, and safe to resume.
//
// Mapping of an acobench experiment onto OMPL's tables (an OMPL "experiment" is one problem):
//   experiments     one row per PROBLEM, in the order given to the constructor: id, name,
//                   totaltime (sum of the stored trials' times, s), timelimit, memorylimit and
//                   runcount (NULL: not ours to know), version ("aco <version>"), hostname,
//                   cpuinfo, date (creation, UTC), seed (NULL: every trial has its own), setup
//                   (the problem as JSON), plus the experiment property optimal_length (NULL if
//                   unknown).
//   plannerConfigs  one row per configuration: id, name, settings (its resolved settings, JSON),
//                   plugins (per slot the binary it last ran: name, version, file, sha256, build;
//                   JSON, NULL if not known).
//   enums           OMPL's table of enum descriptions; empty, created for OMPL's tools.
//   runs            one row per trial: id, experimentid, plannerid, then a column per trial field
//                   of the runs table (trial_fields(), trial_record.hpp; added, NULL for the stored
//                   rows, to a database made before the field was): repetition, seed, solved,
//                   length, grid_length, gap, turns, iterations, best_iteration, time (s),
//                   ant_steps, stopped_by, path (JSON waypoints), and for simulation trials
//                   (NULL otherwise) outcome, time_to_goal (NULL unless reached), collisions,
//                   replans, clearance, control_steps; error (why a trial failed: what the
//                   plugin or the host threw; NULL otherwise), failure (why, one of
//                   kFailureKinds; NULL otherwise), peak_memory_mib (the peak resident memory
//                   of the process that ran the trial, MiB: TrialRecord; NULL if not known,
//                   and in runs stored before it was recorded); UNIQUE(experimentid, plannerid,
//                   repetition). A simulation trial's length is the distance driven, its path the
//                   trajectory, its stopped_by the outcome. length, grid_length and gap are NULL when unsolved; gap is
//                   grid_length / optimal_length - 1 (the relative excess of the grid path over
//                   exact A* on the same graph, as acoplan reports it), NULL if the optimum is
//                   unknown. seed holds the 64-bit seed's bits as SQLite's signed integer.
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
//                   add()). Trials of format 4 or earlier have none.
//   acobench_meta   key/value: format_version, experiment_name and fingerprint (a canonical text
//                   from the caller naming everything that defines the trials; of a grown
//                   experiment, of every configuration and problem it held: growth.hpp);
//                   host_version and host_build (ACO_BUILD_OPTIMISATION) of the acobench that ran
//                   the trials last.
//
// Resuming: each trial is one transaction (its runs row with all its progress rows) in WAL mode,
// so a process killed at any moment (SIGKILL included) leaves every committed trial whole and no
// partial one; finished() tells a rerun what to skip. synchronous=NORMAL keeps commits across a
// killed process; only a power cut may lose the last few.
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

  // (problem, config id, repetition) of every stored trial.
  std::set<std::tuple<int, int, int>> finished() const;
  // (problem, config id, repetition) -> (failure, error) of every stored trial that failed.
  std::map<std::tuple<int, int, int>, std::pair<FailureKind, std::string>> failed() const;
  // What the experiment given to the constructor added to the database (empty if it made it).
  Growth growth() const;

  // Stores one trial and its progress rows in one transaction. Thread-safe. A trial already
  // stored, an unknown problem or config, or a curve whose length is not `iterations` is an
  // Error, and nothing is written. A trial without anytime curves (copied from an older
  // database) gets the older rows: the estimated time, walks NULL.
  void store(const TrialRecord& trial);

  // For reports.
  std::vector<ProblemRecord> problems() const;
  std::vector<std::pair<int, ConfigRecord>> configs() const;  // (id, record) in insertion order
  std::vector<TrialRecord> trials() const;  // ordered by (problem, config, repetition)
  std::string meta(const std::string& key) const;  // Error if the key is not stored
  std::optional<std::string> find_meta(const std::string& key) const;
  // Stores a key of acobench_meta beyond those open() writes (e.g. the ablation path).
  void set_meta(const std::string& key, const std::string& value);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace aco::studies
