// acobench: ablation studies of plugin combinations, with a results database and reports.
//   acobench run EXPERIMENT.yaml [--db FILE] [--threads N] [--shard K/N] [--allow-failures]   (also under mpirun)
//   acobench merge SHARD.db... [--db FILE]
//   acobench report DATABASE [--out DIR] [--plugin-dir DIR]
#include <signal.h>
#include <unistd.h>

#include <boost/program_options.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <iostream>

#include "aco/error.hpp"
#include "aco/hosts/host_options.hpp"
#include "aco/plugin_call.hpp"
#include "aco/memory_limit.hpp"
#include "aco/studies/experiment.hpp"
#include "aco/studies/mpi.hpp"
#include "aco/studies/report.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/runner.hpp"
#include "aco/studies/shards.hpp"
#include "aco/studies/trial_workers.hpp"
#include "aco/value_parsers.hpp"
#include "aco/process/version.hpp"

namespace po = boost::program_options;

namespace {

constexpr const char* kUsage =
    "acobench: fair, reproducible comparisons of ant-colony plugin combinations.\n\n"
    "Usage:\n"
    "  acobench run EXPERIMENT.yaml [--db FILE] [--threads N] [--shard K/N] [--plugin-dir DIR] [--max-memory SIZE]\n"
    "               [--trial-timeout SECONDS] [--trial-memory SIZE] [--in-process] [--allow-failures]\n"
    "      run every trial the database does not hold yet (rerun the same command to continue; an\n"
    "      experiment file that gained configurations, problems or repetitions runs only the new\n"
    "      trials into its database; one whose stored trials would now run otherwise is refused);\n"
    "      each trial runs in a worker process (one per thread): a trial whose plugin crashes, runs\n"
    "      over --trial-timeout or grows over --trial-memory (default: each thread's share of 3/4 of\n"
    "      the memory available) is stored as failed and the rest go on;\n"
    "      --in-process: the trials on this process's threads (for a debugger; no limits);\n"
    "      --shard K/N: only shard K of N of the trials, into its own database (merge them after);\n"
    "      --max-memory: refuse maps whose planning would need more (512M, 4G; default: 3/4 of the\n"
    "      memory available at start). Under mpirun -n N (or srun), rank 0 writes the database and\n"
    "      the other ranks run the trials, each on --threads threads;\n"
    "      exit 3 when a trial of the experiment failed, now or stored as failed by an earlier run\n"
    "      (the failures are counted by reason at the end); --allow-failures: exit 0 all the same\n"
    "  acobench merge DATABASE... [--db FILE]\n"
    "      one database of the trials of several of an experiment's (shards, or any runs of it)\n"
    "  acobench report DATABASE [--out DIR] [--plugin-dir DIR]\n"
    "      statistics, Markdown and HTML report, CSV of all runs\n"
    "  acobench --version\n"
    "      the framework's version, commit, build type and compiler\n\n"
    "Exit codes: 0 done, 1 an error of acobench's own (a bad option or file, a refused database),\n"
    "3 trials failed (stored as failed; acobench run without --allow-failures).\n\n";

std::string clock_text(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return text;
}

// A bar redrawn in place on a terminal; plain lines every ten seconds otherwise (logs, CI).
class Progress {
 public:
  void operator()(std::size_t done, std::size_t total) {
    const auto now = std::chrono::steady_clock::now();
    if (!started_) {
      started_ = true;
      began_ = last_ = now;
      first_done_ = done;
    }
    const double interval = terminal_ ? 0.1 : 10.0;
    if (done != total && std::chrono::duration<double>(now - last_).count() < interval) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - began_).count();
    const double rate = elapsed > 0 ? (done - first_done_) / elapsed : 0.0;
    const double eta = rate > 0 ? (total - done) / rate : 0.0;
    const double fraction = total ? double(done) / total : 1.0;
    char line[160];
    if (terminal_) {
      const int filled = static_cast<int>(fraction * 30);
      std::snprintf(line, sizeof line, "\r[%-30s] %zu/%zu %5.1f%%  %.1f trials/s  ETA %s",
                    std::string(filled, '#').c_str(), done, total, 100 * fraction, rate, clock_text(eta).c_str());
      std::cerr << line << (done == total ? "\n" : "") << std::flush;
    } else {
      std::snprintf(line, sizeof line, "acobench: %zu/%zu trials (%.1f%%), %.1f trials/s, ETA %s\n", done, total,
                    100 * fraction, rate, clock_text(eta).c_str());
      std::cerr << line;
    }
  }

