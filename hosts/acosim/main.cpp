// acosim: a robot follows the colony's path with a local planner among obstacles the map did not
// show (paper 003). See README.md.
#include <boost/program_options.hpp>
#include <iostream>

#include "aco/planning/presets.hpp"
#include "aco/process/version.hpp"
#include "aco/error.hpp"
#include "aco/hosts/host_options.hpp"
#include "aco/machine.hpp"
#include "aco/memory_limit.hpp"
#include "aco/process/output_file.hpp"
#include "aco/thread_limit.hpp"
#include "aco/value_parsers.hpp"
#include "aco/process/worker_process.hpp"
#include "aco/simulation/batch.hpp"
#include "aco/simulation/simulation.hpp"

namespace po = boost::program_options;

namespace {

// A run key given as an option: "--key value", "--key=value", or "--flag" alone for true. The
// scenario's own keys (map, start, goal) are refused by aco::simulation::with_run_keys.
void add_run_key(const std::string& token, const char* next, aco::KeyedValues& keys) {
  std::string key = token.substr(2), value = next ? next : "true";
  if (const auto equals = key.find('='); equals != std::string::npos) {
    value = key.substr(equals + 1);
    key.resize(equals);
  }
  keys.keys[key] = value;
  keys.origins[key] = "--" + key;
}

}  // namespace

