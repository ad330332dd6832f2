#include "aco/hosts/host_options.hpp"

#include <boost/program_options.hpp>

#include <iostream>

#include "aco/process/crash_report.hpp"
#include "aco/error.hpp"
#include "aco/memory_limit.hpp"
#include "aco/plugin_call.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/hosts/program_options_error.hpp"
#include "aco/value_parsers.hpp"
#include "aco/process/worker_process.hpp"

namespace aco {
namespace po = boost::program_options;

void HostOptions::add_plugin_dir(po::options_description& options) {
  options.add_options()("plugin-dir", po::value(&plugin_dirs)->composing()->value_name("DIR"),
                        "also search DIR for plugins (before ACO_PLUGIN_PATH and the default folders)");
}

void HostOptions::add_plugin_dir_and_max_memory(po::options_description& options) {
  add_plugin_dir(options);
  options.add_options()(
      "max-memory",
      po::value<std::string>()->value_name("SIZE")->notifier([this](const std::string& size) { max_memory = size; }),
      kMaxMemoryHelp);
}

void HostOptions::add_threads(po::options_description& options, const std::string& scope) {
  options.add_options()("threads", po::value(&threads)->value_name("N")->default_value(0)->notifier([](int n) {
    if (n < 0) throw Error("--threads: must be 0 (all cores) or more, not " + std::to_string(n));
  }),
                        (scope + kThreadsHelp).c_str());
}

std::vector<std::filesystem::path> HostOptions::plugin_search_dirs() const {
  return PluginRegistry::default_search_dirs({plugin_dirs.begin(), plugin_dirs.end()});
}

std::optional<std::uint64_t> HostOptions::max_memory_bytes() const {
  if (!max_memory) return std::nullopt;
  return parse_memory_size(*max_memory);
}

po::variables_map parse_arguments(const std::vector<std::string>& args, const po::options_description& options,
                                  const char* positional, int count) {
  po::positional_options_description positions;
  positions.add(positional, count);
  po::variables_map vm;
  po::store(po::command_line_parser(args).options(options).positional(positions).run(), vm);
  po::notify(vm);
  return vm;
}

int run_command(const char* program, const std::function<int()>& body) {
  report_crashes(program);
  std::string message;
  try {
    return body();
  } catch (po::error& e) {
    message = program_options_message(e);
  } catch (...) {  // anything, a std::exception or not, is reported and exits kExitError
    message = describe_current_exception();
  }
  if (is_worker_process()) fail_worker(message);
  std::cerr << program << ": error: " << message << "\n";
  return kExitError;
}

}  // namespace aco
