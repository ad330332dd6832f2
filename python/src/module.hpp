#pragma once
// What the native module's files share (module.cpp binds them): the plugin registry, the maps
// Python hands over as arrays, Ctrl-C while native code runs, and each file's bindings.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "aco/map.hpp"
#include "aco/engine/plugin_registry.hpp"
#include "aco/graph.hpp"
#include "aco/terrain.hpp"
#include "aco/drawing/voxel_view.hpp"
#include "aco/planning/yardsticks.hpp"

namespace aco_python {

namespace py = pybind11;

// One registry for the module's life, as a host has one per process (aco.set_plugin_dirs()
// rebuilds it).
aco::PluginRegistry& registry();

// A map given as an array (from aco.Map): occupancy (nonzero = blocked; a 3D array [z, y, x] is a
// voxel world) or heights (NaN = no data).
struct ArrayMap {
  py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast> blocked;
  py::array_t<double, py::array::c_style | py::array::forcecast> heights;
  double cell_size = 1.0;
  std::string name;
};

std::unique_ptr<aco::Map> make_map(const ArrayMap& source, const aco::TerrainOptions& terrain);
// ("occupancy", blocked, 1.0, name) or ("terrain", heights, cell size, name); a voxel world's
// blocked array is 3D, [z, y, x].
py::tuple arrays_of(const aco::Map& map);

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

// A run of aco.plan(), kept for its pictures and its map: the map it planned on (no file is read
// again to draw it), its graph's options, and the run (the final pheromone only when asked for).
struct PlannedRun {
  std::shared_ptr<const aco::Map> map;
  aco::GraphOptions graph_options;
  aco::PlanRun run;
  std::optional<aco::VoxelWorldView> voxel_view;  // a voxel world's run, on *map: its graph is not kept
};

void bind_plans(py::module_& m);  // plans.cpp
void bind_studies(py::module_& m);  // studies.cpp
void bind_pictures(py::module_& m);  // pictures.cpp

}  // namespace aco_python
