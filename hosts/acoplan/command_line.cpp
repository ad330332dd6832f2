#include "command_line.hpp"

#include <boost/program_options.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "aco/error.hpp"
#include "aco/hosts/host_options.hpp"
#include "aco/engine/install_layout.hpp"
#include "aco/engine/map_formats.hpp"
#include "aco/memory_limit.hpp"
#include "aco/planning/planning.hpp"
#include "aco/planning/presets.hpp"
#include "aco/hosts/program_options_error.hpp"
#include "aco/settings_table.hpp"

namespace acoplan {
namespace po = boost::program_options;
namespace {

// acoplan's own settings and its output's form; everything else is a run key (aco/planning/run_spec.hpp).
// Options that name a file or an action (--map, --config, --svg FILE, --help, --print-config,
// --describe ...) stay plain options: they are not settings with a range and a default.
const aco::SettingsTable<HostSettings>& host_settings_table() {
  using S = HostSettings;
  static const aco::SettingsTable<S> table({
      aco::field("threads", &S::threads, "0:1024", aco::kThreadsHelp),
      aco::field(
          "svg-pheromone", &S::svg_pheromone, "",
          "also draw the final pheromone field in the --svg picture (and the strongest voxels' in --html's page)"),
      aco::field("repeat", &S::repeat, "1:1000000",
                 "plan N times with seeds seed, seed+1, ...; print mean and standard deviation (--svg shows the best "
                 "run)"),
  });
  return table;
}

const aco::SettingsTable<OutputSettings>& output_settings_table() {
  using S = OutputSettings;
  using Cost = OutputSettings::IraceCost;
  static const aco::SettingsTable<S> table({
      aco::field("json", &S::json, "", "print one JSON object instead of the readable summary"),
      aco::field("irace", &S::irace, "",
                 "for irace's target runner: print only the cost, the mean over --repeat of --irace-cost (1e9 for an "
                 "unsolved run), and exit 0 unless there is an error"),
      aco::choice("irace-cost", &S::irace_cost,
                  {"length", "gap", "gap-penalised", "any-angle-gap", "any-angle-gap-penalised"},
                  {Cost::length, Cost::gap, Cost::gap_penalised, Cost::any_angle_gap, Cost::any_angle_gap_penalised},
                  "with --irace: length = the final path's length; gap = the grid path's gap to A*'s optimum in %; "
                  "gap-penalised = that gap g plus its square, g (1 + g), which punishes the worst runs; "
                  "any-angle-gap(-penalised) = the same for the final path's gap to the exact any-angle optimum "
                  "(2D grid maps; for continuous smoothers such as taut)"),
      aco::field("irace-effort", &S::irace_effort, "0:1e12",
                 "with --irace: add X times the colony's effort, its ant moves per walk over the optimal path's "
                 "length (about 1 for walks as long as the optimum): effort stands for time, deterministically"),
  });
  return table;
}

std::string type_hint(const aco::ParamSpec& spec) {
  switch (spec.type) {
    case aco::ParamType::integer:
      return "N";
    case aco::ParamType::real:
      return "X";
    case aco::ParamType::boolean:
      return "BOOL";
    case aco::ParamType::categorical:
      return spec.range;
    case aco::ParamType::text:
      return "TEXT";
  }
  return "V";
}

std::string help_text(const aco::ParamSpec& spec) {
  std::string text =
      std::string(spec.help) + " [" + aco::to_string(spec.type) + ", default " + aco::shown_default(spec);
  if (spec.type != aco::ParamType::boolean && spec.type != aco::ParamType::categorical && spec.range && *spec.range)
    text += ", range " + std::string(spec.range);
  return text + "]";
}

void add_table(po::options_description& group, std::span<const aco::ParamSpec> table, const std::string& prefix) {
  for (const auto& spec : table) {
    auto* value = po::value<std::string>()->value_name(type_hint(spec));
    if (spec.type == aco::ParamType::boolean) value->implicit_value("true");
    group.add_options()((prefix + spec.name).c_str(), value, help_text(spec).c_str());
  }
}

// The options of `table` that were given, as run keys ("update.rho" -> "0.3").
void collect(const po::variables_map& vm, std::span<const aco::ParamSpec> table, const std::string& prefix,
             aco::Keys& keys) {
  for (const auto& spec : table)
    if (vm.count(prefix + spec.name)) keys[prefix + spec.name] = vm[prefix + spec.name].as<std::string>();
}

// The settings of `table` from the options given (the others at their defaults), checked.
template <class Settings>
Settings read_settings(const po::variables_map& vm, const aco::SettingsTable<Settings>& table) {
  aco::Keys given;
  collect(vm, table.parameters(), "", given);
  return table.read(aco::resolve(table.parameters(), given, "--"));
}

std::optional<std::string> text(const po::variables_map& vm, const char* key) {
  if (!vm.count(key)) return std::nullopt;
  return vm[key].as<std::string>();
}

// --irace-slots "update,init": every name must be a slot. No option means every slot that shapes
// the planned path: not local, which only acosim's robot uses, so irace would tune it blind.
std::vector<std::string> irace_slots(const std::optional<std::string>& option) {
  if (!option) {
    std::vector<std::string> slots(aco::kSlots.begin(), aco::kSlots.end());
    std::erase(slots, "local");
    return slots;
  }
  std::vector<std::string> slots;
  std::istringstream in(*option);
  for (std::string slot; std::getline(in, slot, ',');) {
    if (slot.empty()) continue;
    if (std::find(aco::kSlots.begin(), aco::kSlots.end(), slot) == aco::kSlots.end()) {
      std::string message = "--irace-slots: '" + slot + "' is not a slot (slots:";
      for (const char* known : aco::kSlots) message += std::string(" ") + known;
      throw aco::Error(message + ")");
    }
    slots.push_back(slot);
  }
  return slots;
}

std::filesystem::path bundled_map() {
  const std::filesystem::path relative = "maps/classic20/map1.txt";
  const std::filesystem::path data = aco::install_layout().data;
  if (std::filesystem::exists(data / relative)) return data / relative;
  throw aco::Error("no --map given and the bundled map " + relative.string() + " was not found under " + data.string());
}

// The settings of a --config file as Boost's parse_config_file() gives them, but read by
// aco::read_config_settings(), whose errors name the file and the line: those the command line's
// slot choices leave (aco::over_pipeline_file).
po::parsed_options config_options(const po::options_description& options, const std::string& file, bool lenient,
                                  const po::variables_map& command_line) {
  po::parsed_options parsed(&options);
  const auto settings = aco::read_config_settings(file);
  aco::KeyedValues in_file, chosen;
  for (const auto& setting : settings) in_file.keys[setting.key] = setting.value;
  for (const char* slot : aco::kSlots)
    if (command_line.count(slot)) chosen.keys[slot] = command_line[slot].as<std::string>();
  if (command_line.count("planner")) chosen.keys["planner"] = command_line["planner"].as<std::string>();
  const aco::Keys kept = aco::over_pipeline_file(in_file, chosen).keys;
  for (const auto& setting : settings) {
    if (!kept.count(setting.key)) continue;
    po::option option(setting.key, {setting.value});
    option.original_tokens = {setting.key, setting.value};
    const auto* known = options.find_nothrow(setting.key, false);
    option.unregistered = !known || known->long_name() != setting.key;
    if (option.unregistered && !lenient) throw po::unknown_option(setting.key);
    parsed.options.push_back(std::move(option));
  }
  return parsed;
}

// The pipeline the command runs: --preset's, --config's, or the recommended one for its map's kind.
aco::PipelineSource pipeline_source(const po::variables_map& vm) {
  const std::string map = vm.count("map")    ? vm["map"].as<std::string>()
                          : vm.count("scen") ? vm["scen"].as<std::string>()
                                             : "";
  return aco::PipelineSource::choose(text(vm, "preset").value_or(""), text(vm, "config").value_or(""),
                                     aco::map_kind(map), "--");
}

// Command line first, then the --config file: po keeps the first value stored for a key.
po::variables_map parse(const po::options_description& options, int argc, const char* const* argv, bool lenient) {
  po::variables_map vm;
  auto parser = po::command_line_parser(argc, argv).options(options);
  if (lenient) parser.allow_unregistered();
  const po::parsed_options parsed = parser.run();
  if (!lenient)
    for (const auto& option : parsed.options)
      if (option.position_key >= 0)
        throw aco::Error("unexpected argument '" + option.value.front() + "' (options start with --)");
  po::store(parsed, vm);
  {
    const std::string file = pipeline_source(vm).file().string();
    const po::parsed_options settings = config_options(options, file, lenient, vm);
    try {
      po::store(settings, vm);
    } catch (po::error& e) {
      throw aco::Error(file + ": " + aco::program_options_message(e));
    }
  }
  po::notify(vm);
  return vm;
}

std::string unknown_option_message(const po::unknown_option& e, const po::options_description& options,
                                   const aco::Keys& slots) {
  std::string name = e.get_option_name();
  name.erase(0, name.find_first_not_of('-'));
  std::vector<std::string> keys;
  for (const auto& option : options.options()) keys.push_back(option->long_name());
  std::string message = "unknown option '--" + name + "'";
  if (const auto near = aco::nearest(name, keys); !near.empty()) message += "; did you mean '--" + near + "'?";
  const auto dot = name.find('.');
  if (dot != std::string::npos) {
    const auto slot = slots.find(name.substr(0, dot));
    if (slot != slots.end()) {
      std::vector<std::string> params;
      for (const auto& key : keys)
        if (key.rfind(slot->first + ".", 0) == 0) params.push_back(key.substr(dot + 1));
      message += " (the " + slot->first + " plugin '" + slot->second + "' has ";
      if (params.empty())
        message += "no parameters)";
      else {
        message += "parameters:";
        for (const auto& p : params) message += " " + p;
        message += ")";
      }
    }
  }
  return message;
}

// The resolved run as a config file: acoplan's settings and the run's plain keys first, then one
// [section] per slot or planner with its parameters (INI's "update.rho" is "rho" under [update]).
std::string config_file(const Request& r) {
  std::ostringstream out;
  out << "# acoplan configuration; run it again with: acoplan --config FILE\n";
  const aco::ParameterValues host = host_settings_table().write(r.host);
  for (const auto& [name, value] : host.all()) out << name << " = " << aco::to_string(value) << "\n";
  const auto values = aco::run_values(r.run);
  std::string section;
  for (const auto& [key, value] : values)
    if (key.find('.') == std::string::npos) out << key << " = " << aco::to_string(value) << "\n";
  for (const auto& [key, value] : values) {
    const auto dot = key.find('.');
    if (dot == std::string::npos) continue;
    if (key.substr(0, dot) != section) out << "\n[" << (section = key.substr(0, dot)) << "]\n";
    out << key.substr(dot + 1) << " = " << aco::to_string(value) << "\n";
  }
  return out.str();
}

}  // namespace

Request parse_command_line(int argc, const char* const* argv) {
  Request r;
  aco::HostOptions host_options;
  po::options_description general("General");
  general.add_options()("help,h", po::bool_switch(),
                        "print this help (with the options of the chosen plugins) and exit")(
      "version", po::bool_switch(), "print the framework's version, commit, build type and compiler and exit")(
      "map", po::value<std::string>()->value_name("FILE"),
      "map: Moving AI .map, ROS map_server .yaml, ESRI ASCII terrain .asc, PGM height image .pgm, a format a map "
      "plugin claims, or 0/1 matrix text (default: bundled classic map1)")(
      "map-format", po::value<std::string>()->value_name("NAME"),
      "read --map with this format, built in (movingai, ros, esri_ascii, height_pgm, matrix) or a map plugin's "
      "(--list-plugins: map/NAME), whatever its ending")("start", po::value<std::string>()->value_name("X,Y"),
                                                         "start cell (column, row from the top, 0-based)")(
      "goal", po::value<std::string>()->value_name("X,Y"), "goal cell")(
      "scen", po::value<std::string>()->value_name("FILE"),
      "Moving AI scenario file (.scen, or .3dscen for voxel worlds); start and goal come from --scen-index, the map "
      "from FILE minus .scen (.3dscen) unless --map")(
      "dump-irace-params", po::value<std::string>()->value_name("FILE"),
      "write irace's parameter file (colony and plugin parameters) to FILE (- = stdout) and exit")(
      "irace-slots", po::value<std::string>()->value_name("SLOTS"),
      "with --dump-irace-params: the slots whose plugin irace chooses, comma separated (default: all but local, which "
      "acoplan does not use)")(
      "irace-plugin", po::value<std::string>()->value_name("SLOT/NAME"),
      "with --dump-irace-params: only this plugin's parameters, its slot fixed to it (e.g. update/mine)")(
      "svg", po::value<std::string>()->value_name("FILE"),
      "write a picture of the map, the path and the convergence curve (a voxel world: an isometric view and "
      "slices)")(
      "html", po::value<std::string>()->value_name("FILE"),
      "voxel worlds: write one self-contained page showing the world, the path, start and goal in 3D (three.js "
      "inside; turn and zoom with the mouse; works offline)")("config", po::value<std::string>()->value_name("FILE"),
                                                              "read options from an INI file (command line wins)")(
      "preset", po::value<std::string>()->value_name("NAME"),
      "read options from the named preset's INI file (see --list-presets; command line wins); default: robust on 2D "
      "maps, terrain on height maps, voxel on voxel worlds, unless --config is given")(
      "list-presets", po::bool_switch(), "list the named presets and exit")(
      "print-config", po::bool_switch(), "print the full resolved configuration as a config file and exit")(
      "list-plugins", po::bool_switch(), "list the plugins found and exit")(
      "describe", po::value<std::string>()->value_name("SLOT/NAME"),
      "print a plugin's parameter table and exit (e.g. init/potential_field; the NAME alone if one slot only has it)");
  host_options.add_plugin_dir_and_max_memory(general);
  add_table(general, host_settings_table().parameters(), "");
  add_table(general, output_settings_table().parameters(), "");
  po::options_description problem("Problem and graph");
  add_table(problem, std::span(&aco::planner_parameter(), 1), "");
  add_table(problem, aco::problem_parameters(), "");
  add_table(problem, aco::graph_parameters(), "");
  po::options_description colony("Colony");
  add_table(colony, aco::colony_parameters(), "");
  po::options_description baselines("Baseline planners (--planner ifwa|pso)");
  for (const auto& planner : aco::planners_with_parameters())
    add_table(baselines, aco::planner_parameters(planner), planner + ".");
  po::options_description slots("Strategies (one plugin per slot; see --list-plugins)");
  for (const char* slot : aco::kSlots)
    slots.add_options()(slot, po::value<std::string>()->value_name("PLUGIN"),
                        (std::string(slot) + " plugin [default " + aco::default_plugin(slot) + "]").c_str());
  po::options_description base;
  base.add(general).add(problem).add(colony).add(baselines).add(slots);

  try {
    // Pass 1: which plugins, and where to find them; their options are not known yet.
    const po::variables_map first = parse(base, argc, argv, true);
    r.registry = std::make_unique<aco::PluginRegistry>(host_options.plugin_search_dirs());
    if (first["version"].as<bool>()) {
      r.action = Request::Action::version;
      return r;
    }
    if (first["list-plugins"].as<bool>()) {
      r.action = Request::Action::list_plugins;
      return r;
    }
    if (first["list-presets"].as<bool>()) {
      r.action = Request::Action::list_presets;
      return r;
    }
    if (first.count("dump-irace-params")) {
      r.action = Request::Action::dump_irace_params;
      r.irace_params_file = first["dump-irace-params"].as<std::string>();
      r.irace_slots = irace_slots(text(first, "irace-slots"));
      r.irace_plugin = text(first, "irace-plugin").value_or("");
      if (!r.irace_plugin.empty() && first.count("irace-slots"))
        throw aco::Error("--irace-plugin and --irace-slots: give one of them (the plugin's slot is fixed to it)");
      return r;
    }
    if (first.count("describe")) {
      r.action = Request::Action::describe;
      r.describe = first["describe"].as<std::string>();
      return r;
    }
    aco::Keys plugins;  // slot -> plugin
    for (const char* slot : aco::kSlots) plugins[slot] = text(first, slot).value_or(aco::default_plugin(slot));
    // The map plugin reading the map, if one does: its parameters are options too (--map.NAME).
    std::string map_plugin;
    if (const auto file = text(first, "map")) {
      const std::string format = aco::map_format_of(*file, text(first, "map-format").value_or(""), *r.registry);
      if (!format.empty() && !aco::find_builtin_map_format(format)) map_plugin = format;
    }

    // Pass 2: every option known; anything left over is a mistake.
    po::options_description all;
    all.add(base);
    std::vector<std::unique_ptr<po::options_description>> groups;
    for (const char* slot : aco::kSlots) {
      const auto& name = plugins[slot];
      const aco::PluginDescriptor& d = r.registry->load(slot, name);
      groups.push_back(std::make_unique<po::options_description>(std::string(slot) + " plugin '" + name + "'"));
      add_table(*groups.back(), d.parameters(), std::string(slot) + ".");
      all.add(*groups.back());
    }
    if (!map_plugin.empty()) {
      groups.push_back(std::make_unique<po::options_description>("map plugin '" + map_plugin + "'"));
      add_table(*groups.back(), r.registry->load("map", map_plugin).parameters(), "map.");
      all.add(*groups.back());
    }
    po::variables_map vm;
    try {
      vm = parse(all, argc, argv, false);
    } catch (const po::unknown_option& e) {
      throw aco::Error(unknown_option_message(e, all, plugins));
    }
    std::ostringstream help;
    help << "acoplan: plan a path with an ant colony composed of runtime plugins.\n\n"
         << "Usage: acoplan [--map FILE --start X,Y --goal X,Y | --scen FILE --scen-index N] [options]\n\n"
         << "A command naming no pipeline (--preset, --config) runs the recommended preset over the engine defaults\n"
         << "listed below: robust on 2D maps, terrain on height maps; --print-config shows what a command runs,\n"
         << "--list-presets the others (each paper's pipeline: --preset paper000 ... paper004).\n\n"
         << all << "\nExit status: " << aco::kExitOk << " solved, " << aco::kExitError << " error, " << aco::kExitNoPath
         << " no path found (goal unreachable or no ant arrived; " << aco::kExitOk << " with --irace).\n";
    r.help = help.str();
    if (vm["help"].as<bool>()) {
      r.action = Request::Action::help;
      return r;
    }
    aco::Keys keys;
    for (const char* key : {"map", "map-format", "scen", "start", "goal"})
      if (auto v = text(vm, key)) keys[key] = *v;
    collect(vm, std::span(&aco::planner_parameter(), 1), "", keys);
    collect(vm, aco::problem_parameters(), "", keys);
    collect(vm, aco::graph_parameters(), "", keys);
    collect(vm, aco::colony_parameters(), "", keys);
    for (const auto& planner : aco::planners_with_parameters())
      collect(vm, aco::planner_parameters(planner), planner + ".", keys);
    for (const char* slot : aco::kSlots) {
      if (vm.count(slot)) keys[slot] = plugins[slot];
      collect(vm, r.registry->load(slot, plugins[slot]).parameters(), std::string(slot) + ".", keys);
    }
    if (!map_plugin.empty()) collect(vm, r.registry->load("map", map_plugin).parameters(), "map.", keys);
    for (const char* option : {"irace-slots", "irace-plugin"})
      if (vm.count(option)) throw aco::Error(std::string("--") + option + " needs --dump-irace-params");
    if (!keys.count("map") && !keys.count("scen")) {
      // The demo problem: the bundled classic map, corner to corner.
      keys["map"] = bundled_map().string();
      keys.emplace("start", "0,0");
      keys.emplace("goal", "19,19");
    }
    if (!keys.count("scen") && (!keys.count("start") || !keys.count("goal")))
      throw aco::Error("--start and --goal are required with --map (or use --scen)");
    r.run = aco::resolve_run(keys, *r.registry, "--");
    r.host = read_settings(vm, host_settings_table());
    r.output = read_settings(vm, output_settings_table());
    if (auto v = text(vm, "svg")) r.svg = *v;
    if (auto v = text(vm, "html")) r.html = *v;
    r.max_memory = host_options.max_memory_bytes();
    r.pipeline_source = pipeline_source(vm).description("--");
    if (vm["print-config"].as<bool>()) {
      r.action = Request::Action::print_config;
      r.config = config_file(r);
    }
  } catch (po::error& e) {
    throw aco::Error(aco::program_options_message(e));
  }
  return r;
}

std::string list_presets() {
  std::ostringstream out;
  out << "presets (--preset NAME; files in " << aco::preset_folder().string() << "):\n";
  for (const auto& preset : aco::list_presets()) out << "  " << preset.name << "  " << preset.summary << "\n";
  return out.str();
}

}  // namespace acoplan
