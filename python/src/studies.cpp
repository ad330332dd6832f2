// aco.run_study() and aco.read_database(): an experiment run as acobench runs it, a database read
// as columns, and the report's statistics on plain samples.
#include "module.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <cmath>
#include <future>
#include <map>
#include <optional>

#include "aco/error.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/runner.hpp"
#include "aco/studies/statistics.hpp"

namespace aco_python {
namespace {

using Sample = std::vector<double>;

// `text`: the experiment itself (Python's dict as JSON), for which `file` stands; empty: read `file`.
py::dict run_experiment(const std::filesystem::path& file, const std::string& text,
                        const std::filesystem::path& database, int threads,
                        const std::function<void(std::size_t, std::size_t)>& progress) {
  aco::studies::RunOptions options;
  options.database = database;
  options.threads = threads;
  // Ctrl-C: the trials running finish and are stored, no other starts, then KeyboardInterrupt.
  std::atomic<bool> interrupted = false;
  struct Interrupted {};
  options.progress = [&](std::size_t done, std::size_t total) {
    if (interrupted) throw Interrupted{};
    if (!progress) return;
    py::gil_scoped_acquire locked;
    progress(done, total);
  };
  const aco::studies::Experiment experiment = text.empty() ? aco::studies::load_experiment(file, registry())
                                                           : aco::studies::load_experiment_text(text, file, registry());
  aco::studies::RunSummary summary;
  // The trials run in a thread of their own, whichever threads they take: this one, Python's main
  // thread, runs the signal handlers meanwhile.
  std::optional<py::error_already_set> signal;
  {
    py::gil_scoped_release unlocked;
    auto trials =
        std::async(std::launch::async, [&] { return aco::studies::run_experiment(experiment, registry(), options); });
    while (trials.wait_for(kSignalCheckInterval) != std::future_status::ready) {
      py::gil_scoped_acquire locked;
      if (!signal && PyErr_CheckSignals() != 0) {
        signal.emplace();
        interrupted = true;
      }
    }
    try {
      summary = trials.get();
    } catch (const Interrupted&) {}
  }
  if (signal) throw std::move(*signal);
  py::list failures;
  py::dict by_reason;
  for (const auto& f : summary.failures) {
    failures.append(py::dict(py::arg("configuration") = f.configuration,
                             py::arg("reason") = aco::studies::to_string(f.kind), py::arg("message") = f.message,
                             py::arg("earlier") = f.earlier));
    const char* reason = aco::studies::to_string(f.kind);
    by_reason[py::str(reason)] = by_reason.attr("get")(reason, 0).cast<int>() + 1;
  }
  return py::dict(py::arg("trials") = summary.trials, py::arg("skipped") = summary.skipped,
                  py::arg("ran") = summary.ran, py::arg("failures") = failures,
                  py::arg("failures_by_reason") = by_reason, py::arg("same_runs") = experiment.same_runs(),
                  py::arg("seconds") = summary.seconds);
}

// A results database as columns (the runs, each with its problem's and configuration's name,
// the problem's optimum and the configuration's settings JSON), in the report's order.
// A field's values as a Python column: numbers as a NumPy array (NULL as NaN for reals, -1 for
// whole numbers), text and booleans as a list (NULL as None).
py::object python_column(const aco::studies::TrialField& field, const std::vector<aco::studies::TrialCell>& cells) {
  const auto numbers = [&](auto null) {
    std::vector<decltype(null)> values;
    for (const auto& cell : cells)
      values.push_back(std::visit(
          [null](const auto& v) -> decltype(null) {
            if constexpr (std::is_arithmetic_v<std::decay_t<decltype(v)>>)
              return static_cast<decltype(null)>(v);
            else
              return null;
          },
          cell));
    return py::object(py::array(py::cast(values)));
  };
  switch (field.type) {
    case aco::studies::TrialCellType::integer:
      return numbers(std::int64_t{-1});
    case aco::studies::TrialCellType::count:
      return numbers(std::uint64_t{0});
    case aco::studies::TrialCellType::real:
      return numbers(std::nan(""));
    default:
      break;
  }
  py::list values;
  for (const auto& cell : cells)
    values.append(std::visit(
        [](const auto& v) -> py::object {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>)
            return py::none();
          else
            return py::cast(v);
        },
        cell));
  return field.type == aco::studies::TrialCellType::boolean ? py::object(py::array(values)) : py::object(values);
}

// The trials of a database as columns: problem, configuration, the trial fields Python shows,
// optimal_length, settings; "properties": a column per property_columns() (NaN where a run has
// none); "csv_columns": runs.csv's columns before the properties, which come first in Python.
py::dict read_trials(const std::filesystem::path& database) {
  if (!std::filesystem::exists(database)) throw aco::Error(database.string() + ": no such results database");
  const aco::studies::ResultsDb db(database);
  const auto problems = db.problems();
  std::map<int, aco::studies::ConfigRecord> configs;
  for (const auto& [id, config] : db.configs()) configs[id] = config;
  py::list problem, configuration, settings;
  std::vector<double> optimal;
  const double none = std::nan("");
  const auto trials = db.trials();
  std::map<std::string, py::list> properties;
  for (const auto& name : aco::studies::property_columns(trials)) properties[name];
  const auto& fields = aco::studies::trial_fields();
  std::vector<std::vector<aco::studies::TrialCell>> cells(fields.size());
  for (const auto& t : trials) {
    for (auto& [name, column] : properties) {
      const auto it = t.properties.find(name);
      if (it == t.properties.end())
        column.append(none);
      else if (const auto* text = std::get_if<std::string>(&it->second))
        column.append(*text);
      else
        column.append(std::visit(
            [](const auto& v) -> double {
              if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>)
                return 0.0;
              else
                return static_cast<double>(v);
            },
            it->second));
    }
    const auto& p = problems.at(static_cast<std::size_t>(t.problem));
    problem.append(p.name);
    optimal.push_back(p.optimal_length > 0 ? p.optimal_length : none);
    configuration.append(configs.at(t.config).name);
    settings.append(configs.at(t.config).settings_json);
    for (std::size_t i = 0; i < fields.size(); ++i) cells[i].push_back(fields[i].get(t, p.optimal_length));
  }
  py::dict columns;
  columns["problem"] = problem;
  columns["configuration"] = configuration;
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].use & aco::studies::kInPython) columns[fields[i].column] = python_column(fields[i], cells[i]);
  columns["optimal_length"] = py::array(py::cast(optimal));
  columns["settings"] = settings;
  py::dict property_columns;
  for (const auto& [name, column] : properties) property_columns[py::str(name)] = column;
  columns["properties"] = property_columns;
  columns["csv_columns"] = aco::studies::runs_csv_columns();
  return columns;
}

}  // namespace

