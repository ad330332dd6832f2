#pragma once
// Host side of the plugin ABI: finds plugin libraries, loads them on demand, checks their ABI,
// and keeps every loaded library alive until the process exits.
#include <boost/config.hpp>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "aco/error.hpp"
#include "aco/plugin.hpp"
#include "aco/plugin_guard.hpp"

namespace aco {

struct PluginFile {
  std::string kind;
  std::string name;
  std::filesystem::path file;
};

class BOOST_SYMBOL_VISIBLE PluginRegistry {
 public:
  // Searches the folders in order; the first plugin of a given kind and name wins.
  explicit PluginRegistry(std::vector<std::filesystem::path> search_dirs);

  // `extra` (e.g. --plugin-dir), then every folder of ACO_PLUGIN_PATH, then the bundled plugins:
  // <prefix>/lib/aco/plugins of an installed libaco, or the build tree's plugin folder of one run
  // from its build tree (aco/install_layout.hpp).
  static std::vector<std::filesystem::path> default_search_dirs(const std::vector<std::filesystem::path>& extra = {});

  const std::vector<std::filesystem::path>& search_dirs() const { return dirs_; }
  // Every plugin found, read from the libraries' export tables without loading them.
  const std::vector<PluginFile>& available() const { return files_; }
  std::vector<std::string> names(const std::string& kind) const;
  const PluginFile* find(const std::string& kind, const std::string& name) const;

  // Loads the plugin (once) and checks it. Throws Error if it is missing, cannot be loaded,
  // was built for another ABI, or has a malformed parameter table.
  const PluginDescriptor& load(const std::string& kind, const std::string& name);

  // The plugin made by its factory (whatever the factory throws becomes an Error naming it).
  std::unique_ptr<Strategy> create(const std::string& kind, const std::string& name, const ParameterValues& values);

  // The plugin as its slot's interface, behind the error boundary (aco/plugin_guard.hpp): every
  // call into it that throws, on any thread, throws an Error naming the plugin and the hook.
  template <class Interface>
  std::unique_ptr<Interface> create(const std::string& kind, const std::string& name, const ParameterValues& values) {
    auto strategy = create(kind, name, values);
    auto* typed = dynamic_cast<Interface*>(strategy.get());
    if (typed == nullptr) throw Error("plugin " + kind + "/" + name + " does not implement the " + kind + " interface");
    strategy.release();
    return guard(std::unique_ptr<Interface>(typed), identity(kind, name));
  }

 private:
  PluginIdentity identity(const std::string& kind, const std::string& name) const;

  std::vector<std::filesystem::path> dirs_;
  std::vector<PluginFile> files_;
};

}  // namespace aco