 private:
  bool terminal_ = isatty(STDERR_FILENO) != 0;
  bool started_ = false;
  std::size_t first_done_ = 0;
  std::chrono::steady_clock::time_point began_, last_;
};

// Told when a run is stopped (Ctrl-C, a scheduler's time limit, mpirun ending the job after a
// rank died): every trial finished before is stored, and the same command runs only the others.
// Written with write(), the only output a signal handler may use, from text made beforehand.
std::string stopped_message;

void tell_stopped(int signal_number) {
  [[maybe_unused]] const auto written = write(STDERR_FILENO, stopped_message.data(), stopped_message.size());
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

void on_stop_tell(const std::string& database, const std::string& command) {
  stopped_message = "\nacobench: stopped by a signal; every trial finished before it is stored in " + database +
                    ": run `" + command + "` again to run the others\n";
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) ::signal(s, tell_stopped);
}

std::string command_line(const std::vector<std::string>& args) {
  std::string text = "acobench run";
  for (const auto& a : args) text += " " + a;
  return text;
}

// Two configurations that are one run compare it with itself: told before any trial runs.
void warn_same_runs(const aco::studies::Experiment& experiment) {
  for (const auto& [first, second] : experiment.same_runs())
    std::cerr << "acobench: warning: configurations '" << first << "' and '" << second
              << "' resolve to the same run (the same plugins and parameters), so comparing them compares a run with "
                 "itself: did '"
              << second << "' forget a key (its plugin, say)?\n";
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "'" : ", '") + n + "'";
  return text;
}

