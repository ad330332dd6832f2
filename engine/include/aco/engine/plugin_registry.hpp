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
#include "aco/engine/plugin_compatibility.hpp"
#include "aco/engine/plugin_guard.hpp"

namespace aco {

struct PluginFile {
  std::string slot;
  std::string name;
  std::filesystem::path file;
  PluginRecord record;  // read from the file; empty fields if it has none
  std::string unusable;  // why it must not be loaded (foreign ABI or standard library); empty if it may
  // Files later in the search order exporting the same slot and name: this one hides them.
  std::vector<std::filesystem::path> shadowed;
};

// Which binary a run used: enough to tell, later, whether a rerun would use the same code.
struct PluginProvenance {
  std::string slot;
  std::string name;
  std::string version;
  std::string file;
  std::string sha256;  // of the library file's contents, hex
  std::string build;  // "optimised", "unoptimised"...: the record's (ACO_BUILD_OPTIMISATION)
};

class BOOST_SYMBOL_VISIBLE PluginRegistry {
 public:
  // Searches the folders in order; the first plugin of a given slot and name wins (the others are
  // kept as its `shadowed` files, and loading it warns about them).
  explicit PluginRegistry(std::vector<std::filesystem::path> search_dirs);

  // `extra` (e.g. --plugin-dir), then every folder of ACO_PLUGIN_PATH, then the bundled plugins:
  // <prefix>/lib/aco/plugins of an installed libaco, or the build tree's plugin folder of one run
  // from its build tree (aco/engine/install_layout.hpp). A folder of `extra` that is missing or is a
  // file is an Error saying which.
  static std::vector<std::filesystem::path> default_search_dirs(const std::vector<std::filesystem::path>& extra = {});

  const std::vector<std::filesystem::path>& search_dirs() const { return dirs_; }
  // Every plugin found, read from the libraries' export tables and plugin records without loading
  // them: no plugin code runs to list them.
  const std::vector<PluginFile>& available() const { return files_; }
  std::vector<std::string> names(const std::string& slot) const;
  const PluginFile* find(const std::string& slot, const std::string& name) const;
  // find(), or an Error listing the plugins of that slot and the folders searched.
  const PluginFile& get(const std::string& slot, const std::string& name) const;

  // Loads the plugin (once) and checks it. Throws Error if it is missing, was built for another
  // ABI or standard library, cannot be loaded (a symbol missing), crashes while loading (tried
  // first in a child process), or has a malformed parameter table.
  const PluginDescriptor& load(const std::string& slot, const std::string& name);

  // Name, version, file and content hash of the plugin (hashed once per file, not loaded).
  PluginProvenance provenance(const std::string& slot, const std::string& name) const;

  // The plugin made by its factory (whatever the factory throws becomes an Error naming it).
  std::unique_ptr<Strategy> create(const std::string& slot, const std::string& name, const ParameterValues& values);

  // The plugin as its slot's interface, behind the error boundary (aco/engine/plugin_guard.hpp): every
  // call into it that throws, on any thread, throws an Error naming the plugin and the hook.
  template <class Interface>
  std::unique_ptr<Interface> create(const std::string& slot, const std::string& name, const ParameterValues& values) {
    auto strategy = create(slot, name, values);
    auto* typed = dynamic_cast<Interface*>(strategy.get());
    if (typed == nullptr) throw Error("plugin " + slot + "/" + name + " does not implement the " + slot + " interface");
    strategy.release();
    return guard(std::unique_ptr<Interface>(typed), identity(slot, name));
  }

 private:
  PluginIdentity identity(const std::string& slot, const std::string& name) const;

  std::vector<std::filesystem::path> dirs_;
  std::vector<PluginFile> files_;
};

}  // namespace aco
