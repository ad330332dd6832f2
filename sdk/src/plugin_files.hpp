#pragma once
// The plugins of a library file, and the default plugins a colony run fills its other slots
// with. Internal to the checks.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "aco/engine/pipeline.hpp"
#include "aco/engine/plugin_registry.hpp"

namespace aco::conformance {

// The registry over the file's folder (one per folder, kept for the process) and the file's
// plugins. Throws Error if the file is missing or exports none.
std::pair<PluginRegistry*, std::vector<PluginFile>> plugins_of(const std::filesystem::path& file);

// The default plugins, found where an installed or build-tree host finds them.
PluginRegistry& default_plugins();

// A fresh instance of the default plugin of `slot`, at its defaults.
template <class Interface>
std::unique_ptr<Interface> default_instance(const std::string& slot) {
  PluginRegistry& registry = default_plugins();
  const std::string name = default_plugin(slot);
  return registry.create<Interface>(slot, name, resolve(registry.load(slot, name).parameters(), {}, slot + "."));
}

}  // namespace aco::conformance