int main(int argc, char** argv) {
  // An error goes to stderr, or from a worker process of --batch to the acosim that started it.
  return aco::run_command("acosim", [&] {
    std::string scenario_file, csv, svg, html;
    aco::HostOptions host;
    po::options_description options(
        "acosim: drive a robot along the colony's path with a local planner.\n\n"
        "Usage: acosim SCENARIO.yaml [options]\n\nOptions");
    options.add_options()("help,h", "print this help and exit")(
        "version", "print the framework's version, commit, build type and compiler and exit")(
        "json", po::bool_switch(), "print the summary and the trajectory as one JSON object")(
        "csv", po::value(&csv)->value_name("FILE"), "write the trajectory (t, x, y, heading, v, w) as CSV")(
        "svg", po::value(&svg)->value_name("FILE"),
        "write a picture: map, unknown cells, plans, trajectory, moving tracks, start and goal, with a legend")(
        "html", po::value(&html)->value_name("FILE"), "write a page that plays the run (play/pause, time slider)")(
        "batch", po::value<int>()->value_name("N"),
        "run N generated variations of the scenario and print their summary")(
        "seed", po::value<std::uint64_t>()->default_value(1), "with --batch or --variation: the variations' seed")(
        "variation", po::value<int>()->value_name("K"), "run variation K (0-based) of --batch's, with every output")(
        "variation-timeout", po::value<std::string>()->value_name("SECONDS"),
        "with --batch: a variation running longer is stopped and counted as timed out")(
        "variation-memory", po::value<std::string>()->value_name("SIZE"),
        "with --batch: a variation growing its worker's memory by more is stopped and counted as out of memory")(
        "in-process",
        "with --batch: run the variations on this process's threads, not in worker processes (for a debugger; a crash "
        "ends the batch, no limits)")("preset", po::value<std::string>()->value_name("NAME"),
                                      "run the named preset's pipeline (acoplan --list-presets) over the scenario's")(
        "config", po::value<std::string>()->value_name("FILE"),
        "run a config file's pipeline (as acoplan --config) over the scenario's");
    host.add_threads(options, "with --batch: ");
    host.add_plugin_dir_and_max_memory(options);
    po::options_description hidden;
    hidden.add_options()("scenario", po::value(&scenario_file))(
        "variation-worker", "serve --batch's variations to the acosim that started this one");
    po::options_description all;
    all.add(options).add(hidden);
    // Any other --key [value] is a run key, as on acoplan's command line, over the scenario's.
    std::vector<std::string> own_options;
    aco::KeyedValues command_line_keys;
    for (int i = 1; i < argc; ++i) {
      const std::string token = argv[i];
      const std::string name = token.rfind("--", 0) == 0 ? token.substr(2, token.find('=') - 2) : "";
      if (name.empty() || all.find_nothrow(name, true)) {  // with Boost's abbreviations (--thr)
        own_options.push_back(token);
        continue;
      }
      const bool valued =
          token.find('=') == std::string::npos && i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0;
      add_run_key(token, valued ? argv[++i] : nullptr, command_line_keys);
    }
    const po::variables_map vm = aco::parse_arguments(own_options, all, "scenario", 1);
    if (vm.count("help")) {
      std::cout
          << options
          << "\nAny run key of acoplan (--local track, --local.follow 0.5, --ants 20, --update max_min) goes over\n"
             "the scenario's run keys (map, start and goal are the scenario's). A scenario naming no pipeline\n"
             "(config or preset) runs the recommended one, data/presets/robust.ini.\n";
      return aco::kExitOk;
    }
    if (vm.count("version")) {
      std::cout << aco::version_text("acosim") << "\n";
      return aco::kExitOk;
    }
    if (scenario_file.empty()) throw aco::Error("no scenario file (acosim SCENARIO.yaml; --help for options)");
    const aco::MemoryLimit memory(host.max_memory_bytes());
    aco::PluginRegistry registry(host.plugin_search_dirs());
    aco::simulation::Scenario scenario = aco::simulation::load_scenario(scenario_file, registry);
    {
      const auto given = [&vm](const char* key) { return vm.count(key) ? vm[key].as<std::string>() : std::string(); };
      const aco::KeyedValues changes =
          aco::overlay(aco::PipelineSource::named(given("preset"), given("config"), "--").keys(), command_line_keys);
      if (!changes.keys.empty()) scenario = aco::simulation::with_run_keys(scenario, changes, registry);
    }
    if (vm.count("batch")) {
      const int n = vm["batch"].as<int>(), threads = host.threads;
      if (n < 1) throw aco::Error("--batch: N must be at least 1");
      const std::uint64_t seed = vm["seed"].as<std::uint64_t>();
      if (vm.count("variation-worker")) {
        aco::simulation::serve_variations(scenario, n, seed, registry);
        return aco::kExitOk;
      }
      aco::WorkerLimits limits;
      if (vm.count("variation-timeout"))
        limits.timeout_s = aco::parse_seconds(vm["variation-timeout"].as<std::string>(), "--variation-timeout");
      if (vm.count("variation-memory"))
        limits.memory_bytes = aco::parse_memory_size(vm["variation-memory"].as<std::string>(), "--variation-memory");
      aco::simulation::BatchSummary b;
      if (vm.count("in-process")) {
        if (limits.timeout_s > 0 || limits.memory_bytes > 0)
          std::cerr
              << "acosim: warning: --in-process: the variation time and memory limits are not enforced (they need "
                 "worker processes)\n";
        const aco::ThreadLimit limit(threads);
        b = aco::simulation::run_batch(aco::simulation::variations(scenario, n, seed, registry), registry);
      } else {
        // Each variation in a worker process: this acosim started again with the same arguments.
        std::vector<std::string> command{aco::this_program(), "--variation-worker"};
        command.insert(command.end(), argv + 1, argv + argc);
        b = aco::simulation::run_batch_in_workers(n, command, aco::lane_count(threads), limits,
                                                  [](int k, const aco::simulation::SimulationResult& r) {
                                                    std::cerr << "acosim: variation " << k << ": " << r.reason << "\n";
                                                  });
      }
      std::cout << "batch:      " << b.runs << " variations of " << scenario_file << " (seed " << seed
                << ", local planner " << scenario.run.pipeline.at("local").plugin << ")\n"
                << "reached:    " << b.reached << " (" << 100.0 * b.reached / b.runs << " %)\n"
                << "collisions: " << b.collisions << " (in reached runs: " << b.reached_with_collision << ")\n"
                << "outcomes:  ";
      for (const auto& [outcome, count] : b.outcomes) std::cout << " " << outcome << " " << count << ";";
      std::cout << "\nmean time to goal: " << b.mean_time
                << " s (reached runs); mean smallest clearance: " << b.mean_clearance << "; replans: " << b.replans
                << "\n";
      for (std::size_t k = 0; k < b.results.size(); ++k)  // to replay with --variation K
        if (!b.results[k].reached)
          std::cout << "variation " << k << ": " << b.results[k].outcome << " (" << b.results[k].reason << ")\n";
      return aco::kExitOk;
    }
    if (vm.count("variation")) {
      const int k = vm["variation"].as<int>();
      if (k < 0) throw aco::Error("--variation: K must be 0 or more");
      scenario = aco::simulation::variations(scenario, k + 1, vm["seed"].as<std::uint64_t>(), registry)[k];
    }
    const aco::simulation::SimulationResult result = aco::simulation::simulate(scenario, registry);
    if (!csv.empty()) aco::write_output_file(csv, aco::simulation::trajectory_csv(result), "trajectory CSV");
    if (!svg.empty()) aco::write_output_file(svg, aco::simulation::render_svg(scenario, result), "SVG");
    if (!html.empty()) aco::write_output_file(html, aco::simulation::render_html(scenario, result), "HTML player");
    if (vm["json"].as<bool>()) {
      std::cout << aco::simulation::summary_json(scenario, result, registry) << "\n";
    } else {
      std::cout << "scenario:  " << scenario_file << " (local planner " << scenario.run.pipeline.at("local").plugin
                << ")\n"
                << "outcome:   " << result.outcome << (result.reason.empty() ? "" : " (" + result.reason + ")") << "\n"
                << "time:      " << result.time << " s in " << result.steps << " control steps\n"
                << "distance:  " << result.distance << "\n"
                << "clearance: " << result.min_clearance << " (smallest)\n"
                << "collisions " << result.collisions << ", replans " << result.replans << "\n";
    }
    return result.reached ? aco::kExitOk : aco::kExitNoPath;
  });
}
