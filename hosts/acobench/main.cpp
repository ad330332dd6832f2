// acobench: ablation studies of plugin combinations, with a results database and reports.
//   acobench run EXPERIMENT.yaml [--db FILE] [--threads N] [--shard K/N]   (also under mpirun)
//   acobench merge SHARD.db... [--db FILE]
//   acobench report DATABASE [--out DIR]
#include <signal.h>
#include <unistd.h>

#include <boost/program_options.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <iostream>

#include "aco/crash_report.hpp"
#include "aco/error.hpp"
#include "aco/plugin_guard.hpp"
#include "aco/memory_limit.hpp"
#include "aco/program_options_error.hpp"
#include "aco/studies/experiment.hpp"
#include "aco/studies/mpi.hpp"
#include "aco/studies/report.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/runner.hpp"
#include "aco/studies/shards.hpp"
#include "aco/studies/trial_workers.hpp"
#include "aco/version.hpp"

namespace po = boost::program_options;

namespace {

constexpr const char* kUsage =
    "acobench: fair, reproducible comparisons of ant-colony plugin combinations.\n\n"
    "Usage:\n"
    "  acobench run EXPERIMENT.yaml [--db FILE] [--threads N] [--shard K/N] [--plugin-dir DIR] [--max-memory SIZE]\n"
    "               [--trial-timeout SECONDS] [--trial-memory SIZE] [--in-process]\n"
    "      run every trial the database does not hold yet (rerun the same command to continue);\n"
    "      each trial runs in a worker process (one per thread): a trial whose plugin crashes, runs\n"
    "      over --trial-timeout or grows over --trial-memory (default: each thread's share of 3/4 of\n"
    "      the memory available) is stored as failed and the rest go on;\n"
    "      --in-process: the trials on this process's threads (for a debugger; no limits);\n"
    "      --shard K/N: only shard K of N of the trials, into its own database (merge them after);\n"
    "      --max-memory: refuse maps whose planning would need more (512M, 4G; default: 3/4 of the\n"
    "      memory available at start). Under mpirun -n N (or srun), rank 0 writes the database and\n"
    "      the other ranks run the trials, each on --threads threads\n"
    "  acobench merge DATABASE... [--db FILE]\n"
    "      one database of the trials of several of an experiment's (shards, or any runs of it)\n"
    "  acobench report DATABASE [--out DIR]\n"
    "      statistics, Markdown and HTML report, CSV of all runs\n"
    "  acobench --version\n"
    "      the framework's version, commit, build type and compiler\n\n";

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
      std::snprintf(line, sizeof line, "\r[%-30s] %zu/%zu %5.1f%%  %.1f trials/s  ETA %s", std::string(filled, '#').c_str(),
                    done, total, 100 * fraction, rate, clock_text(eta).c_str());
      std::cerr << line << (done == total ? "\n" : "") << std::flush;
    } else {
      std::snprintf(line, sizeof line, "acobench: %zu/%zu trials (%.1f%%), %.1f trials/s, ETA %s\n", done, total, 100 * fraction,
                    rate, clock_text(eta).c_str());
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

void print_summary(const acobench::RunSummary& s, const acobench::Experiment& experiment, const acobench::RunOptions& run) {
  std::cout << "acobench: " << experiment.name << (run.shard ? " shard " + acobench::to_string(*run.shard) : "") << ": "
            << s.trials << " trials, " << s.skipped << " already in " << run.database.string() << ", " << s.ran
            << " run in " << s.seconds << " s (" << (s.seconds > 0 ? s.ran / s.seconds : 0.0) << " trials/s)\n";
  if (s.ablation_left)
    std::cout << "acobench: the experiment's ablation path is not run by shards: merge the shards (acobench merge), "
                 "then `acobench run` of the merged database runs it\n";
  if (!s.failures.empty()) {
    // The experiment went on; the failed trials are stored as such (runs.error) and reported.
    std::cerr << "acobench: " << s.failures.size() << " trials failed:\n";
    for (std::size_t i = 0; i < s.failures.size() && i < 10; ++i) std::cerr << "  " << s.failures[i] << "\n";
    if (s.failures.size() > 10) std::cerr << "  ... (all in the report)\n";
  }
}

#ifdef ACOBENCH_WITH_MPI
// Rank 0 coordinates and writes the database, the others run trials. A rank that fails ends the
// job (the others would wait for it forever); mpirun reports which.
int run_with_ranks(const acobench::mpi::Session& session, const acobench::Experiment& experiment,
                   aco::PluginRegistry& registry, acobench::RunOptions run, const std::vector<std::string>& args,
                   const std::function<std::unique_ptr<acobench::TrialWorkers>(int lanes)>& make_workers) {
  try {
    if (session.rank() > 0) {
      const auto workers = make_workers(aco::lane_count(run.threads));
      acobench::mpi::serve_trials(session, experiment, registry, run.threads, workers.get());
      return 0;
    }
    acobench::mpi::Coordinator coordinator(session, experiment.fingerprint(registry));
    run.executor = &coordinator;
    run.progress = Progress();
    on_stop_tell(run.database.string(), command_line(args));
    const auto s = acobench::run_experiment(experiment, registry, run);
    coordinator.finish();
    print_summary(s, experiment, run);
    const auto per_trial = [&](double seconds) { return s.ran ? 1e6 * seconds / static_cast<double>(s.ran) : 0.0; };
    std::cout << "acobench: " << session.size() - 1 << " worker ranks; the coordinator (rank 0) handled messages for "
              << coordinator.busy_seconds() << " s, " << per_trial(coordinator.busy_seconds())
              << " us per trial, of which storing in the database " << per_trial(coordinator.storing_seconds())
              << " us and handing out and receiving "
              << per_trial(coordinator.busy_seconds() - coordinator.storing_seconds()) << " us\n";
    return 0;
  } catch (...) {
    std::cerr << "acobench: rank " << session.rank() << ": error: " << aco::describe_current_exception() << "\n";
    session.abort(1);
  }
}
#endif

int run(const std::vector<std::string>& args) {
  po::options_description options("acobench run");
  std::string db, shard;
  int threads = 0;
  std::vector<std::string> plugin_dirs;
  options.add_options()("experiment", po::value<std::string>()->required(), "experiment file (YAML)")
      ("db", po::value(&db), "results database (default: the experiment file's name with .db, in the current folder)")
      ("threads", po::value(&threads), "worker threads, 0 = all cores; results do not depend on it")
      ("shard", po::value(&shard)->value_name("K/N"), "only shard K of N of the trials, into its own database")
      ("plugin-dir", po::value(&plugin_dirs)->composing(), "also search DIR for plugins")
      ("max-memory", po::value<std::string>()->value_name("SIZE"), aco::kMaxMemoryHelp)
      ("trial-timeout", po::value<std::string>()->value_name("SECONDS"), "a trial running longer is stopped and stored as timed out")
      ("trial-memory", po::value<std::string>()->value_name("SIZE"), "a trial growing its worker's memory by more is stopped and stored as out of memory (default: each thread's share of 3/4 of the memory available at start)")
      ("in-process", "run the trials on this process's threads, not in worker processes (for a debugger)");
  po::positional_options_description positional;
  positional.add("experiment", 1);
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(options).positional(positional).run(), vm);
  po::notify(vm);
  if (threads < 0) throw aco::Error("--threads must be >= 0");
  std::optional<std::uint64_t> max_memory;
  if (vm.count("max-memory")) max_memory = aco::parse_memory_size(vm["max-memory"].as<std::string>());
  const aco::MemoryLimit memory(max_memory);
  const std::filesystem::path file = vm["experiment"].as<std::string>();
  acobench::RunOptions run;
  if (!shard.empty()) run.shard = acobench::parse_shard(shard);
  const std::string stem = file.stem().string();
  run.database = !db.empty() ? std::filesystem::path(db)
                 : run.shard ? std::filesystem::path(stem + ".shard-" + std::to_string(run.shard->index) + "-of-" +
                                                     std::to_string(run.shard->count) + ".db")
                             : std::filesystem::path(stem + ".db");
  run.threads = threads;
  std::vector<std::filesystem::path> dirs(plugin_dirs.begin(), plugin_dirs.end());
  aco::PluginRegistry registry(aco::PluginRegistry::default_search_dirs(dirs));
#ifndef ACOBENCH_WITH_MPI
  if (acobench::mpi::launched_ranks() > 1)
    throw aco::Error("this acobench was built without MPI but was started as one of " +
                     std::to_string(acobench::mpi::launched_ranks()) +
                     " MPI processes, which would each run every trial: build it with MPI (libopenmpi-dev installed, "
                     "cmake -DACO_WITH_MPI=ON) or run one process");
#endif
  // Before MPI starts: loading probes each plugin in a forked child, and some MPI transports
  // (InfiniBand's) object to fork().
  const acobench::Experiment experiment = acobench::load_experiment(file, registry);
  acobench::TrialLimits limits;
  if (experiment.trial_timeout_s) limits.timeout_s = *experiment.trial_timeout_s;
  if (experiment.trial_memory_bytes) limits.memory_bytes = *experiment.trial_memory_bytes;
  if (vm.count("trial-timeout")) limits.timeout_s = aco::parse_seconds(vm["trial-timeout"].as<std::string>(), "--trial-timeout");
  if (vm.count("trial-memory")) limits.memory_bytes = aco::parse_memory_size(vm["trial-memory"].as<std::string>(), "--trial-memory");
  const bool in_process = vm.count("in-process") > 0;
  if (in_process && (limits.timeout_s > 0 || limits.memory_bytes > 0))
    std::cerr << "acobench: warning: --in-process: the trial time and memory limits are not enforced (they need "
                 "worker processes)\n";
  // Workers are started by the process that runs trials: this one, or each MPI worker rank.
  // Without a memory limit, each lane's share of 3/4 of the memory available: a plugin filling
  // memory stops its trial before the machine swaps.
  const auto make_workers = [&](int lanes) -> std::unique_ptr<acobench::TrialWorkers> {
    if (in_process) return nullptr;
    acobench::TrialLimits lane_limits = limits;
    if (!lane_limits.memory_bytes) lane_limits.memory_bytes = aco::default_memory_limit() / static_cast<std::uint64_t>(lanes);
    return std::make_unique<acobench::TrialWorkers>(lanes, acobench::worker_command(experiment, plugin_dirs, max_memory), lane_limits,
                                                    experiment.fingerprint(registry));
  };
#ifdef ACOBENCH_WITH_MPI
  std::optional<acobench::mpi::Session> session;
  if (acobench::mpi::started_by_launcher()) session.emplace();
  if (session && session->size() > 1) return run_with_ranks(*session, experiment, registry, run, args, make_workers);
  if (session) acobench::mpi::warn_if_bound(*session, threads);
#endif
  const auto workers = make_workers(aco::lane_count(threads));
  std::optional<acobench::WorkerExecutor> executor;
  if (workers) run.executor = &executor.emplace(*workers);
  run.progress = Progress();
  on_stop_tell(run.database.string(), command_line(args));
  print_summary(acobench::run_experiment(experiment, registry, run), experiment, run);
  return 0;
}

