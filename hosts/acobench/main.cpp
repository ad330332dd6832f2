// acobench: ablation studies of plugin combinations, with a results database and reports.
//   acobench run EXPERIMENT.yaml [--db FILE] [--threads N]
//   acobench report DATABASE [--out DIR]
#include <unistd.h>

#include <boost/program_options.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "aco/plugin_guard.hpp"
#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "experiment.hpp"
#include "report.hpp"
#include "runner.hpp"

namespace po = boost::program_options;

namespace {

constexpr const char* kUsage =
    "acobench: fair, reproducible comparisons of ant-colony plugin combinations.\n\n"
    "Usage:\n"
    "  acobench run EXPERIMENT.yaml [--db FILE] [--threads N] [--plugin-dir DIR] [--max-memory SIZE]\n"
    "      run every trial the database does not hold yet (rerun the same command to continue);\n"
    "      --max-memory: refuse maps whose planning would need more (512M, 4G; default: 3/4 of the\n"
    "      memory available at start)\n"
    "  acobench report DATABASE [--out DIR]\n"
    "      statistics, Markdown and HTML report, CSV of all runs\n\n";

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

int run(const std::vector<std::string>& args) {
  po::options_description options("acobench run");
  std::string db;
  int threads = 0;
  std::vector<std::string> plugin_dirs;
  options.add_options()("experiment", po::value<std::string>()->required(), "experiment file (YAML)")
      ("db", po::value(&db), "results database (default: the experiment file's name with .db, in the current folder)")
      ("threads", po::value(&threads), "worker threads, 0 = all cores; results do not depend on it")
      ("plugin-dir", po::value(&plugin_dirs)->composing(), "also search DIR for plugins")
      ("max-memory", po::value<std::string>()->value_name("SIZE"), aco::kMaxMemoryHelp);
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
  std::vector<std::filesystem::path> dirs(plugin_dirs.begin(), plugin_dirs.end());
  aco::PluginRegistry registry(aco::PluginRegistry::default_search_dirs(dirs));
  const acobench::Experiment experiment = acobench::load_experiment(file, registry);
  acobench::RunOptions run;
  run.database = db.empty() ? std::filesystem::path(file.stem().string() + ".db") : std::filesystem::path(db);
  run.threads = threads;
  run.progress = Progress();
  const auto s = acobench::run_experiment(experiment, registry, run);
  std::cout << "acobench: " << experiment.name << ": " << s.trials << " trials, " << s.skipped << " already in "
            << run.database.string() << ", " << s.ran << " run in " << s.seconds << " s ("
            << (s.seconds > 0 ? s.ran / s.seconds : 0.0) << " trials/s)\n";
  if (!s.failures.empty()) {
    // The experiment went on; the failed trials are stored as such (runs.error) and reported.
    std::cerr << "acobench: " << s.failures.size() << " trials failed:\n";
    for (std::size_t i = 0; i < s.failures.size() && i < 10; ++i) std::cerr << "  " << s.failures[i] << "\n";
    if (s.failures.size() > 10) std::cerr << "  ... (all in the report)\n";
  }
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
  const auto files = acobench::write_report(vm["database"].as<std::string>(), out);
  for (const auto& f : files) std::cout << f.string() << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::cout << kUsage;
      return args.empty() ? 1 : 0;
    }
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "run") return run(rest);
    if (args[0] == "report") return report(rest);
    throw aco::Error("unknown command '" + args[0] + "' (use run or report)");
  } catch (const po::error& e) {
    std::cerr << "acobench: error: " << e.what() << "\n";
  } catch (...) {  // anything, a std::exception or not, is reported and exits 1
    std::cerr << "acobench: error: " << aco::describe_current_exception() << "\n";
  }
  return 1;
}
