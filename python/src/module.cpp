// The native half of the Python package: aco._aco. The package's Python files (python/aco/) wrap
// it; everything here calls the libraries the hosts call, so a run from Python is acoplan's run
// and a study is acobench's.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <future>
#include <memory>
#include <optional>
#include <sstream>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/map_formats.hpp"
#include "aco/map_io.hpp"
#include "aco/memory_limit.hpp"
#include "aco/pipeline.hpp"
#include "aco/plan_report.hpp"
#include "aco/planning.hpp"
#include "aco/plugin_catalog.hpp"
#include "aco/plugin_error.hpp"
#include "aco/presets.hpp"
#include "aco/run_spec.hpp"
#include "aco/simulation/simulation.hpp"
#include "aco/studies/results_db.hpp"
#include "aco/studies/runner.hpp"
#include "aco/studies/statistics.hpp"
#include "aco/svg.hpp"
#include "aco/terrain.hpp"
#include "aco/thread_limit.hpp"
#include "aco/value_parsers.hpp"
#include "aco/version.hpp"
#include "aco/voxel.hpp"
#include "aco/voxel_svg.hpp"

namespace py = pybind11;

namespace {

// One registry for the module's life, as a host has one per process; extra folders rebuild it.
std::vector<std::filesystem::path> extra_plugin_dirs;
aco::PluginRegistry& registry() {
  static std::unique_ptr<aco::PluginRegistry> instance;
  static std::vector<std::filesystem::path> made_with;
  if (!instance || made_with != extra_plugin_dirs) {
    instance = std::make_unique<aco::PluginRegistry>(aco::PluginRegistry::default_search_dirs(extra_plugin_dirs));
    made_with = extra_plugin_dirs;
  }
  return *instance;
}

// A map given as an array (from aco.Map): occupancy (nonzero = blocked; a 3D array [z, y, x] is a
// voxel world) or heights (NaN = no data).
struct ArrayMap {
  py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> blocked;
  py::array_t<double, py::array::c_style | py::array::forcecast> heights;
  double cell_size = 1.0;
  std::string name;
};

std::unique_ptr<aco::Map> make_map(const ArrayMap& source, const aco::TerrainOptions& terrain) {
  if (source.heights.size() > 0) {
    const int height = static_cast<int>(source.heights.shape(0)), width = static_cast<int>(source.heights.shape(1));
    std::vector<double> heights(source.heights.data(), source.heights.data() + source.heights.size());
    return std::make_unique<aco::TerrainMap>(width, height, source.cell_size, std::move(heights), terrain.max_slope_deg,
                                             source.name);
  }
  if (source.blocked.ndim() == 3) {
    const int depth = static_cast<int>(source.blocked.shape(0)), height = static_cast<int>(source.blocked.shape(1)),
              width = static_cast<int>(source.blocked.shape(2));
    auto world = std::make_unique<aco::VoxelMap>(width, height, depth, source.name);
    const auto voxels = source.blocked.unchecked<3>();
    for (int z = 0; z < depth; ++z)
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) world->set_blocked({x, y, z}, voxels(z, y, x) != 0);
    return world;
  }
  const int height = static_cast<int>(source.blocked.shape(0)), width = static_cast<int>(source.blocked.shape(1));
  auto grid = std::make_unique<aco::OccupancyGrid>(width, height, source.name);
  const auto cells = source.blocked.unchecked<2>();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) grid->set_blocked({x, y}, cells(y, x) != 0);
  return grid;
}

// A map file as arrays, for aco.Map.load(): ("occupancy", blocked, 1.0, name) or ("terrain", heights, cell size,
// name); a voxel world's blocked array is 3D, [z, y, x].
py::tuple map_arrays(const std::filesystem::path& file, const aco::Keys& terrain_keys) {
  aco::Keys keys = terrain_keys;
  keys["map"] = file.string();
  const auto map = aco::load_problem_map(aco::resolve_problem(keys, registry(), "--"), &registry());
  const py::ssize_t w = map->width(), h = map->height();
  if (const auto* terrain = dynamic_cast<const aco::TerrainMap*>(map.get())) {
    py::array_t<double> heights({h, w});
    auto out = heights.mutable_unchecked<2>();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) out(y, x) = terrain->elevation({x, y});
    return py::make_tuple("terrain", heights, terrain->cell_size(), map->name());
  }
  if (map->volumetric()) {
    const py::ssize_t d = map->depth();
    py::array_t<bool> blocked({d, h, w});
    auto out = blocked.mutable_unchecked<3>();
    for (int z = 0; z < d; ++z)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out(z, y, x) = !map->passable({x, y, z});
    return py::make_tuple("occupancy", blocked, 1.0, map->name());
  }
  py::array_t<bool> blocked({h, w});
  auto out = blocked.mutable_unchecked<2>();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out(y, x) = !map->passable({x, y});
  return py::make_tuple("occupancy", blocked, 1.0, map->name());
}

