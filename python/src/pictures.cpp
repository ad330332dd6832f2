// Pictures and simulation: aco.plan(svg=), Result and Map in Jupyter, aco.simulate().
#include "module.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <variant>

#include "aco/error.hpp"
#include "aco/graph.hpp"
#include "aco/memory_limit.hpp"
#include "aco/planning/run_pictures.hpp"
#include "aco/planning/run_spec.hpp"
#include "aco/planning/presets.hpp"
#include "aco/simulation/simulation.hpp"
#include "aco/drawing/svg.hpp"
#include "aco/drawing/voxel_svg.hpp"

namespace aco_python {
namespace {

using MapSource = std::variant<std::filesystem::path, ArrayMap>;

// An aco.Map's map and graph, made from its file or array with its terrain keys, as a run on it
// makes them. A voxel world's pictures need no graph: none.
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

// acoplan's picture of a run (aco::render_svg; a voxel world's isometric, with a slice per layer of
// run_layers()), from the map it planned on: a 2D map's graph is built again, not its file read.
std::string run_svg(const PlannedRun& planned) {
  if (planned.voxel_view) {
    aco::VoxelSvgStyle style;
    style.slices = run_layers(*planned.voxel_view);
    return aco::render_voxel_svg(*planned.voxel_view, style);
  }
  const aco::Graph graph = aco::build_graph(*planned.map, planned.graph_options);
  return aco::render_svg(graph, aco::run_picture(graph, planned.run, !planned.run.pheromone.empty()));
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
  aco::KeyedValues given;
  given.keys = keys;
  const aco::KeySpelling spelling = aco::KeySpelling::keyword();
  const aco::KeyedValues changes = aco::overlay(aco::PipelineSource::named(preset, config, spelling).keys(), given);
  if (!changes.keys.empty()) run.scenario = aco::simulation::with_run_keys(run.scenario, changes, registry(), spelling);
  py::gil_scoped_release unlocked;  // local planners written in Python take it back
  const aco::MemoryLimit memory(std::nullopt, spelling);
  run.result = aco::simulation::simulate(run.scenario, registry());
  return run;
}

}  // namespace

void bind_pictures(py::module_& m) {
  py::class_<PlannedRun, std::shared_ptr<PlannedRun>>(m, "PlannedRun")
      .def("svg", &run_svg)
      .def("map_arrays", [](const PlannedRun& planned) { return arrays_of(*planned.map); });
  m.def("map_svg", &map_svg, py::arg("map"), py::arg("terrain_keys"));
  py::class_<Simulation>(m, "Simulation")
      .def("summary_json",
           [](const Simulation& s) { return aco::simulation::summary_json(s.scenario, s.result, registry()); })
      .def("svg", [](const Simulation& s) { return aco::simulation::render_svg(s.scenario, s.result); })
      .def("html", [](const Simulation& s) { return aco::simulation::render_html(s.scenario, s.result); });
  m.def("simulate", &simulate, py::arg("file"), py::arg("keys"), py::arg("preset"), py::arg("config"));
}

}  // namespace aco_python