void bind_studies(py::module_& m) {
  m.def("run_experiment", &run_experiment, py::arg("file"), py::arg("text"), py::arg("database"), py::arg("threads"),
        py::arg("progress"));
  m.def("read_trials", &read_trials, py::arg("database"));
  // The trial fields (aco/studies/trial_record.hpp): where each goes, for the tests.
  m.def("trial_fields", [] {
    py::list fields;
    for (const auto& f : aco::studies::trial_fields())
      fields.append(py::dict(py::arg("name") = f.name, py::arg("column") = f.column, py::arg("stored_as") = f.stored_as,
                             py::arg("in_runs_table") = bool(f.use & aco::studies::kInRunsTable),
                             py::arg("when_used") = bool(f.use & aco::studies::kWhenUsed),
                             py::arg("in_runs_csv") = bool(f.use & aco::studies::kInRunsCsv),
                             py::arg("in_python") = bool(f.use & aco::studies::kInPython)));
    return fields;
  });

  // The report's statistics (aco/studies/statistics.hpp), on plain samples.
  m.def("summarize", [](const Sample& s) {
    const auto r = aco::studies::summarize(s);
    return py::dict(py::arg("n") = r.n, py::arg("mean") = r.mean, py::arg("sd") = r.stddev,
                    py::arg("median") = r.median, py::arg("q1") = r.q1, py::arg("q3") = r.q3, py::arg("iqr") = r.iqr,
                    py::arg("ci_low") = r.ci_low, py::arg("ci_high") = r.ci_high, py::arg("min") = r.min,
                    py::arg("max") = r.max);
  });
  m.def("mann_whitney_u", [](const Sample& a, const Sample& b) {
    const auto r = aco::studies::mann_whitney_u(a, b);
    return py::dict(py::arg("u") = r.u, py::arg("p") = r.p, py::arg("exact") = r.exact);
  });
  m.def("holm_adjust", [](const Sample& p) { return aco::studies::holm_adjust(p); });
  m.def("vargha_delaney_a12", [](const Sample& a, const Sample& b) { return aco::studies::vargha_delaney_a12(a, b); });
  m.def("effect_size", [](double a12) { return std::string(aco::studies::to_string(aco::studies::effect_size(a12))); });
  m.def("average_ranks", [](const std::vector<Sample>& scores) { return aco::studies::average_ranks(scores); });
  m.def("ecdf", [](Sample hitting_times, const Sample& at) { return aco::studies::ecdf(hitting_times, at); });
  m.def("expected_running_time", [](const Sample& hitting_times, const Sample& efforts) {
    return aco::studies::expected_running_time(hitting_times, efforts);
  });
}

}  // namespace aco_python