// How often a run looks for Ctrl-C: taking the GIL may wait for another Python thread.
constexpr std::chrono::milliseconds kSignalCheckInterval{50};

// Python's signal handlers, run at most every kSignalCheckInterval from the thread that calls
// (they run in the main thread only): Ctrl-C throws their KeyboardInterrupt as an error_already_set.
class SignalCheck {
 public:
  void operator()() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < kSignalCheckInterval) return;
    last_ = now;
    py::gil_scoped_acquire locked;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// A cell from Python: (x, y) on a grid or terrain, (x, y, z) in a voxel world.
using CellArg = std::vector<int>;

// "x,y" or "x,y,z", as the command line writes a cell.
std::string cell_text(const CellArg& cell) {
  std::string text;
  for (const int v : cell) {
    if (!text.empty()) text += ',';
    text += std::to_string(v);
  }
  return text;
}

aco::Cell to_cell(const CellArg& cell) {
  if (cell.size() < 2 || cell.size() > 3) throw aco::Error("a cell is (x, y), or (x, y, z) in a voxel world");
  return {cell[0], cell[1], cell.size() == 3 ? cell[2] : 0};
}

// A voxel world's cells are (x, y, z), a grid's or a terrain's (x, y): the other count is refused
// before anything else is said of the cell (acoplan reads "X,Y" in a voxel world as layer 0).
void check_arity(const aco::Map& map, const CellArg& cell, const std::string& what) {
  const std::string given = what + " (" + cell_text(cell) + ")";
  const std::string size = std::to_string(map.width()) + "x" + std::to_string(map.height());
  if (map.volumetric() && cell.size() != 3)
    throw aco::Error(given + " has no z, but " + map.name() + " is a " + size + "x" + std::to_string(map.depth()) +
                     " voxel world: give its cells as (x, y, z)");
  if (!map.volumetric() && cell.size() != 2)
    throw aco::Error(given + " has a z, but " + map.name() + " is a " + size +
                     " 2D map: give its cells as (x, y) (a voxel world's cells have a z)");
}

// One run, as acoplan's: the keys over the pipeline file (a preset, a config file, or the
// default preset for the map's kind), resolved once, then plan_runs() and its JSON. Returns the
// JSON, the pipeline's source, the map's cell size (the world units of the path per cell), and
// what the run's picture needs and the JSON leaves out: each iteration's best length and, with
// keep_pheromone, the final pheromone per edge.
py::tuple plan(const std::variant<std::filesystem::path, ArrayMap>& map, const CellArg& start, const CellArg& goal,
               const aco::Keys& keys, const std::string& preset, const std::string& config, std::int64_t threads,
               const std::optional<std::string>& max_memory, bool keep_pheromone) {
  aco::KeyedValues changes;
  changes.keys = keys;
  changes.keys["start"] = cell_text(start);
  changes.keys["goal"] = cell_text(goal);
  const auto* file = std::get_if<std::filesystem::path>(&map);
  if (file) changes.keys["map"] = file->string();
  std::string source = preset;
  if (!config.empty())
    source = "none (config " + config + ")";
  else if (source.empty() && file)
    source = aco::default_preset(*file);
  else if (source.empty())
    source = std::get<ArrayMap>(map).heights.size()        ? "terrain"
             : std::get<ArrayMap>(map).blocked.ndim() == 3 ? "voxel"
                                                           : "robust";
  const aco::KeyedValues pipeline = config.empty() ? aco::preset_keys(source) : aco::config_file_keys(config);
  aco::RunSpec run = aco::resolve_run(aco::over_pipeline_file(pipeline, changes).keys, registry(), "--");
  run.colony.between_iterations = SignalCheck();  // Ctrl-C stops the colony after its iteration

  std::string json;
  double cell_size = 1.0;
  std::vector<double> iteration_best, pheromone;
  {
    py::gil_scoped_release unlocked;  // plugins written in Python take it back (python bridge plugins)
    const aco::MemoryLimit memory(max_memory ? std::optional(aco::parse_memory_size(*max_memory, "max_memory"))
                                             : std::nullopt);
    // load_problem()'s steps, with the cells' count of coordinates checked first.
    const std::unique_ptr<aco::Map> owned =
        file ? aco::load_problem_map(run.problem, &registry()) : make_map(std::get<ArrayMap>(map), run.problem.terrain);
    check_arity(*owned, start, "start");
    check_arity(*owned, goal, "goal");
    const aco::Cell from = to_cell(start), to = to_cell(goal);
    aco::check_cell(*owned, from, "start");
    aco::check_cell(*owned, to, "goal");
    if (keep_pheromone && owned->volumetric())
      throw aco::Error("svg_pheromone: the picture of a voxel world (" + owned->name() +
                       ") draws no pheromone field; plan without it");
    if (const auto* terrain = dynamic_cast<const aco::TerrainMap*>(owned.get())) cell_size = terrain->cell_size();
    const aco::Graph graph = aco::build_graph(*owned, run.graph);
    const aco::ThreadLimit limit(threads);
    const auto runs = aco::plan_runs(registry(), graph, graph.node(from), graph.node(to), run, 1);
    const aco::PlanReport report{run, registry(), graph, source};
    json = aco::to_json(report, runs.front());
    iteration_best = runs.front().iteration_best;
    if (keep_pheromone) pheromone = runs.front().pheromone;
  }
  return py::make_tuple(json, source, cell_size, iteration_best, pheromone);
}