// `acobench worker EXPERIMENT [--plugin-dir DIR]...`: a worker process of `acobench run` (not
// for users; started with the socket it serves on).
int worker(const std::vector<std::string>& args) {
  try {
    po::options_description options("acobench worker");
    std::vector<std::string> plugin_dirs;
    options.add_options()("experiment", po::value<std::string>()->required(), "experiment file (YAML)")
        ("plugin-dir", po::value(&plugin_dirs)->composing(), "also search DIR for plugins")
        ("max-memory", po::value<std::string>()->value_name("SIZE"), aco::kMaxMemoryHelp);
    po::positional_options_description positional;
    positional.add("experiment", 1);
    po::variables_map vm;
    po::store(po::command_line_parser(args).options(options).positional(positional).run(), vm);
    po::notify(vm);
    std::optional<std::uint64_t> max_memory;
    if (vm.count("max-memory")) max_memory = aco::parse_memory_size(vm["max-memory"].as<std::string>());
    const aco::MemoryLimit memory(max_memory);
    std::vector<std::filesystem::path> dirs(plugin_dirs.begin(), plugin_dirs.end());
    aco::PluginRegistry registry(aco::PluginRegistry::default_search_dirs(dirs));
    const acobench::Experiment experiment = acobench::load_experiment(vm["experiment"].as<std::string>(), registry);
    acobench::serve_trials_as_worker(experiment, registry);
    return 0;
  } catch (...) {
    if (!aco::is_worker_process()) throw;
    aco::fail_worker("a worker process failed: " + aco::describe_current_exception());
  }
}

