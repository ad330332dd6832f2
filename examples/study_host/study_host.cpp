// A host of its own: runs an experiment file into a results database through the studies library,
// then writes the HTML report, as `acobench run` and `acobench report` do.
//   study_host EXPERIMENT.yaml DATABASE.db REPORT_FOLDER
#include <iostream>

#include "aco/plugin_call.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/studies/report.hpp"
#include "aco/studies/runner.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: study_host EXPERIMENT.yaml DATABASE.db REPORT_FOLDER\n";
    return 2;
  }
  try {
    aco::PluginRegistry registry(aco::PluginRegistry::default_search_dirs());  // bundled and ACO_PLUGIN_PATH
    aco::studies::RunOptions options;
    options.database = argv[2];
    options.progress = [](std::size_t done, std::size_t total) { std::cerr << "\r" << done << "/" << total; };
    const auto summary =
        aco::studies::run_experiment(aco::studies::load_experiment(argv[1], registry), registry, options);
    std::cout << "\nran " << summary.ran << " trials (" << summary.skipped << " already stored), "
              << summary.failures.size() << " failed\n";
    for (const auto& file : aco::studies::write_report(argv[2], argv[3]))
      std::cout << "wrote " << file.string() << "\n";
  } catch (...) {  // a bad experiment file or plugin: its message, as acobench prints it
    std::cerr << "study_host: error: " << aco::describe_current_exception() << "\n";
    return 1;
  }
}