// A parameter's default as its type's Python value (int, float, bool, str), as a run reads it.
py::object typed_default(const aco::ParamSpec& spec) {
  const aco::ParamValue value = aco::parse_value(spec, spec.default_value, spec.name);
  return std::visit([](const auto& v) { return py::cast(v); }, value);
}

py::dict parameter_dict(const aco::ParamSpec& spec) {
  return py::dict(py::arg("name") = spec.name, py::arg("type") = aco::to_string(spec.type),
                  py::arg("default") = typed_default(spec), py::arg("range") = spec.range ? spec.range : "",
                  py::arg("help") = spec.help);
}

// Every run key of acoplan's tables (problem, graph, planner, colony, the baseline planners', the
// slots), each a parameter_dict() with its group; the plugins' own keys are in plugins().
py::list run_key_tables() {
  py::list keys;
  const auto add = [&keys](std::span<const aco::ParamSpec> table, const std::string& group, const std::string& scope) {
    for (const auto& spec : table) {
      py::dict key = parameter_dict(spec);
      key["name"] = scope + spec.name;
      key["group"] = group;
      keys.append(key);
    }
  };
  add(std::span(&aco::planner_parameter(), 1), "planner", "");
  add(aco::problem_parameters(), "problem", "");
  add(aco::graph_parameters(), "graph", "");
  add(aco::colony_parameters(), "colony", "");
  for (const auto& planner : aco::planners_with_parameters())
    add(aco::planner_parameters(planner), planner, planner + ".");
  for (const char* slot : aco::kSlots) {
    std::string plugins;
    for (const auto& name : registry().names(slot)) plugins += (plugins.empty() ? "" : ",") + name;
    keys.append(py::dict(
        py::arg("name") = slot, py::arg("type") = "categorical", py::arg("default") = aco::default_plugin(slot),
        py::arg("range") = plugins,
        py::arg("help") = std::string(slot) + " plugin (range: those found), or a Python object with the slot's method",
        py::arg("group") = "slot"));
  }
  return keys;
}

py::list plugins() {
  py::list list;
  for (const auto& file : registry().available()) {
    py::dict plugin;
    plugin["slot"] = file.slot;
    plugin["name"] = file.name;
    plugin["version"] = file.record.version;
    plugin["summary"] = file.record.summary;
    plugin["file"] = file.file.string();
    plugin["unusable"] = file.unusable;
    py::list parameters;
    if (file.unusable.empty())
      for (const auto& spec : registry().load(file.slot, file.name).parameters())
        parameters.append(parameter_dict(spec));
    plugin["parameters"] = parameters;
    list.append(plugin);
  }
  return list;
}

