#include "plugin_files.hpp"

#include <map>
#include <mutex>

#include "aco/sdk/conformance.hpp"

namespace aco::conformance {
namespace {

namespace fs = std::filesystem;

PluginRegistry& registry_of_folder(const fs::path& folder) {
  static std::mutex mutex;
  static std::map<fs::path, std::unique_ptr<PluginRegistry>> registries;
  std::lock_guard lock(mutex);
  auto& registry = registries[folder];
  if (!registry) registry = std::make_unique<PluginRegistry>(std::vector<fs::path>{folder});
  return *registry;
}

}  // namespace

std::pair<PluginRegistry*, std::vector<PluginFile>> plugins_of(const fs::path& file) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw Error(file.string() + ": no such file");
  const fs::path real = fs::canonical(file);
  PluginRegistry& registry = registry_of_folder(real.parent_path());
  std::vector<PluginFile> found;
  for (const auto& plugin : registry.available())
    if (fs::equivalent(plugin.file, real, ec)) found.push_back(plugin);
  if (found.empty())
    throw Error(file.string() +
                ": exports no aco plugin (or each is shadowed by a plugin of the same slot and name in a "
                "file of its folder that sorts before it)");
  return {&registry, found};
}

PluginRegistry& default_plugins() {
  static PluginRegistry registry(PluginRegistry::default_search_dirs());
  return registry;
}

std::vector<PluginFile> plugins_in(const fs::path& file) { return plugins_of(file).second; }

std::pair<PluginRegistry*, PluginFile> find_in(const fs::path& file, const std::string& slot) {
  auto [registry, plugins] = plugins_of(file);
  for (const auto& plugin : plugins)
    if (plugin.slot == slot) return {registry, plugin};
  throw Error(file.string() + ": exports no " + slot + " plugin");
}

}  // namespace aco::conformance
