#pragma once
// acoplan's options: its own settings, then the run's keys (aco/planning/run_spec.hpp) as options: the
// problem, the graph, the planner, the colony, one flag per slot, and one option group per loaded
// plugin and per baseline planner built from its parameter table (--update.rho ...).
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aco/planning/run_spec.hpp"
#include "aco/engine/plugin_registry.hpp"

namespace acoplan {

// acoplan's own settings, not keys of the run; each declared once, with its option's name, range
// and help, in host_settings_table() (command_line.cpp). --print-config writes them with the run.
struct HostSettings {
  int threads = 0;
  bool svg_pheromone = false;
  int repeat = 1;
};

// How acoplan reports its runs (output_settings_table()): no part of a configuration, so
// --print-config leaves them out.
struct OutputSettings {
  bool json = false;
  bool irace = false;  // print only the cost (irace_cost, kIraceUnsolvedCost if unsolved) and exit 0
  // What a run costs irace. length: the final path's length; gap: the grid path's gap to A*'s
  // optimum in percent; gap_penalised: that gap g plus its square, g (1 + g), so that a
  // configuration is judged by its worst runs too, not by its mean alone. any_angle_gap(_penalised):
  // the same with the final path's gap to the exact any-angle optimum, for continuous smoothers.
  enum class IraceCost { length, gap, gap_penalised, any_angle_gap, any_angle_gap_penalised };
  IraceCost irace_cost = IraceCost::length;
  // X times the ants' moves per walk over the optimal path's length is added to the cost, so
  // that irace weighs effort (which time follows) against quality, deterministically.
  double irace_effort = 0.0;
};

struct Request {
  enum class Action { plan, help, version, list_plugins, list_presets, describe, print_config, dump_irace_params };
  Action action = Action::plan;
  std::string describe;  // plugin to describe
  std::string help;  // full --help text
  std::string config;
  std::string pipeline_source;  // "preset robust (the default for 2D maps ...)", "preset paper001", "config FILE"
  std::string irace_params_file;  // --dump-irace-params: where to write the table ("-" = stdout)
  std::vector<std::string> irace_slots;  // the slots whose plugins irace chooses (--irace-slots)
  std::string irace_plugin;  // --irace-plugin SLOT/NAME: only its parameters ("" = the slots')

  std::optional<std::filesystem::path> svg;
  std::optional<std::filesystem::path> html;  // a voxel world's 3D page
  std::optional<std::uint64_t> max_memory;  // --max-memory in bytes; none: the default limit

  HostSettings host;
  OutputSettings output;
  aco::RunSpec run;  // everything else, resolved once
  std::unique_ptr<aco::PluginRegistry> registry;
};

// Throws aco::Error with a message naming the offending option (and the nearest valid one).
Request parse_command_line(int argc, const char* const* argv);

// The named presets, each with its first comment line.
std::string list_presets();

}  // namespace acoplan