// `text`: the experiment itself (Python's dict as JSON), for which `file` stands; empty: read `file`.
py::dict run_experiment(const std::filesystem::path& file, const std::string& text,
                        const std::filesystem::path& database, int threads,
                        const std::function<void(std::size_t, std::size_t)>& progress) {
  aco::studies::RunOptions options;
  options.database = database;
  options.threads = threads;
  // Ctrl-C: the trials running finish and are stored, no other starts, then KeyboardInterrupt.
  std::atomic<bool> interrupted = false;
  struct Interrupted {};
  options.progress = [&](std::size_t done, std::size_t total) {
    if (interrupted) throw Interrupted{};
    if (!progress) return;
    py::gil_scoped_acquire locked;
    progress(done, total);
  };
  const aco::studies::Experiment experiment = text.empty() ? aco::studies::load_experiment(file, registry())
                                                           : aco::studies::load_experiment_text(text, file, registry());
  aco::studies::RunSummary summary;
  // The trials run in a thread of their own, whichever threads they take: this one, Python's main
  // thread, runs the signal handlers meanwhile.
  std::optional<py::error_already_set> signal;
  {
    py::gil_scoped_release unlocked;
    auto trials =
        std::async(std::launch::async, [&] { return aco::studies::run_experiment(experiment, registry(), options); });
    while (trials.wait_for(kSignalCheckInterval) != std::future_status::ready) {
      py::gil_scoped_acquire locked;
      if (!signal && PyErr_CheckSignals() != 0) {
        signal.emplace();
        interrupted = true;
      }
    }
    try {
      summary = trials.get();
    } catch (const Interrupted&) {}
  }
  if (signal) throw std::move(*signal);
  py::list failures;
  py::dict by_reason;
  for (const auto& f : summary.failures) {
    failures.append(py::dict(py::arg("configuration") = f.configuration,
                             py::arg("reason") = aco::studies::to_string(f.kind), py::arg("message") = f.message,
                             py::arg("earlier") = f.earlier));
    const char* reason = aco::studies::to_string(f.kind);
    by_reason[py::str(reason)] = by_reason.attr("get")(reason, 0).cast<int>() + 1;
  }
  return py::dict(py::arg("trials") = summary.trials, py::arg("skipped") = summary.skipped,
                  py::arg("ran") = summary.ran, py::arg("failures") = failures,
                  py::arg("failures_by_reason") = by_reason, py::arg("same_runs") = experiment.same_runs(),
                  py::arg("seconds") = summary.seconds);
}

// A results database as columns (the runs, each with its problem's and configuration's name,
// the problem's optimum and the configuration's settings JSON), in the report's order.
// A field's values as a Python column: numbers as a NumPy array (NULL as NaN for reals, -1 for
// whole numbers), text and booleans as a list (NULL as None).
py::object python_column(const aco::studies::TrialField& field, const std::vector<aco::studies::TrialCell>& cells) {
  const auto numbers = [&](auto null) {
    std::vector<decltype(null)> values;
    for (const auto& cell : cells)
      values.push_back(std::visit(
          [null](const auto& v) -> decltype(null) {
            if constexpr (std::is_arithmetic_v<std::decay_t<decltype(v)>>)
              return static_cast<decltype(null)>(v);
            else
              return null;
          },
          cell));
    return py::object(py::array(py::cast(values)));
  };
  switch (field.type) {
    case aco::studies::TrialCellType::integer:
      return numbers(std::int64_t{-1});
    case aco::studies::TrialCellType::count:
      return numbers(std::uint64_t{0});
    case aco::studies::TrialCellType::real:
      return numbers(std::nan(""));
    default:
      break;
  }
  py::list values;
  for (const auto& cell : cells)
    values.append(std::visit(
        [](const auto& v) -> py::object {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>)
            return py::none();
          else
            return py::cast(v);
        },
        cell));
  return field.type == aco::studies::TrialCellType::boolean ? py::object(py::array(values)) : py::object(values);
}

