#pragma once
// An acobench experiment file (YAML): the problems, the common settings, a baseline
// configuration and what to vary (named configurations, a full factorial, an ablation path).
// See data/experiments/README.md for the format.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "aco/graph.hpp"
#include "aco/parameters.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/map.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/simulation/simulation.hpp"

namespace aco::studies {

// A problem's cell as stored (fingerprint, problem setup): [x, y], or [x, y, z] where z is not 0
// (a voxel world's cell above the ground), so 2D problems keep the fingerprints stored before.
std::vector<int> cell_json(aco::Cell c);

struct Problem {
  std::string name;  // unique within the experiment
  std::filesystem::path map;  // resolved against the experiment file's folder
  // Its reader, as aco::ProblemSpec has it: map-format (or the map plugin claiming the file's
  // ending; "" for a built-in format by its ending) and a map plugin's map.NAME parameters.
  std::string map_format;
  aco::ParameterValues map_parameters;
  aco::Cell start;
  aco::Cell goal;
  int bucket = -1;  // Moving AI difficulty bucket (scenario column 1) for scenario problems, else -1
  // A simulation problem: an acosim scenario file (map, start and goal are its). A trial drives
  // the robot through it with the configuration's keys over the scenario's run keys.
  std::shared_ptr<const aco::simulation::Scenario> simulation;
  // With a simulation: each repetition drives through a generated variation of the scenario
  // (acosim --batch's unknown cells and crossing discs, drawn from the trial's seed, so every
  // configuration meets the same variations); without, through the scenario as written.
  bool variations = false;
};

// A configuration is a set of run keys (aco/planning/run_spec.hpp), written as on acoplan's command line
// without the dashes: "planner", "neighbourhood", "max-slope", colony parameters ("ants",
// "search"), slots ("update") and plugin parameters ("update.rho"); every key but the problem's
// (map, scen, start, goal: the experiment's problems) and the seed (set per trial). Keys it does
// not set keep their defaults; every key and value is checked when the experiment is loaded.
// Its origins (where each key was written) serve error messages; they are not part of its
// identity.
struct Configuration : aco::KeyedValues {
  std::string name;
  // The keys resolved, once, when the file is loaded (empty for configurations made later, such
  // as the ablation path's flips, which resolve when they are added to the run).
  std::optional<aco::RunSpec> run;
  // The configuration whose measured time, trial by trial, is this one's time limit (the key
  // time-limit-from of an OMPL configuration); "" for none.
  std::string time_limit_from() const;
};

// An OMPL configuration's key naming the configuration (or `colony`: the only colony one) whose
// wall time on the same problem and repetition is each trial's ompl.time_limit. Not a run key:
// resolve() leaves it out, the runner orders the trials by it.
inline constexpr const char* kTimeLimitFrom = "time-limit-from";

// The configuration with its run keys only (time-limit-from left out): what resolve_run() and a
// scenario take.
Configuration run_keys(const Configuration& config);

// The resolved run as JSON (aco::to_json), with time-limit-from when the configuration has it:
// what decides its trials, for the fingerprint and the stored settings.
std::string run_json(const Configuration& config, const aco::RunSpec& run);

struct Experiment {
  std::string name;
  std::filesystem::path file;
  std::vector<Problem> problems;
  Configuration baseline;  // common settings + the baseline's own keys
  std::vector<Configuration> configurations;  // baseline first, then named, then factorial
  std::optional<Configuration> ablation_target;
  int repetitions = 10;
  std::uint64_t seed = 1;
  // Per-trial limits of the worker processes (keys trial-timeout, trial-memory; acobench run's
  // --trial-timeout and --trial-memory win). Not part of the fingerprint: they decide which
  // trials fail, not what a trial computes.
  std::optional<double> trial_timeout_s;
  std::optional<std::uint64_t> trial_memory_bytes;

  // `path` relative to the experiment file's folder, as the database stores it (absolute when it
  // cannot be relative: another root). Works whether the experiment's path or `path` is relative.
  std::string relative_to_file(const std::filesystem::path& path) const;

  // Canonical text (JSON) of everything that decides the trials, the plugin binaries included
  // (name, version, SHA-256 of every plugin the configurations use): a results database made
  // with another fingerprint belongs to another experiment.
  std::string fingerprint(const aco::PluginRegistry& registry) const;

  // Pairs of configurations (the earlier first) that resolve to the same run: the same plugins
  // and parameters, such as one that forgot its plugin key and so is the baseline. Their
  // comparison would be of a run with itself.
  std::vector<std::pair<std::string, std::string>> same_runs() const;
};

// Loads and checks an experiment file. Errors name the file, the line and the key.
Experiment load_experiment(const std::filesystem::path& file, aco::PluginRegistry& registry);
// The same from text (YAML or JSON; Python's run_experiment(dict)): `file` stands for the file it
// would be, in messages, as the folder relative paths start from, and as the experiment file stored.
Experiment load_experiment_text(const std::string& text, const std::filesystem::path& file,
                                aco::PluginRegistry& registry);

// A configuration's keys resolved into a run (aco::resolve_run, without a problem: the trials
// take it from the problem list). Errors name the file, the line, the configuration and the key.
aco::RunSpec resolve(const Configuration& config, aco::PluginRegistry& registry);
// The same for an experiment's problems: when they are all simulations, the keys go over the
// first scenario's (a configuration may then set parameters of the scenarios' plugins, such as
// local.follow of their dwa); every scenario is checked when the trials are prepared.
aco::RunSpec resolve(const Configuration& config, const std::vector<Problem>& problems, aco::PluginRegistry& registry);

// The seed of a trial: a hash of the master seed, the problem's name and the repetition, so
// that a trial gives the same result whenever and wherever it runs, and every configuration
// meets the same random streams on the same problem and repetition (common random numbers).
std::uint64_t trial_seed(std::uint64_t master_seed, const std::string& problem, int repetition);

// The ablation path's components: the keys that differ between two configurations, grouped so
// that a slot's plugin moves together with its parameters ("update" carries "update.rho").
std::vector<std::vector<std::string>> ablation_components(const Configuration& from, const Configuration& to);

// `config` with one component set as in `target` (keys absent from the target are removed).
Configuration flip(const Configuration& config, const Configuration& target, const std::vector<std::string>& component);

}  // namespace aco::studies
