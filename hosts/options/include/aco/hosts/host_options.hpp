#pragma once
// What the framework's commands share (acoplan, acobench, acosim, aco-plugin-check): the exit
// statuses, the options --plugin-dir, --max-memory and --threads, and main()'s error handling.
// Written once, so every command spells, checks and explains them alike. --version's text is
// aco::version_text() (aco/process/version.hpp); output files are aco::write_output_file()'s.
#include <boost/program_options/options_description.hpp>
#include <boost/program_options/variables_map.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace aco {

// The exit statuses of every command; docs/planning.md's "Exit status" table explains them.
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;  // the command failed; the message on stderr says why
inline constexpr int kExitUsage = 2;  // aco-plugin-check, aco-new-plugin: the command line cannot be read
inline constexpr int kExitNoPath = 3;  // acoplan: no path found; acosim: the robot did not reach the goal
inline constexpr int kExitTrialsFailed = 3;  // acobench: a trial failed (now or in an earlier run of the study)

inline constexpr const char* kThreadsHelp = "worker threads, 0 = all cores; results do not depend on it";

// --plugin-dir, --max-memory and --threads as a command declares them, and what they ask for.
struct HostOptions {
  std::vector<std::string> plugin_dirs;  // --plugin-dir, repeatable, searched first
  std::optional<std::string> max_memory;  // --max-memory as given; none: the default limit
  int threads = 0;  // --threads; 0: all cores

  // Adds --plugin-dir DIR to `options`, stored here.
  void add_plugin_dir(boost::program_options::options_description& options);
  // Adds --plugin-dir DIR and --max-memory SIZE to `options`, stored here.
  void add_plugin_dir_and_max_memory(boost::program_options::options_description& options);
  // Adds --threads N, stored here; a negative N is refused. `scope` starts its help ("with --batch: ").
  void add_threads(boost::program_options::options_description& options, const std::string& scope = "");

  // The folders plugins are looked for in: --plugin-dir's, ACO_PLUGIN_PATH's, the bundled one. A
  // --plugin-dir that is missing or is a file is an Error saying which and what to give instead.
  std::vector<std::filesystem::path> plugin_search_dirs() const;
  // --max-memory in bytes (an Error naming the option for a malformed size); none given: nullopt.
  std::optional<std::uint64_t> max_memory_bytes() const;
};

// A (sub)command's words parsed against `options`, the first `count` words that are no option
// (-1: all) given to the option `positional`; the options' notifiers have run.
boost::program_options::variables_map parse_arguments(const std::vector<std::string>& args,
                                                      const boost::program_options::options_description& options,
                                                      const char* positional, int count);

// main() of a command: reports crashes as `program`'s (aco::report_crashes), runs `body` and
// returns its status. Anything `body` throws ends it with kExitError after "PROGRAM: error:
// MESSAGE" on stderr (Boost's option errors with the user's text as typed); in a worker process
// the message goes to the process that started it instead.
int run_command(const char* program, const std::function<int()>& body);

}  // namespace aco