// The trials of a database as columns: problem, configuration, the trial fields Python shows,
// optimal_length, settings; "properties": a column per property_columns() (NaN where a run has
// none); "csv_columns": runs.csv's columns before the properties, which come first in Python.
py::dict read_trials(const std::filesystem::path& database) {
  if (!std::filesystem::exists(database)) throw aco::Error(database.string() + ": no such results database");
  const aco::studies::ResultsDb db(database);
  const auto problems = db.problems();
  std::map<int, aco::studies::ConfigRecord> configs;
  for (const auto& [id, config] : db.configs()) configs[id] = config;
  py::list problem, configuration, settings;
  std::vector<double> optimal;
  const double none = std::nan("");
  const auto trials = db.trials();
  std::map<std::string, py::list> properties;
  for (const auto& name : aco::studies::property_columns(trials)) properties[name];
  const auto& fields = aco::studies::trial_fields();
  std::vector<std::vector<aco::studies::TrialCell>> cells(fields.size());
  for (const auto& t : trials) {
    for (auto& [name, column] : properties) {
      const auto it = t.properties.find(name);
      if (it == t.properties.end())
        column.append(none);
      else if (const auto* text = std::get_if<std::string>(&it->second))
        column.append(*text);
      else
        column.append(std::visit(
            [](const auto& v) -> double {
              if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::string>)
                return 0.0;
              else
                return static_cast<double>(v);
            },
            it->second));
    }
    const auto& p = problems.at(static_cast<std::size_t>(t.problem));
    problem.append(p.name);
    optimal.push_back(p.optimal_length > 0 ? p.optimal_length : none);
    configuration.append(configs.at(t.config).name);
    settings.append(configs.at(t.config).settings_json);
    for (std::size_t i = 0; i < fields.size(); ++i) cells[i].push_back(fields[i].get(t, p.optimal_length));
  }
  py::dict columns;
  columns["problem"] = problem;
  columns["configuration"] = configuration;
  for (std::size_t i = 0; i < fields.size(); ++i)
    if (fields[i].use & aco::studies::kInPython) columns[fields[i].column] = python_column(fields[i], cells[i]);
  columns["optimal_length"] = py::array(py::cast(optimal));
  columns["settings"] = settings;
  py::dict property_columns;
  for (const auto& [name, column] : properties) property_columns[py::str(name)] = column;
  columns["properties"] = property_columns;
  columns["csv_columns"] = aco::studies::runs_csv_columns();
  return columns;
}

// ---- Pictures and simulation (aco.plan(svg=), Result/Map._repr_svg_, aco.simulate) ----

using MapSource = std::variant<std::filesystem::path, ArrayMap>;

// The map and graph a run planned on, made again from the map and the run's problem and graph keys
// (its resolved config), as the run made them. A voxel world's pictures need no graph: none.
struct PlannedOn {
  std::unique_ptr<aco::Map> map;
  aco::Graph graph;
};

PlannedOn planned_on(const MapSource& source, const aco::Keys& run_keys) {
  aco::Keys keys;
  const auto wanted = [](const std::string& key) {
    const auto named = [&key](const aco::ParamSpec& spec) { return spec.name == key; };
    const auto problem = aco::problem_parameters(), graph = aco::graph_parameters();
    return key.rfind("map.", 0) == 0 || std::any_of(problem.begin(), problem.end(), named) ||
           std::any_of(graph.begin(), graph.end(), named);
  };
  for (const auto& [key, value] : run_keys)
    if (wanted(key) && key != "start" && key != "goal") keys[key] = value;
  const auto* file = std::get_if<std::filesystem::path>(&source);
  if (file)
    keys["map"] = file->string();
  else
    keys.erase("map");
  const aco::RunSpec run = aco::resolve_run(keys, registry());
  PlannedOn on;
  on.map = file ? aco::load_problem_map(run.problem, &registry())
                : make_map(std::get<ArrayMap>(source), run.problem.terrain);
  if (!on.map->volumetric()) on.graph = aco::build_graph(*on.map, run.graph);
  return on;
}

aco::Cell cell_of(const aco::Map& map, const CellArg& cell, const std::string& what) {
  check_arity(map, cell, what);
  const aco::Cell c = to_cell(cell);
  if (!map.contains(c)) throw aco::Error(what + " " + cell_text(cell) + " is outside the map");
  return c;
}

aco::NodeId node_of(const aco::Graph& graph, const CellArg& cell, const std::string& what) {
  return graph.node(cell_of(*graph.map, cell, what));
}

// The layers a run's voxel picture slices: the start's, the goal's and the path's highest.
std::vector<int> run_layers(const aco::VoxelWorldView& view) {
  std::vector<int> layers;
  if (view.start) layers.push_back(view.start->z);
  if (view.goal) layers.push_back(view.goal->z);
  if (!view.grid_path.empty())
    layers.push_back(
        std::max_element(view.grid_path.begin(), view.grid_path.end(), [](auto& a, auto& b) { return a.z < b.z; })->z);
  std::sort(layers.begin(), layers.end());
  layers.erase(std::unique(layers.begin(), layers.end()), layers.end());
  return layers;
}