// "1 problem", "24 problems".
std::string counted(std::size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// Before the first trial: how many trials the experiment has and how many are stored already,
// so that a user knows what was started ("4320 trials: 18 configurations x 24 problems x 10
// repetitions; 0 already in paper003.db, 4320 to run").
std::function<void(const aco::studies::TrialPlan&)> announce_trials(const aco::studies::Experiment& experiment,
                                                                    const aco::studies::RunOptions& run) {
  return [&experiment, &run](const aco::studies::TrialPlan& plan) {
    const std::size_t configurations = plan.configurations + plan.ablation_configurations;
    const std::size_t all = configurations * plan.problems * static_cast<std::size_t>(plan.repetitions);
    std::cout << "acobench: " << experiment.name << ": ";
    if (run.shard) std::cout << "shard " << aco::studies::to_string(*run.shard) << ": " << plan.trials << " of the ";
    std::cout << all << " trials: ";
    if (plan.ablation_configurations)
      std::cout << "(" << plan.configurations << " + " << plan.ablation_configurations
                << " on the ablation path) configurations";
    else
      std::cout << counted(plan.configurations, "configuration");
    // The ablation path's stored trials are known as its rounds start (they come after all others).
    const bool ablation_stored = plan.ablation_configurations > 0 && plan.stored > 0;
    std::cout << " x " << counted(plan.problems, "problem") << " x "
              << counted(static_cast<std::size_t>(plan.repetitions), "repetition") << "; " << plan.stored
              << " already in " << run.database.string() << ", " << (ablation_stored ? "at most " : "")
              << plan.trials - plan.stored << " to run\n"
              << std::flush;
  };
}

// The run's verdict: 0, or aco::kExitTrialsFailed when a trial failed and failures are not allowed.
int print_summary(const aco::studies::RunSummary& s, const aco::studies::Experiment& experiment,
                  const aco::studies::RunOptions& run, bool allow_failures) {
  const auto& g = s.growth;
  if (g.grew()) {
    std::string added;
    const auto add = [&](const std::string& part) { added += (added.empty() ? "" : "; ") + part; };
    if (!g.added_configurations.empty()) add("configurations " + quoted_list(g.added_configurations));
    if (!g.added_problems.empty()) add("problems " + quoted_list(g.added_problems));
    if (g.repetitions_now > g.repetitions_before)
      add("repetitions " + std::to_string(g.repetitions_before) + " -> " + std::to_string(g.repetitions_now));
    std::cout << "acobench: the experiment grew (" << added << "): only the new trials run, the stored ones are kept\n";
  }
  if (!g.dropped_configurations.empty() || !g.dropped_problems.empty())
    std::cout << "acobench: " << run.database.string() << " also holds "
              << quoted_list(g.dropped_configurations.empty() ? g.dropped_problems : g.dropped_configurations)
              << (g.dropped_configurations.empty() || g.dropped_problems.empty()
                      ? ""
                      : " and " + quoted_list(g.dropped_problems))
              << ", which the experiment file no longer names: their trials are kept (and reported), not run\n";
  std::cout << "acobench: " << experiment.name << (run.shard ? " shard " + aco::studies::to_string(*run.shard) : "")
            << ": " << s.trials << " trials, " << s.skipped << " already in " << run.database.string() << ", " << s.ran
            << " run in " << s.seconds << " s (" << (s.seconds > 0 ? s.ran / s.seconds : 0.0) << " trials/s)\n";
  if (s.stored_by_another > 0)
    std::cout << "acobench: " << s.stored_by_another << " of the trials run here were stored first by another process "
              << "writing " << run.database.string() << " (counted as already in it)\n";
  if (s.ablation_left)
    std::cout << "acobench: the experiment's ablation path is not run by shards: merge the shards (acobench merge), "
                 "then `acobench run` of the merged database runs it\n";
  if (s.failures.empty()) return 0;
  // The experiment went on; the failed trials are stored as such (runs.error, runs.failure) and
  // reported. Those of earlier runs count too: the same command gives the same verdict.
  const auto earlier = std::count_if(s.failures.begin(), s.failures.end(), [](const auto& f) { return f.earlier; });
  std::cerr << "acobench: " << s.failures.size() << " of " << s.trials << " trials failed";
  if (earlier) std::cerr << " (" << earlier << " stored as failed by an earlier run)";
  std::cerr << ", by reason and configuration:\n";
  for (const auto& line : aco::studies::describe_failures(s.failures)) std::cerr << "  " << line << "\n";
  if (allow_failures) {
    std::cerr << "acobench: --allow-failures: exit 0 all the same\n";
    return 0;
  }
  std::cerr << "acobench: exit " << aco::kExitTrialsFailed << ": trials failed (all in the report: acobench report "
            << run.database.string() << "); --allow-failures accepts them\n";
  return aco::kExitTrialsFailed;
}

#ifdef ACOBENCH_WITH_MPI
// Rank 0 coordinates and writes the database, the others run trials. A rank that fails ends the
// job (the others would wait for it forever); mpirun reports which.
int run_with_ranks(const aco::studies::mpi::Session& session, const aco::studies::Experiment& experiment,
                   aco::PluginRegistry& registry, aco::studies::RunOptions run, const std::vector<std::string>& args,
                   bool allow_failures,
                   const std::function<std::unique_ptr<aco::studies::TrialWorkers>(int lanes)>& make_workers) {
  try {
    if (session.rank() > 0) {
      const auto workers = make_workers(aco::lane_count(run.threads));
      aco::studies::mpi::serve_trials(session, experiment, registry, run.threads, workers.get());
      return 0;
    }
    warn_same_runs(experiment);
    aco::studies::mpi::Coordinator coordinator(session, experiment.fingerprint(registry));
    run.executor = &coordinator;
    run.progress = Progress();
    run.starting = announce_trials(experiment, run);
    on_stop_tell(run.database.string(), command_line(args));
    const auto s = aco::studies::run_experiment(experiment, registry, run);
    coordinator.finish();
    const int verdict = print_summary(s, experiment, run, allow_failures);
    const auto per_trial = [&](double seconds) { return s.ran ? 1e6 * seconds / static_cast<double>(s.ran) : 0.0; };
    std::cout << "acobench: " << session.size() - 1 << " worker ranks; the coordinator (rank 0) handled messages for "
              << coordinator.busy_seconds() << " s, " << per_trial(coordinator.busy_seconds())
              << " us per trial, of which storing in the database " << per_trial(coordinator.storing_seconds())
              << " us and handing out and receiving "
              << per_trial(coordinator.busy_seconds() - coordinator.storing_seconds()) << " us\n";
    return verdict;
  } catch (...) {
    std::cerr << "acobench: rank " << session.rank() << ": error: " << aco::describe_current_exception() << "\n";
    session.abort(1);
  }
}
#endif

int run(const std::vector<std::string>& args) {
  po::options_description options("acobench run");
  std::string db, shard;
  aco::HostOptions host;
  options.add_options()("experiment", po::value<std::string>()->required(), "experiment file (YAML)")(
      "db", po::value(&db), "results database (default: the experiment file's name with .db, in the current folder)")(
      "shard", po::value(&shard)->value_name("K/N"), "only shard K of N of the trials, into its own database");
  host.add_threads(options);
  host.add_plugin_dir_and_max_memory(options);
  options.add_options()("trial-timeout", po::value<std::string>()->value_name("SECONDS"),
                        "a trial running longer is stopped and stored as timed out")(
      "trial-memory", po::value<std::string>()->value_name("SIZE"),
      "a trial growing its worker's memory by more is stopped and stored as out of memory (default: each thread's "
      "share of 3/4 of the memory available at start)")(
      "in-process", "run the trials on this process's threads, not in worker processes (for a debugger)")(
      "allow-failures", "exit 0 even when trials failed (else 3)");
  const po::variables_map vm = aco::parse_arguments(args, options, "experiment", 1);
  const int threads = host.threads;
  const std::optional<std::uint64_t> max_memory = host.max_memory_bytes();
  const aco::MemoryLimit memory(max_memory);
  const std::filesystem::path file = vm["experiment"].as<std::string>();
  aco::studies::RunOptions run;
  if (!shard.empty()) run.shard = aco::studies::parse_shard(shard);
  const std::string stem = file.stem().string();
  run.database = !db.empty() ? std::filesystem::path(db)
                 : run.shard ? std::filesystem::path(stem + ".shard-" + std::to_string(run.shard->index) + "-of-" +
                                                     std::to_string(run.shard->count) + ".db")
                             : std::filesystem::path(stem + ".db");
  run.threads = threads;
  aco::PluginRegistry registry(host.plugin_search_dirs());
#ifndef ACOBENCH_WITH_MPI
  if (aco::studies::mpi::launched_ranks() > 1)
    throw aco::Error("this acobench was built without MPI but was started as one of " +
                     std::to_string(aco::studies::mpi::launched_ranks()) +
                     " MPI processes, which would each run every trial: build it with MPI (libopenmpi-dev installed, "
                     "cmake -DACO_WITH_MPI=ON) or run one process");
#endif
  // Before MPI starts: loading probes each plugin in a forked child, and some MPI transports
  // (InfiniBand's) object to fork().
  const aco::studies::Experiment experiment = aco::studies::load_experiment(file, registry);
  aco::studies::TrialLimits limits;
  if (experiment.trial_timeout_s) limits.timeout_s = *experiment.trial_timeout_s;
  if (experiment.trial_memory_bytes) limits.memory_bytes = *experiment.trial_memory_bytes;
  if (vm.count("trial-timeout"))
    limits.timeout_s = aco::parse_seconds(vm["trial-timeout"].as<std::string>(), "--trial-timeout");
  if (vm.count("trial-memory"))
    limits.memory_bytes = aco::parse_memory_size(vm["trial-memory"].as<std::string>(), "--trial-memory");
  const bool in_process = vm.count("in-process") > 0;
  const bool allow_failures = vm.count("allow-failures") > 0;
  if (in_process && (limits.timeout_s > 0 || limits.memory_bytes > 0))
    std::cerr << "acobench: warning: --in-process: the trial time and memory limits are not enforced (they need "
                 "worker processes)\n";
  // Workers are started by the process that runs trials: this one, or each MPI worker rank.
  // Without a memory limit, each lane's share of 3/4 of the memory available: a plugin filling
  // memory stops its trial before the machine swaps.
  const auto make_workers = [&](int lanes) -> std::unique_ptr<aco::studies::TrialWorkers> {
    if (in_process) return nullptr;
    aco::studies::TrialLimits lane_limits = limits;
    if (!lane_limits.memory_bytes)
      lane_limits.memory_bytes = aco::default_memory_limit() / static_cast<std::uint64_t>(lanes);
    return std::make_unique<aco::studies::TrialWorkers>(
        lanes, aco::studies::worker_command(experiment, host.plugin_dirs, max_memory), lane_limits,
        experiment.fingerprint(registry));
  };
  if (!in_process) run.limits = limits;  // as given: MPI ranks' workers apply their own default memory share
#ifdef ACOBENCH_WITH_MPI
  std::optional<aco::studies::mpi::Session> session;
  if (aco::studies::mpi::started_by_launcher()) session.emplace();
  if (session && session->size() > 1)
    return run_with_ranks(*session, experiment, registry, run, args, allow_failures, make_workers);
  if (session) aco::studies::mpi::warn_if_bound(*session, threads);
#endif
  const auto workers = make_workers(aco::lane_count(threads));
  std::optional<aco::studies::WorkerExecutor> executor;
  if (workers) {
    run.executor = &executor.emplace(*workers);
    run.limits = workers->limits();
  }
  warn_same_runs(experiment);
  run.progress = Progress();
  run.starting = announce_trials(experiment, run);
  on_stop_tell(run.database.string(), command_line(args));
  return print_summary(aco::studies::run_experiment(experiment, registry, run), experiment, run, allow_failures);
}

// `acobench worker EXPERIMENT [--plugin-dir DIR]...`: a worker process of `acobench run` (not
// for users; started with the socket it serves on).
int worker(const std::vector<std::string>& args) {
  try {
    po::options_description options("acobench worker");
    aco::HostOptions host;
    options.add_options()("experiment", po::value<std::string>()->required(), "experiment file (YAML)");
    host.add_plugin_dir_and_max_memory(options);
    const po::variables_map vm = aco::parse_arguments(args, options, "experiment", 1);
    const aco::MemoryLimit memory(host.max_memory_bytes());
    aco::PluginRegistry registry(host.plugin_search_dirs());
    const aco::studies::Experiment experiment =
        aco::studies::load_experiment(vm["experiment"].as<std::string>(), registry);
    aco::studies::serve_trials_as_worker(experiment, registry);
    return 0;
  } catch (...) {
    if (!aco::is_worker_process()) throw;
    aco::fail_worker("a worker process failed: " + aco::describe_current_exception());
  }
}

int merge(const std::vector<std::string>& args) {
  po::options_description options("acobench merge");
  std::string db;
  options.add_options()("databases", po::value<std::vector<std::string>>()->required(), "results databases to merge")(
      "db", po::value(&db),
      "the merged database, created or added to (default: the experiment file's name with "
      ".db, in the current folder)");
  const po::variables_map vm = aco::parse_arguments(args, options, "databases", -1);
  const auto names = vm["databases"].as<std::vector<std::string>>();
  const std::vector<std::filesystem::path> inputs(names.begin(), names.end());
  std::string experiment_file = "EXPERIMENT.yaml";
  if (const auto stored = aco::studies::ResultsDb(inputs.front()).find_meta("experiment_file"))
    experiment_file = *stored;
  const std::filesystem::path output =
      db.empty() ? std::filesystem::path(std::filesystem::path(experiment_file).stem().string() + ".db")
                 : std::filesystem::path(db);
  const auto s = aco::studies::merge_databases(inputs, output);
  std::cout << "acobench: merged " << inputs.size() << " databases into " << output.string() << ": " << s.copied
            << " trials copied, " << s.duplicates << " held twice (identical, kept once), " << s.expected - s.missing
            << " of the configurations' " << s.expected << " trials now stored\n";
  const std::string rerun = "acobench run " + experiment_file + " --db " + output.string();
  if (s.missing) {
    std::cerr << "acobench: warning: " << s.missing << " trials are in none of the databases:\n";
    for (const auto& line : s.missing_by_shard) std::cerr << "  " << line << "\n";
    std::cerr << "  rerun those shards and merge again, or run them here: " << rerun << "\n";
  }
  if (s.ablation_left)
    std::cout << "acobench: the experiment's ablation path is not in the shards: " << rerun << " runs it\n";
  return 0;
}

int report(const std::vector<std::string>& args) {
  po::options_description options("acobench report");
  std::string out = ".";
  aco::HostOptions host;
  options.add_options()("database", po::value<std::string>()->required(), "results database")(
      "out", po::value(&out), "folder for report.md, report.html, runs.csv and plots/*.svg (default: current folder)");
  host.add_plugin_dir(options);  // map plugins, to draw the maps of their formats
  const po::variables_map vm = aco::parse_arguments(args, options, "database", 1);
  std::vector<std::string> warnings;
  const auto files =
      aco::studies::write_report(vm["database"].as<std::string>(), out, &warnings, host.plugin_search_dirs());
  // The plots, one file each, are many on a large study: their folder is named once.
  std::size_t plots = 0;
  for (const auto& f : files) {
    if (f.parent_path().filename() == "plots")
      ++plots;
    else
      std::cout << f.string() << "\n";
  }
  if (plots > 0) std::cout << (std::filesystem::path(out) / "plots").string() << "/ (" << plots << " SVG plots)\n";
  for (const auto& warning : warnings) std::cerr << "acobench: warning: " << warning << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return aco::run_command("acobench", [&] {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kUsage;
      return args.empty() ? aco::kExitError : aco::kExitOk;
    }
    if (args[0] == "--version") {
      std::cout << aco::version_text("acobench") << "\n";
      return aco::kExitOk;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    // "acobench run --help": every command's usage is the one text.
    if (std::find(rest.begin(), rest.end(), "--help") != rest.end() ||
        std::find(rest.begin(), rest.end(), "-h") != rest.end()) {
      std::cout << kUsage;
      return aco::kExitOk;
    }
    if (args[0] == "run") return run(rest);
    if (args[0] == "merge") return merge(rest);
    if (args[0] == "report") return report(rest);
    if (args[0] == "worker") return worker(rest);
    throw aco::Error("unknown command '" + args[0] + "' (use run, merge or report)");
  });
}