int merge(const std::vector<std::string>& args) {
  po::options_description options("acobench merge");
  std::string db;
  options.add_options()("databases", po::value<std::vector<std::string>>()->required(), "results databases to merge")
      ("db", po::value(&db), "the merged database, created or added to (default: the experiment file's name with "
                             ".db, in the current folder)");
  po::positional_options_description positional;
  positional.add("databases", -1);
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(options).positional(positional).run(), vm);
  po::notify(vm);
  const auto names = vm["databases"].as<std::vector<std::string>>();
  const std::vector<std::filesystem::path> inputs(names.begin(), names.end());
  std::string experiment_file = "EXPERIMENT.yaml";
  if (const auto stored = acobench::ResultsDb(inputs.front()).find_meta("experiment_file")) experiment_file = *stored;
  const std::filesystem::path output =
      db.empty() ? std::filesystem::path(std::filesystem::path(experiment_file).stem().string() + ".db")
                 : std::filesystem::path(db);
  const auto s = acobench::merge_databases(inputs, output);
  std::cout << "acobench: merged " << inputs.size() << " databases into " << output.string() << ": " << s.copied
            << " trials copied, " << s.duplicates << " held twice (identical, kept once), "
            << s.expected - s.missing << " of the configurations' " << s.expected << " trials now stored\n";
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
  options.add_options()("database", po::value<std::string>()->required(), "results database")
      ("out", po::value(&out), "folder for report.md, report.html and runs.csv (default: current folder)");
  po::positional_options_description positional;
  positional.add("database", 1);
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(options).positional(positional).run(), vm);
  po::notify(vm);
  std::vector<std::string> warnings;
  const auto files = acobench::write_report(vm["database"].as<std::string>(), out, &warnings);
  for (const auto& f : files) std::cout << f.string() << "\n";
  for (const auto& warning : warnings) std::cerr << "acobench: warning: " << warning << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  aco::report_crashes("acobench");
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kUsage;
      return args.empty() ? 1 : 0;
    }
    if (args[0] == "--version") {
      std::cout << aco::version_text("acobench") << "\n";
      return 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    // "acobench run --help": every command's usage is the one text.
    if (std::find(rest.begin(), rest.end(), "--help") != rest.end() || std::find(rest.begin(), rest.end(), "-h") != rest.end()) {
      std::cout << kUsage;
      return 0;
    }
    if (args[0] == "run") return run(rest);
    if (args[0] == "merge") return merge(rest);
    if (args[0] == "report") return report(rest);
    if (args[0] == "worker") return worker(rest);
    throw aco::Error("unknown command '" + args[0] + "' (use run, merge or report)");
  } catch (po::error& e) {
    std::cerr << "acobench: error: " << aco::program_options_message(e) << "\n";
  } catch (...) {  // anything, a std::exception or not, is reported and exits 1
    std::cerr << "acobench: error: " << aco::describe_current_exception() << "\n";
  }
  return 1;
}