// A voxel world's picture of a run (aco::render_voxel_svg): the isometric view with the paths,
// start and goal, and a slice per layer of run_layers().
std::string voxel_run_svg(const aco::Map& world, const std::string& title, const CellArg& start, const CellArg& goal,
                          const std::vector<CellArg>& grid_path, const std::vector<std::vector<double>>& path) {
  aco::VoxelWorldView view{world};
  view.title = title;
  view.start = cell_of(world, start, "start");
  view.goal = cell_of(world, goal, "goal");
  for (const auto& cell : grid_path) view.grid_path.push_back(cell_of(world, cell, "a grid path's cell"));
  for (const auto& point : path) {
    if (point.size() != 3) throw aco::Error("a path's point in a voxel world needs x, y and z");
    view.path.emplace_back(point[0], point[1], point[2]);
  }
  aco::VoxelSvgStyle style;
  style.slices = run_layers(view);
  return aco::render_voxel_svg(view, style);
}

// acoplan's picture of a run (aco::render_svg), from the run's fields as aco.Result holds them.
std::string run_svg(const MapSource& source, const aco::Keys& run_keys, const CellArg& start, const CellArg& goal,
                    const std::vector<CellArg>& grid_path, const std::vector<std::vector<double>>& path, bool solved,
                    double length, std::uint64_t seed, const std::vector<double>& best_so_far,
                    const std::vector<double>& iteration_best, const std::vector<double>& pheromone,
                    double optimal_length) {
  const PlannedOn on = planned_on(source, run_keys);
  const std::string title = aco::run_title(on.map->name(), solved, length, seed);
  if (on.map->volumetric()) {
    if (!pheromone.empty()) throw aco::Error("the picture of a voxel world draws no pheromone field");
    return voxel_run_svg(*on.map, title, start, goal, grid_path, path);
  }
  aco::RunPicture picture;
  picture.title = title;
  picture.start = node_of(on.graph, start, "start");
  picture.goal = node_of(on.graph, goal, "goal");
  for (const auto& cell : grid_path) picture.grid_path.push_back(node_of(on.graph, cell, "a grid path's cell"));
  for (const auto& point : path) {
    if (point.size() < 2) throw aco::Error("a path's point needs x and y");
    picture.path.emplace_back(point[0], point[1], point.size() > 2 ? point[2] : 0.0);
  }
  if (!pheromone.empty() && pheromone.size() != static_cast<std::size_t>(on.graph.num_edges()))
    throw aco::Error("the pheromone has " + std::to_string(pheromone.size()) + " values, not one per edge (" +
                     std::to_string(on.graph.num_edges()) + ")");
  picture.pheromone = pheromone;
  picture.best_so_far = best_so_far;
  picture.iteration_best = iteration_best;
  picture.optimal_length = optimal_length;
  return aco::render_svg(on.graph, picture);
}

// The map alone; a voxel world isometric, with slices at its lowest, middle and highest layers.
std::string map_svg(const MapSource& source, const aco::Keys& terrain_keys) {
  const PlannedOn on = planned_on(source, terrain_keys);
  if (!on.map->volumetric()) return aco::render_map_svg(on.graph);
  const aco::VoxelWorldView view{*on.map};
  aco::VoxelSvgStyle style;
  style.slices = aco::spread_layers(on.map->depth(), 3);
  return aco::render_voxel_svg(view, style);
}

// One simulation as acosim runs it: the scenario with its run keys changed, and what happened.
struct Simulation {
  aco::simulation::Scenario scenario;
  aco::simulation::SimulationResult result;
};

// acosim SCENARIO [--preset NAME | --config FILE] [--KEY VALUE ...]: the changes over the
// scenario's run keys, then the run; the same checks and messages.
Simulation simulate(const std::filesystem::path& file, const aco::Keys& keys, const std::string& preset,
                    const std::string& config) {
  Simulation run{aco::simulation::load_scenario(file, registry()), {}};
  aco::KeyedValues changes;
  if (!preset.empty()) changes = aco::preset_keys(preset);
  if (!config.empty()) changes = aco::config_file_keys(config);
  aco::KeyedValues given;
  given.keys = keys;
  changes = aco::overlay(changes, given);
  if (!changes.keys.empty()) run.scenario = aco::simulation::with_run_keys(run.scenario, changes, registry());
  py::gil_scoped_release unlocked;  // local planners written in Python take it back
  const aco::MemoryLimit memory(std::nullopt);
  run.result = aco::simulation::simulate(run.scenario, registry());
  return run;
}

