// aco.plan() and what it needs: maps as arrays, cells, the run's record, the plugins and run keys.
#include "module.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <sstream>
#include <variant>

#include "aco/error.hpp"
#include "aco/engine/map_formats.hpp"
#include "aco/engine/map_io.hpp"
#include "aco/memory_limit.hpp"
#include "aco/planning/plan_request.hpp"
#include "aco/planning/planning.hpp"
#include "aco/planning/plugin_catalog.hpp"
#include "aco/planning/presets.hpp"
#include "aco/planning/run_pictures.hpp"
#include "aco/planning/run_report.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/value_parsers.hpp"
#include "aco/voxel.hpp"

namespace aco_python {

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

py::tuple arrays_of(const aco::Map& map) {
  const py::ssize_t w = map.width(), h = map.height();
  if (const auto* terrain = dynamic_cast<const aco::TerrainMap*>(&map)) {
    py::array_t<double> heights({h, w});
    auto out = heights.mutable_unchecked<2>();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) out(y, x) = terrain->elevation({x, y});
    return py::make_tuple("terrain", heights, terrain->cell_size(), map.name());
  }
  if (map.volumetric()) {
    const py::ssize_t d = map.depth();
    py::array_t<bool> blocked({d, h, w});
    auto out = blocked.mutable_unchecked<3>();
    for (int z = 0; z < d; ++z)
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) out(z, y, x) = !map.passable({x, y, z});
    return py::make_tuple("occupancy", blocked, 1.0, map.name());
  }
  py::array_t<bool> blocked({h, w});
  auto out = blocked.mutable_unchecked<2>();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out(y, x) = !map.passable({x, y});
  return py::make_tuple("occupancy", blocked, 1.0, map.name());
}

namespace {

// A map file as arrays, for aco.Map.load().
py::tuple map_arrays(const std::filesystem::path& file, const aco::Keys& terrain_keys) {
  aco::Keys keys = terrain_keys;
  keys["map"] = file.string();
  const aco::KeySpelling spelling = aco::KeySpelling::keyword();
  return arrays_of(*aco::load_problem_map(aco::resolve_problem(keys, registry(), spelling), &registry(), spelling));
}

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

// A JSON value as Python's json.loads() would give it, without the text between.
py::object to_python(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(value.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(value.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(value.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(value.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(value.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& item : value) list.append(to_python(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, item] : value.items()) dict[py::str(key)] = to_python(item);
      return dict;
    }
    default:
      throw aco::Error("a run's record holds a value JSON has no Python type for");
  }
}

// One run, as acoplan's: the keys over the pipeline PipelineSource chooses, resolved once, then
// aco::plan(PlanRequest). Returns the run's record (acoplan's --json, as a dict), the pipeline's
// name, the map's cell size (the world units of the path per cell) and the run itself.
py::tuple plan(const std::variant<std::filesystem::path, ArrayMap>& map, const CellArg& start, const CellArg& goal,
               const aco::Keys& keys, const std::string& preset, const std::string& config, std::int64_t threads,
               const std::optional<std::string>& max_memory, bool keep_pheromone) {
  aco::KeyedValues changes;
  changes.keys = keys;
  const auto* file = std::get_if<std::filesystem::path>(&map);
  if (file) changes.keys["map"] = file->string();
  const auto* array = std::get_if<ArrayMap>(&map);
  const aco::MapKind kind = file                         ? aco::map_kind(*file)
                            : array->heights.size()      ? aco::MapKind::terrain
                            : array->blocked.ndim() == 3 ? aco::MapKind::voxel
                                                         : aco::MapKind::grid;
  const aco::KeySpelling spelling = aco::KeySpelling::keyword();
  const aco::PipelineSource source = aco::PipelineSource::choose(preset, config, kind, spelling);
  aco::PlanRequest request;
  request.spelling = spelling;
  request.run = aco::resolve_run(aco::over_pipeline_file(source.keys(), changes).keys, registry(), spelling);
  // The cells as given, not as keys: check_arity() below names them with the map's size, once it is read.
  const auto to_cell = [](const CellArg& c) { return aco::Cell{c.at(0), c.at(1), c.size() == 3 ? c[2] : 0}; };
  request.run.problem.start = to_cell(start);
  request.run.problem.goal = to_cell(goal);
  request.run.colony.between_iterations = SignalCheck();  // Ctrl-C stops the colony after its iteration
  request.threads = static_cast<int>(threads);
  if (max_memory) request.max_memory = aco::parse_memory_size(*max_memory, "max_memory");
  if (array) request.map = make_map(*array, request.run.problem.terrain);
  request.check_map = [&](const aco::Map& loaded) {
    check_arity(loaded, start, "start");
    check_arity(loaded, goal, "goal");
    if (keep_pheromone && loaded.volumetric())
      throw aco::Error("svg_pheromone: the picture of a voxel world (" + loaded.name() +
                       ") draws no pheromone field; plan without it");
  };
  std::optional<aco::PlannedRuns> planned;
  {
    py::gil_scoped_release unlocked;  // plugins written in Python take it back (python bridge plugins)
    planned = aco::plan(request, registry());
  }
  const aco::PlanReport report{planned->run, registry(), planned->graph, source.name()};
  py::object record = to_python(aco::run_record(report, planned->runs.front()));
  const auto* terrain = dynamic_cast<const aco::TerrainMap*>(planned->map.get());
  // The run moves into what Python keeps: its record is made, and its pheromone (per edge, megabytes
  // on a large map) is dropped unless the picture needs it.
  auto kept =
      std::make_shared<PlannedRun>(PlannedRun{planned->map, planned->run.graph, std::move(planned->runs.front()), {}});
  if (!keep_pheromone) {
    kept->run.pheromone = {};
    kept->run.pheromone_edges = {};
  }
  if (planned->graph.volumetric) kept->voxel_view.emplace(aco::run_view(planned->graph, kept->run, false));
  return py::make_tuple(record, source.name(), terrain ? terrain->cell_size() : 1.0, kept);
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

}  // namespace

void bind_plans(py::module_& m) {
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
  m.def("gap_percent", &aco::gap_percent, py::arg("length"), py::arg("optimal"));
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
  m.def("presets", [] {
    std::vector<std::pair<std::string, std::string>> list;
    for (const auto& p : aco::list_presets()) list.emplace_back(p.name, p.summary);
    return list;
  });
}

}  // namespace aco_python
