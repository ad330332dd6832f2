#include "aco/plugin_registry.hpp"

#include "aco/install_layout.hpp"

#include <boost/dll/library_info.hpp>
#include <boost/dll/runtime_symbol_info.hpp>
#include <boost/dll/shared_library.hpp>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <mutex>
#include <sstream>

namespace aco {
namespace {

namespace fs = std::filesystem;

// Every library the process loaded. Never destroyed: objects, vtables and exceptions a plugin
// created must not outlive its code, so no library is ever unloaded before exit.
struct Loaded {
  std::mutex mutex;
  std::vector<boost::dll::shared_library> libraries;
  std::map<std::string, const PluginDescriptor*> descriptors;  // by "file|alias"
};
Loaded& loaded() {
  static Loaded* instance = new Loaded;
  return *instance;
}

std::string alias_of(const PluginFile& p) { return kPluginAliasPrefix + p.kind + "__" + p.name; }
std::string label(const PluginFile& p) { return p.kind + "/" + p.name + " (" + p.file.string() + ")"; }

// Plugins exported by a library file, read from its "boostdll" section without loading it.
std::vector<PluginFile> exported_plugins(const fs::path& file) {
  std::vector<PluginFile> found;
  std::vector<std::string> symbols;
  try {
    boost::dll::library_info info(file);
    symbols = info.symbols("boostdll");
  } catch (const std::exception&) {
    return found;  // not a shared library we can read: not a plugin
  }
  const std::string prefix = kPluginAliasPrefix;
  for (const auto& symbol : symbols) {
    if (symbol.rfind(prefix, 0) != 0) continue;
    const std::string rest = symbol.substr(prefix.size());
    const auto split = rest.find("__");
    if (split == std::string::npos || split == 0 || split + 2 >= rest.size()) continue;
    found.push_back({rest.substr(0, split), rest.substr(split + 2), file});
  }
  return found;
}

}  // namespace

PluginRegistry::PluginRegistry(std::vector<fs::path> search_dirs) : dirs_(std::move(search_dirs)) {
  for (const auto& dir : dirs_) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> libraries;
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.path().extension() == ".so" && entry.is_regular_file(ec)) libraries.push_back(entry.path());
    std::sort(libraries.begin(), libraries.end());
    for (const auto& file : libraries)
      for (auto& plugin : exported_plugins(file))
        if (!find(plugin.kind, plugin.name)) files_.push_back(std::move(plugin));
  }
}

std::vector<fs::path> PluginRegistry::default_search_dirs(const std::vector<fs::path>& extra) {
  std::vector<fs::path> dirs = extra;
  if (const char* env = std::getenv("ACO_PLUGIN_PATH")) {
    std::istringstream parts(env);
    for (std::string part; std::getline(parts, part, ':');)
      if (!part.empty()) dirs.emplace_back(part);
  }
  // The bundled plugins: an installed framework's or its build tree's, never both.
  dirs.push_back(install_layout().plugins);
  return dirs;
}

std::vector<std::string> PluginRegistry::names(const std::string& kind) const {
  std::vector<std::string> result;
  for (const auto& p : files_)
    if (p.kind == kind) result.push_back(p.name);
  std::sort(result.begin(), result.end());
  return result;
}

const PluginFile* PluginRegistry::find(const std::string& kind, const std::string& name) const {
  for (const auto& p : files_)
    if (p.kind == kind && p.name == name) return &p;
  return nullptr;
}

const PluginDescriptor& PluginRegistry::load(const std::string& kind, const std::string& name) {
  const PluginFile* plugin = find(kind, name);
  if (plugin == nullptr) {
    std::string message = "unknown " + kind + " plugin '" + name + "'";
    const auto known = names(kind);
    if (const auto near = nearest(name, known); !near.empty()) message += "; did you mean '" + near + "'?";
    message += known.empty() ? " (no " + kind + " plugins found" : " (available: ";
    for (std::size_t i = 0; i < known.size(); ++i) message.append(i ? ", " : "").append(known[i]);
    message += "; searched:";
    for (const auto& dir : dirs_) message.append(" ").append(dir.string());
    throw Error(message + ")");
  }

  Loaded& state = loaded();
  std::lock_guard lock(state.mutex);
  const std::string key = plugin->file.string() + "|" + alias_of(*plugin);
  if (const auto it = state.descriptors.find(key); it != state.descriptors.end()) return *it->second;

  boost::dll::shared_library library;
  try {
    // Every symbol bound now: a plugin that needs one no library defines is refused here, with
    // the symbol named, instead of killing the process at its first call ("symbol lookup error").
    library.load(plugin->file, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local);
  } catch (const std::exception& e) {
    throw Error("plugin " + label(*plugin) + ": cannot be loaded: " + e.what());
  }
  // Kept even if the checks below refuse it: its static objects may already reference it.
  state.libraries.push_back(library);
  const PluginDescriptor* found = nullptr;
  try {
    found = &library.get_alias<const PluginDescriptor>(alias_of(*plugin));
  } catch (const std::exception& e) {
    throw Error("plugin " + label(*plugin) + ": no descriptor " + alias_of(*plugin) + ": " + e.what());
  }
  const PluginDescriptor& descriptor = *found;
  // magic and abi_version are read before any other field: their layout never changes.
  if (descriptor.magic != kPluginMagic) throw Error("plugin " + label(*plugin) + ": not an aco plugin descriptor");
  if (descriptor.abi_version != kPluginAbiVersion)
    throw Error("plugin " + label(*plugin) + ": ABI " + std::to_string(descriptor.abi_version) + ", host expects " +
                std::to_string(kPluginAbiVersion) + " (rebuild the plugin against this framework)");
  if (descriptor.compiler_abi != __GXX_ABI_VERSION)
    throw Error("plugin " + label(*plugin) + ": built with C++ ABI " + std::to_string(descriptor.compiler_abi) +
                ", host uses " + std::to_string(__GXX_ABI_VERSION));
  if (kind != descriptor.kind || name != descriptor.name || descriptor.create == nullptr)
    throw Error("plugin " + label(*plugin) + ": descriptor says " + descriptor.kind + "/" + descriptor.name);
  check_table(descriptor.parameters(), "plugin " + kind + "/" + name);
  state.descriptors[key] = &descriptor;
  return descriptor;
}

std::unique_ptr<Strategy> PluginRegistry::create(const std::string& kind, const std::string& name,
                                                 const ParameterValues& values) {
  const PluginDescriptor& descriptor = load(kind, name);
  std::unique_ptr<Strategy> strategy;
  try {
    strategy.reset(descriptor.create(values));
  } catch (...) {
    rethrow_from_plugin(identity(kind, name), "its factory");
  }
  if (!strategy) throw Error("plugin " + kind + "/" + name + ": factory returned nothing");
  return strategy;
}

PluginIdentity PluginRegistry::identity(const std::string& kind, const std::string& name) const {
  const PluginFile* file = find(kind, name);
  return {kind, name, file ? file->file.string() : std::string()};
}

}  // namespace aco