// ---- end of pictures and simulation ----

using Sample = std::vector<double>;

py::handle plugin_error_type;  // aco.PluginError

// Raises the Python exception nested in `e` (a Python hook's, nested by python/bridge and the
// plugin guard): KeyboardInterrupt, SystemExit and every other BaseException that is no Exception
// as itself, any other as aco.PluginError(message) from it. False if none is nested.
bool raise_python_cause(const std::exception& e, const std::string& message) {
  try {
    std::rethrow_if_nested(e);
  } catch (const py::error_already_set& cause) {
    PyErr_Restore(cause.type().inc_ref().ptr(), cause.value().inc_ref().ptr(), cause.trace().inc_ref().ptr());
    if (cause.matches(PyExc_Exception)) py::raise_from(plugin_error_type.ptr(), message.c_str());
    return true;
  } catch (const std::exception& inner) {
    return raise_python_cause(inner, message);
  } catch (...) {}
  return false;
}

}  // namespace

PYBIND11_MODULE(_aco, m) {
  m.doc() = "aco's native module; use the package: import aco";
  m.attr("__version__") = aco::version();
  // Raised here, but at home in the package: tracebacks, help() and pickle say aco.Error.
  auto error = py::register_exception<aco::Error>(m, "Error", PyExc_ValueError);
  error.attr("__module__") = "aco";
  error.attr("__doc__") =
      "A bad run key or value, map, cell, plugin, preset, experiment file or database, with the message the "
      "command line (acoplan, acobench) gives. A ValueError: except ValueError catches it too.";
  auto& plugin_error = py::register_exception<aco::PluginError>(m, "PluginError", error.ptr());
  plugin_error.attr("__module__") = "aco";
  plugin_error_type = plugin_error;
  plugin_error.doc() =
      "A plugin failed: a C++ plugin threw, or a Python plugin's hook raised an exception, which is\n"
      "this error's __cause__ with its traceback (KeyboardInterrupt and SystemExit pass as themselves).";
  // Tried before the two above: an Error holding a Python hook's exception (python/bridge).
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      std::rethrow_exception(thrown);
    } catch (const aco::Error& e) {
      if (!raise_python_cause(e, e.what())) throw;
    }
  });

  py::class_<ArrayMap>(m, "ArrayMap")
      .def(py::init([](py::object blocked, py::object heights, double cell_size, std::string name) {
        ArrayMap a;
        if (!blocked.is_none()) a.blocked = blocked.cast<decltype(a.blocked)>();
        if (!heights.is_none()) a.heights = heights.cast<decltype(a.heights)>();
        a.cell_size = cell_size;
        a.name = std::move(name);
        return a;
      }));
  m.def("map_arrays", &map_arrays, py::arg("file"), py::arg("terrain_keys"));
  // A voxel world's .3dmap text, as acoplan and aco_mapgen write it (aco::write_movingai_voxels).
  m.def(
      "voxel_map_text",
      [](const ArrayMap& source) {
        const auto world = make_map(source, {});
        std::ostringstream text;
        aco::write_movingai_voxels(dynamic_cast<const aco::VoxelMap&>(*world), text);
        return text.str();
      },
      py::arg("map"));
  m.def("plan", &plan, py::arg("map"), py::arg("start"), py::arg("goal"), py::arg("keys"), py::arg("preset"),
        py::arg("config"), py::arg("threads"), py::arg("max_memory"), py::arg("keep_pheromone"));
  // A Moving AI .scen file's problems, with the map file acoplan --scen reads them on.
  m.def("scenarios", [](const std::filesystem::path& file) {
    py::list list;
    // A .3dscen's cells are voxels (x, y, z); it states no bucket and no map size (0).
    const auto cell = [](const aco::Scenario& s, aco::Cell c) {
      return s.volumetric ? py::make_tuple(c.x, c.y, c.z) : py::make_tuple(c.x, c.y);
    };
    for (const auto& s : aco::load_scenarios(file))
      list.append(py::dict(py::arg("map") = aco::scenario_map_file(file), py::arg("start") = cell(s, s.start),
                           py::arg("goal") = cell(s, s.goal), py::arg("optimal_length") = s.optimal_length,
                           py::arg("bucket") = s.bucket, py::arg("width") = s.width, py::arg("height") = s.height));
    return list;
  });
  m.def("plugins", &plugins);
  m.def("run_key_tables", &run_key_tables);
  // The prefixes of parameter keys ("update" of "update.rho", "ifwa" of "ifwa.radius").
  m.def("key_scopes", [] {
    std::vector<std::string> scopes(aco::kSlots.begin(), aco::kSlots.end());
    for (const auto& planner : aco::planners_with_parameters()) scopes.push_back(planner);
    return scopes;
  });
  m.def("describe", [](const std::string& name) { return aco::describe_plugin(registry(), name); });
  m.def("set_plugin_dirs", [](const std::vector<std::filesystem::path>& dirs) { extra_plugin_dirs = dirs; });
  m.def("search_dirs", [] { return registry().search_dirs(); });
  m.def("presets", [] {
    std::vector<std::pair<std::string, std::string>> list;
    for (const auto& p : aco::list_presets()) list.emplace_back(p.name, p.summary);
    return list;
  });
  m.def("run_experiment", &run_experiment, py::arg("file"), py::arg("text"), py::arg("database"), py::arg("threads"),
        py::arg("progress"));
  m.def("read_trials", &read_trials, py::arg("database"));
  // The trial fields (aco/studies/trial_record.hpp): where each goes, for the tests.
  m.def("trial_fields", [] {
    py::list fields;
    for (const auto& f : aco::studies::trial_fields())
      fields.append(py::dict(py::arg("name") = f.name, py::arg("column") = f.column, py::arg("stored_as") = f.stored_as,
                             py::arg("in_runs_table") = bool(f.use & aco::studies::kInRunsTable),
                             py::arg("when_used") = bool(f.use & aco::studies::kWhenUsed),
                             py::arg("in_runs_csv") = bool(f.use & aco::studies::kInRunsCsv),
                             py::arg("in_python") = bool(f.use & aco::studies::kInPython)));
    return fields;
  });

  // The report's statistics (aco/studies/statistics.hpp), on plain samples.
  m.def("summarize", [](const Sample& s) {
    const auto r = aco::studies::summarize(s);
    return py::dict(py::arg("n") = r.n, py::arg("mean") = r.mean, py::arg("sd") = r.stddev,
                    py::arg("median") = r.median, py::arg("q1") = r.q1, py::arg("q3") = r.q3, py::arg("iqr") = r.iqr,
                    py::arg("ci_low") = r.ci_low, py::arg("ci_high") = r.ci_high, py::arg("min") = r.min,
                    py::arg("max") = r.max);
  });
  m.def("mann_whitney_u", [](const Sample& a, const Sample& b) {
    const auto r = aco::studies::mann_whitney_u(a, b);
    return py::dict(py::arg("u") = r.u, py::arg("p") = r.p, py::arg("exact") = r.exact);
  });
  m.def("holm_adjust", [](const Sample& p) { return aco::studies::holm_adjust(p); });
  m.def("vargha_delaney_a12", [](const Sample& a, const Sample& b) { return aco::studies::vargha_delaney_a12(a, b); });
  m.def("effect_size", [](double a12) { return std::string(aco::studies::to_string(aco::studies::effect_size(a12))); });
  m.def("average_ranks", [](const std::vector<Sample>& scores) { return aco::studies::average_ranks(scores); });
  m.def("ecdf", [](Sample hitting_times, const Sample& at) { return aco::studies::ecdf(hitting_times, at); });
  m.def("expected_running_time", [](const Sample& hitting_times, const Sample& efforts) {
    return aco::studies::expected_running_time(hitting_times, efforts);
  });

  // Pictures and simulation.
  m.def("run_svg", &run_svg, py::arg("map"), py::arg("keys"), py::arg("start"), py::arg("goal"), py::arg("grid_path"),
        py::arg("path"), py::arg("solved"), py::arg("length"), py::arg("seed"), py::arg("best_so_far"),
        py::arg("iteration_best"), py::arg("pheromone"), py::arg("optimal_length"));
  m.def("map_svg", &map_svg, py::arg("map"), py::arg("terrain_keys"));
  py::class_<Simulation>(m, "Simulation")
      .def("summary_json",
           [](const Simulation& s) { return aco::simulation::summary_json(s.scenario, s.result, registry()); })
      .def("svg", [](const Simulation& s) { return aco::simulation::render_svg(s.scenario, s.result); })
      .def("html", [](const Simulation& s) { return aco::simulation::render_html(s.scenario, s.result); });
  m.def("simulate", &simulate, py::arg("file"), py::arg("keys"), py::arg("preset"), py::arg("config"));
}
