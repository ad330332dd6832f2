#pragma once
// What a trial of a study measured, and the problems and configurations it names: plain records,
// which the results database stores (results_db.hpp), the trial runner makes (trial_runner.hpp),
// and worker processes and MPI ranks send (as CBOR) without knowing of the database.
//
// A trial's single values are declared once more, in trial_fields(): each field's name, type and
// where it goes. The messages, the runs table (its columns, INSERT and SELECT, the columns an older
// database lacks), runs.csv and Python's read_trials() all walk that table, so a new field is a
// member here and an entry there.
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "aco/process/failure_kind.hpp"
#include "aco/parameters.hpp"

namespace aco::studies {

struct ProblemRecord {
  std::string name;
  std::string setup_json;  // the problem: map file, start, goal, neighbourhood...
  double optimal_length;  // < 0: unknown (read back as -1)
  // The exact any-angle optimum (aco/any_angle.hpp): the shortest path at any angles, the
  // yardstick of smoothed and continuous paths; < 0: unknown (a terrain or simulation problem).
  double anyangle_length = -1.0;
};

struct ConfigRecord {
  std::string name;
  std::string settings_json;  // the full resolved settings
  // Per slot, the plugin binary the configuration last ran: name, version, file, sha256, build
  // (aco::plugins_json). Not part of its identity (a moved or rebuilt file is told, not refused
  // here: the experiment's fingerprint refuses other binaries); "" when not known.
  std::string plugins_json = {};
};

// What a simulation trial (an acosim scenario as a problem) measured beyond solved and length.
struct SimulationRecord {
  std::string outcome;  // one of aco::simulation::kOutcomes
  double time_to_goal = std::nan("");  // simulated seconds; NaN unless reached (stored as NULL)
  int collisions = 0;
  int replans = 0;
  double clearance = std::nan("");  // the smallest distance between the robot and an obstacle
  int control_steps = 0;
};

// Why a trial failed: the kinds the worker processes say too (aco/process/failure_kind.hpp), timed_out
// and out_of_memory being the trial time and memory limits; their texts are runs.failure's, the
// JSON messages' and Python's.
using aco::failure_kind;
using aco::FailureKind;
using aco::to_string;

struct TrialRecord {
  int problem = 0;  // index into the problems given to the constructor
  int config = 0;  // id returned by add_config()
  int repetition = 0;
  std::uint64_t seed = 0;
  bool solved = false;
  double length = 0, grid_length = 0;  // only meaningful when solved (read back as 0 otherwise)
  // Whether the final path runs through the corridor of the exact any-angle optimum
  // (aco/corridor.hpp); none when unsolved or on maps other than flat grids (stored as NULL).
  std::optional<bool> optimal_corridor;
  int turns = 0, iterations = 0, best_iteration = 0;
  double time_s = 0;
  std::uint64_t ant_steps = 0;
  std::string stopped_by;
  std::string path_json;  // "[[x,y],...]" or "[[x,y,z],...]"
  std::vector<double> best_so_far;  // one per iteration; +infinity until solved (stored as NULL)
  // The anytime curves (aco::SearchResult's), one value per iteration each; both empty for a trial
  // read from rows without them (stored by an acobench of format 3 or earlier).
  std::vector<double> elapsed_s;
  std::vector<std::uint64_t> walks;
  std::optional<SimulationRecord> simulation;  // simulation trials only (NULL columns otherwise)
  // A trial that failed: the message (solved false; stopped_by "error", "crashed", "timed out" or
  // "out of memory") and why; "" and none otherwise.
  std::string error;
  FailureKind failure = FailureKind::none;
  // The run's properties (aco::PlanOutcome::properties): the planner's ("ant_steps",
  // "evaluations"...) and the plugins' figures ("update/max_min.restarts").
  std::map<std::string, aco::ParamValue> properties;
  // The peak resident memory (Linux's VmHWM), MiB, of the process that ran the trial, read as it
  // ended. A worker process (acobench run) starts its peak over before each trial: the trial's own
  // peak, the worker's resident memory when it began included. A trial run in the process that
  // asked for it (acobench run --in-process, Python, MPI ranks without workers) shares it with the
  // trials before and beside it: the process's peak so far, an upper bound. NaN (NULL) where not
  // known: a trial that crashed, timed out or ran out of memory, one stored before the field was.
  double peak_memory_mib = std::nan("");
};

// One value of a trial's row: NULL, or of its field's type.
using TrialCell = std::variant<std::monostate, bool, std::int64_t, std::uint64_t, double, std::string>;

enum class TrialCellType { boolean, integer, count, real, text };  // count: 64 bits unsigned

// Where a field goes (a bit set).
enum TrialFieldUse : unsigned {
  kInMessage = 1,  // the JSON a worker process or an MPI rank sends (trial_messages.hpp)
  kInRunsTable = 2,  // a column of the results database's runs table (results_db.hpp)
  kInRunsCsv = 4,  // a column of the report's runs.csv, after problem and configuration
  kInPython = 8,  // a column of Python's read_database()
  kEverywhere = 15,
  // A column of the database's run_texts table instead: free text, which OMPL's tools would take
  // for a measurement of the runs table (Planner Arena offers every runs column as one).
  kInRunTexts = 16,
  // A runs column added when the first trial with a value is stored (the simulation measures,
  // failure):
  // a study without them has no empty columns, which OMPL's script would plot as empty pages.
  kWhenUsed = 32,
};

struct TrialField {
  const char* name;  // its JSON key and runs column
  const char* column;  // its runs.csv and Python column
  TrialCellType type;
  unsigned use;  // TrialFieldUse bits
  int csv_digits;  // significant digits of a real in runs.csv
  // The value of a trial, whose problem's optimal length (< 0: unknown) derived fields need.
  std::function<TrialCell(const TrialRecord&, double optimal_length)> get;
  // Sets the member from a value; NULL leaves the record's default. Empty for derived fields,
  // which are not in messages.
  std::function<void(TrialRecord&, const TrialCell&)> set;
  // A text field's only values when it has a fixed set (failure: FailureKind's texts); else empty.
  // In the runs table such a field is one of OMPL's ENUMs: the value's index, described by the
  // rows of the enums table.
  std::vector<std::string> values;
  // Its runs or run_texts column: OMPL's name where OMPL has one (length is solution_length,
  // peak_memory_mib is memory), and no name the experiments table has (runs.seed would clash with
  // experiments.seed in Planner Arena's join).
  const char* stored_as = name;
  // false: not a measurement (repetition, the seed): declared INT, which OMPL's script, plotting
  // only BOOLEAN, ENUM, INTEGER and REAL columns, leaves out; SQLite stores it as an integer.
  bool measure = true;
  // What a stored value may be, checked where a row is read back (a number also within its
  // member's type, a real also finite): its least value, and when it may be NULL.
  double low = -std::numeric_limits<double>::infinity();
  // unless_solved: NULL exactly when unsolved; solved_only: NULL when unsolved, and when solved
  // where unknown (an OMPL planner's path has no grid length).
  enum class Null { allowed, never, unless_solved, solved_only } null = Null::allowed;
};

// Every field, in the order of the runs table's columns (after id, experimentid, plannerid) and
// of runs.csv's: problem and config, the curves (progress table) and the properties (properties
// table) are not fields. status is the runs table's alone: OMPL's planner status, an ENUM of
// planner_status_names(), derived from solved and failure.
const std::vector<TrialField>& trial_fields();

// OMPL's ompl::base::PlannerStatus texts, in its order (1.5.2): the values of runs.status, so that
// an OMPL log appended to our database (which keeps the enums rows it finds) reads alike.
const std::vector<std::string>& planner_status_names();

// The names of runs.csv's columns before the properties: problem, configuration, the fields.
std::vector<std::string> runs_csv_columns();
// The properties that get a column of their own in runs.csv and Python: every property some trial
// has, sorted, but those that are a field already (aco's ant_steps and stopped_by).
std::vector<std::string> property_columns(const std::vector<TrialRecord>& trials);
// runs.csv: one row per trial, the fields then one column per property_columns(), empty where a
// value is NULL or a trial lacks the property.
std::string runs_csv(const std::vector<TrialRecord>& trials, const std::vector<ProblemRecord>& problems,
                     const std::vector<std::pair<int, ConfigRecord>>& configs);

// What a failure kind means, for the summary at the end of a run.
std::string describe_failure(FailureKind kind);

}  // namespace aco::studies
