// The native half of the Python package: aco._aco. The package's Python files (python/aco/) wrap
// it; everything here calls the libraries the hosts call, so a run from Python is acoplan's run
// and a study is acobench's. This file makes the module and its errors; plans.cpp, studies.cpp
// and pictures.cpp bind the rest.
#include "module.hpp"

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <exception>
#include <filesystem>
#include <vector>

#include "aco/error.hpp"
#include "aco/plugin_error.hpp"
#include "aco/process/version.hpp"

namespace aco_python {
namespace {

std::vector<std::filesystem::path> extra_plugin_dirs;  // aco.set_plugin_dirs()

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

aco::PluginRegistry& registry() {
  static std::unique_ptr<aco::PluginRegistry> instance;
  static std::vector<std::filesystem::path> made_with;
  if (!instance || made_with != extra_plugin_dirs) {
    instance = std::make_unique<aco::PluginRegistry>(aco::PluginRegistry::default_search_dirs(extra_plugin_dirs));
    made_with = extra_plugin_dirs;
  }
  return *instance;
}

}  // namespace aco_python

using namespace aco_python;

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

  m.def("set_plugin_dirs", [](const std::vector<std::filesystem::path>& dirs) { extra_plugin_dirs = dirs; });
  m.def("search_dirs", [] { return registry().search_dirs(); });
  bind_plans(m);
  bind_studies(m);
  bind_pictures(m);
}
