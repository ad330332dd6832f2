#include "aco/studies/trial_record.hpp"

#include <cstdio>
#include <set>
#include <sstream>
#include <type_traits>
#include <utility>

#include "aco/engine/colony.hpp"
#include "aco/simulation/simulation.hpp"
#include "aco/planning/yardsticks.hpp"

namespace aco::studies {
namespace {

// The texts of the kinds of failure (FailureKind::none's "" left out).
std::vector<std::string> failure_texts() {
  std::vector<std::string> texts;
  for (const char* text : aco::kFailureTexts)
    if (*text) texts.push_back(text);
  return texts;
}

// What a trial's stopped_by may say: why the colony stopped, why a trial failed (the four kinds
// the report's table of failures counts), a simulation's outcome.
std::vector<std::string> stop_texts() {
  std::vector<std::string> texts;
  for (auto reason :
       {aco::StopReason::iterations, aco::StopReason::stagnation, aco::StopReason::same_path, aco::StopReason::time})
    texts.push_back(aco::to_string(reason));
  texts.push_back(to_string(FailureKind::error));  // a trial that threw (TrialRunner::failed())
  for (FailureKind kind : {FailureKind::crashed, FailureKind::timed_out, FailureKind::out_of_memory})
    texts.push_back(to_string(kind));
  for (const char* outcome : aco::simulation::kOutcomes) texts.push_back(outcome);
  return texts;
}

// OMPL's PlannerStatus values runs.status uses.
enum PlannerStatus { kTimeout = 4, kExactSolution = 6, kCrash = 7, kAbort = 8 };

int planner_status(const TrialRecord& t) {
  if (t.solved) return kExactSolution;
  switch (t.failure) {
    case FailureKind::none:  // OMPL's TIMEOUT: "the planner failed to find a solution"
    case FailureKind::timed_out:
      return kTimeout;
    case FailureKind::crashed:
      return kCrash;
    default:
      return kAbort;
  }
}

template <class Member>
constexpr TrialCellType type_of() {
  if constexpr (std::is_same_v<Member, bool>)
    return TrialCellType::boolean;
  else if constexpr (std::is_same_v<Member, std::uint64_t>)
    return TrialCellType::count;
  else if constexpr (std::is_integral_v<Member>)
    return TrialCellType::integer;
  else if constexpr (std::is_floating_point_v<Member>)
    return TrialCellType::real;
  else
    return TrialCellType::text;
}

// NaN is NULL, as the database stores it.
template <class Member>
TrialCell cell(const Member& value) {
  if constexpr (std::is_same_v<Member, bool> || std::is_same_v<Member, std::uint64_t> ||
                std::is_same_v<Member, std::string>)
    return value;
  else if constexpr (std::is_integral_v<Member>)
    return static_cast<std::int64_t>(value);
  else
    return std::isnan(value) ? TrialCell() : TrialCell(value);
}

template <class Member>
void assign(Member& member, const TrialCell& value) {
  if (std::holds_alternative<std::monostate>(value)) return;
  if constexpr (std::is_integral_v<Member> && !std::is_same_v<Member, bool> && !std::is_same_v<Member, std::uint64_t>)
    member = static_cast<Member>(std::get<std::int64_t>(value));
  else
    member = std::get<Member>(value);
}

// A member of the record; `column` names it in runs.csv and Python when not `name`.
template <class Member>
TrialField field(const char* name, Member TrialRecord::*member, unsigned use, const char* column = nullptr,
                 int csv_digits = 10) {
  return {name,
          column ? column : name,
          type_of<Member>(),
          use,
          csv_digits,
          [member](const TrialRecord& t, double) { return cell(t.*member); },
          [member](TrialRecord& t, const TrialCell& value) { assign(t.*member, value); },
          {}};
}

TrialField stored_as(TrialField f, const char* column) {
  f.stored_as = column;
  return f;
}

// An identity of the trial, not a measurement.
TrialField label(TrialField f) {
  f.measure = false;
  return f;
}

TrialField one_of(TrialField f, std::vector<std::string> values) {
  f.values = std::move(values);
  return f;
}

TrialField at_least(TrialField f, double low) {
  f.low = low;
  return f;
}

// Never NULL in a stored row.
TrialField never_null(TrialField f) {
  f.null = TrialField::Null::never;
  return f;
}

// A length: NULL unless solved.
TrialField solved_only(const char* name, double TrialRecord::*member, TrialField::Null null) {
  TrialField f = at_least(field(name, member, kEverywhere), 0.0);
  f.get = [member](const TrialRecord& t, double) { return t.solved ? TrialCell(t.*member) : TrialCell(); };
  f.null = null;
  return f;
}

// Text that is NULL when empty.
TrialField text_or_null(const char* name, std::string TrialRecord::*member, unsigned use) {
  TrialField f = field(name, member, use);
  f.get = [member](const TrialRecord& t, double) { return (t.*member).empty() ? TrialCell() : TrialCell(t.*member); };
  return f;
}

// A measure of simulation trials: NULL for planning trials.
template <class Member>
TrialField simulation_field(const char* name, Member SimulationRecord::*member) {
  return {name,
          name,
          type_of<Member>(),
          kInMessage | kInRunsTable | kInPython | kWhenUsed,
          10,
          [member](const TrialRecord& t, double) { return t.simulation ? cell((*t.simulation).*member) : TrialCell(); },
          [member](TrialRecord& t, const TrialCell& value) {
            if (std::holds_alternative<std::monostate>(value)) return;
            if (!t.simulation) t.simulation.emplace();
            assign((*t.simulation).*member, value);
          },
          {}};
}

// The excess of a solved trial's grid path over the optimum (exact A* on the same graph) times
// `scale`: NULL if unsolved or the optimum is unknown.
TrialField gap(const char* name, unsigned use, double scale, int csv_digits) {
  return {name,
          name,
          TrialCellType::real,
          use,
          csv_digits,
          [scale](const TrialRecord& t, double optimal) {
            return t.solved && optimal > 0 ? TrialCell(scale * aco::relative_gap(t.grid_length, optimal)) : TrialCell();
          },
          {},
          {}};
}

std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string csv_real(double v, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

// Text is quoted where it must be (a comma, a quote, a line break in it).
std::string csv_cell(const TrialCell& value, int digits) {
  return std::visit(
      [digits](const auto& v) -> std::string {
        using Value = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<Value, std::monostate>)
          return "";
        else if constexpr (std::is_same_v<Value, bool>)
          return v ? "1" : "0";
        else if constexpr (std::is_same_v<Value, double>)
          return csv_real(v, digits);
        else if constexpr (std::is_same_v<Value, std::string>)
          return v.find_first_of(",\"\r\n") == std::string::npos ? v : quoted(v);
        else
          return std::to_string(v);
      },
      value);
}

// A property in a CSV cell: numbers as they are (reals to 10 significant digits), text quoted.
std::string csv_cell(const aco::ParamValue& value) {
  if (const auto* text = std::get_if<std::string>(&value)) return quoted(*text);
  if (const auto* real = std::get_if<double>(&value)) return csv_real(*real, 10);
  return aco::to_string(value);
}

}  // namespace

const std::vector<TrialField>& trial_fields() {
  constexpr unsigned kStored = kInMessage | kInRunTexts;
  static const std::vector<TrialField> fields = {
      never_null(label(at_least(field("repetition", &TrialRecord::repetition, kEverywhere), 0))),
      never_null(label(stored_as(field("seed", &TrialRecord::seed, kEverywhere), "trial_seed"))),
      never_null(field("solved", &TrialRecord::solved, kEverywhere)),
      stored_as(solved_only("length", &TrialRecord::length, TrialField::Null::unless_solved), "solution_length"),
      solved_only("grid_length", &TrialRecord::grid_length, TrialField::Null::solved_only),
      gap("gap", kInRunsTable, 1.0, 10),
      gap("gap_percent", kInRunsCsv | kInPython, 100.0, 6),
      {"optimal_corridor",
       "optimal_corridor",
       TrialCellType::boolean,
       kEverywhere | kWhenUsed,
       10,
       [](const TrialRecord& t, double) { return t.optimal_corridor ? TrialCell(*t.optimal_corridor) : TrialCell(); },
       [](TrialRecord& t, const TrialCell& value) {
         if (const auto* b = std::get_if<bool>(&value)) t.optimal_corridor = *b;
       },
       {}},
      at_least(field("turns", &TrialRecord::turns, kEverywhere), 0),
      at_least(field("iterations", &TrialRecord::iterations, kEverywhere), 0),
      at_least(field("best_iteration", &TrialRecord::best_iteration, kEverywhere), 0),
      at_least(field("time", &TrialRecord::time_s, kEverywhere, "time_s", 6), 0),
      field("ant_steps", &TrialRecord::ant_steps, kEverywhere),
      one_of(text_or_null("stopped_by", &TrialRecord::stopped_by, kEverywhere), stop_texts()),
      field("path", &TrialRecord::path_json, kStored),
      one_of(simulation_field("outcome", &SimulationRecord::outcome),
             {std::begin(aco::simulation::kOutcomes), std::end(aco::simulation::kOutcomes)}),
      at_least(simulation_field("time_to_goal", &SimulationRecord::time_to_goal), 0),
      at_least(simulation_field("collisions", &SimulationRecord::collisions), 0),
      at_least(simulation_field("replans", &SimulationRecord::replans), 0),
      simulation_field("clearance", &SimulationRecord::clearance),
      at_least(simulation_field("control_steps", &SimulationRecord::control_steps), 0),
      text_or_null("error", &TrialRecord::error, kStored | kInPython),
      {"failure", "failure", TrialCellType::text, kInMessage | kInRunsTable | kWhenUsed, 10,
       [](const TrialRecord& t, double) {
         return t.failure == FailureKind::none ? TrialCell() : TrialCell(std::string(to_string(t.failure)));
       },
       [](TrialRecord& t, const TrialCell& value) {
         if (const auto* text = std::get_if<std::string>(&value)) t.failure = failure_kind(*text);
       },
       failure_texts()},
      at_least(stored_as(field("peak_memory_mib", &TrialRecord::peak_memory_mib, kEverywhere), "memory"), 0),
      {"status",
       "status",
       TrialCellType::text,
       kInRunsTable,
       10,
       [](const TrialRecord& t, double) { return TrialCell(planner_status_names().at(planner_status(t))); },
       {},
       planner_status_names()},
  };
  return fields;
}

const std::vector<std::string>& planner_status_names() {
  // ompl::base::PlannerStatus::asString() of 1.5.2 but for ABORT, which it calls "Unknown status".
  static const std::vector<std::string> names = {"Unknown status",         "Invalid start", "Invalid goal",
                                                 "Unrecognized goal type", "Timeout",       "Approximate solution",
                                                 "Exact solution",         "Crash",         "Abort"};
  return names;
}

std::vector<std::string> runs_csv_columns() {
  std::vector<std::string> columns = {"problem", "configuration"};
  for (const auto& f : trial_fields())
    if (f.use & kInRunsCsv) columns.push_back(f.column);
  return columns;
}

std::vector<std::string> property_columns(const std::vector<TrialRecord>& trials) {
  std::set<std::string> fields, properties;
  for (const auto& f : trial_fields()) fields.insert(f.name);
  for (const auto& t : trials)
    for (const auto& [name, value] : t.properties)
      if (!fields.contains(name)) properties.insert(name);
  return {properties.begin(), properties.end()};
}

std::string runs_csv(const std::vector<TrialRecord>& trials, const std::vector<ProblemRecord>& problems,
                     const std::vector<std::pair<int, ConfigRecord>>& configs) {
  const auto properties = property_columns(trials);
  std::ostringstream out;
  std::string separator;
  for (const auto& name : runs_csv_columns()) out << std::exchange(separator, ",") << name;
  for (const auto& name : properties) out << "," << name;
  out << "\n";
  std::map<int, std::string> config_names;
  for (const auto& [id, c] : configs) config_names[id] = c.name;
  for (const auto& t : trials) {
    const ProblemRecord& problem = problems.at(static_cast<std::size_t>(t.problem));
    out << quoted(problem.name) << "," << quoted(config_names.at(t.config));
    for (const auto& f : trial_fields())
      if (f.use & kInRunsCsv) out << "," << csv_cell(f.get(t, problem.optimal_length), f.csv_digits);
    for (const auto& name : properties) {
      const auto it = t.properties.find(name);
      out << "," << (it == t.properties.end() ? "" : csv_cell(it->second));
    }
    out << "\n";
  }
  return out.str();
}

std::string describe_failure(FailureKind kind) {
  switch (kind) {
    case FailureKind::crashed:
      return "crashed (a signal)";
    case FailureKind::timed_out:
      return "over the trial time limit";
    case FailureKind::out_of_memory:
      return "out of memory";
    case FailureKind::plugin_error:
      return "a plugin threw";
    case FailureKind::invalid_value:
      return "a plugin wrote an invalid value";
    case FailureKind::none:
    case FailureKind::error:
      break;
  }
  return "other error";
}

}  // namespace aco::studies
