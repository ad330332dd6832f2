// The plugins' side of the bridge: finds Python's runtime and the helper library, without
// linking either, and asks the helper for the object.
#include <dlfcn.h>

#include <filesystem>

#include "aco/error.hpp"
#include "bridge.hpp"

namespace aco::python {
namespace {

// The helper is built and installed beside the plugins: found next to this plugin's own file.
std::filesystem::path own_folder() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&own_folder), &info) == 0 || info.dli_fname == nullptr)
    throw Error("the python bridge cannot tell which file this plugin was loaded from");
  return std::filesystem::path(info.dli_fname).parent_path();
}

MakeObject load_helper() {
  // A Python process (the package aco) already has its runtime: a second one would be wrong.
  if (dlsym(RTLD_DEFAULT, "Py_IsInitialized") == nullptr &&
      // Global: numpy's extension modules link no libpython and look its symbols up in the process.
      dlopen(ACO_PYTHON_LIBRARY, RTLD_NOW | RTLD_GLOBAL) == nullptr)
    throw Error(std::string("the python plugins need Python's runtime library " ACO_PYTHON_LIBRARY
                            " (on Debian, python3-dev installs it), which cannot be loaded: ") +
                dlerror());
  const auto helper = own_folder() / ACO_PYTHON_BRIDGE_FILE;
  void* library = dlopen(helper.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) throw Error("cannot load the python bridge " + helper.string() + ": " + dlerror());
  const auto make = reinterpret_cast<MakeObject>(dlsym(library, "aco_python_make_object"));
  if (make == nullptr) throw Error("the python bridge " + helper.string() + " has no aco_python_make_object");
  return make;
}

}  // namespace

const SettingsTable<Settings>& settings_table() {
  static const SettingsTable<Settings> table({
      text_field("class", &Settings::object,
                 "the Python object, module:attribute (a class is made with no arguments, once per plugin object)"),
      text_field("path", &Settings::path,
                 "folders put in front of Python's sys.path before the import, separated by ':'"),
  });
  return table;
}

std::unique_ptr<Object> make_object(const std::string& slot, const ParameterValues& values,
                                    std::initializer_list<const char*> required) {
  static const MakeObject make = load_helper();  // once per plugin; a failure is tried again
  const Settings settings = settings_table().read(values);
  return std::unique_ptr<Object>(make(slot, settings.object, settings.path, {required.begin(), required.end()}));
}

}  // namespace aco::python
