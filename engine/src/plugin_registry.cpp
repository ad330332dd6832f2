#include "aco/engine/plugin_registry.hpp"

#include "aco/engine/install_layout.hpp"

#include <boost/dll/library_info.hpp>
#include <boost/dll/shared_library.hpp>

#include <dlfcn.h>
#include <openssl/evp.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
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
  std::map<std::string, std::string> sha256;  // by file
};
Loaded& loaded() {
  static Loaded* instance = new Loaded;
  return *instance;
}

std::string alias_of(const PluginFile& p) { return kPluginAliasPrefix + p.slot + "__" + p.name; }
std::string label(const PluginFile& p) { return p.slot + "/" + p.name + " (" + p.file.string() + ")"; }

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
    PluginFile plugin;
    plugin.slot = rest.substr(0, split);
    plugin.name = rest.substr(split + 2);
    plugin.file = file;
    found.push_back(std::move(plugin));
  }
  if (found.empty()) return found;

  std::vector<PluginRecord> records;
  std::string unreadable;
  try {
    records = read_plugin_records(file);
  } catch (const Error& e) {
    unreadable = e.what();
  }
  for (auto& plugin : found) {
    const auto record = std::find_if(records.begin(), records.end(), [&](const PluginRecord& r) {
      return (r.slot == plugin.slot && r.name == plugin.name) || r.abi != std::to_string(kPluginAbiVersion);
    });
    if (!unreadable.empty())
      plugin.unusable = "its plugin record cannot be read: " + unreadable;
    else if (record == records.end())
      plugin.unusable = "it has no plugin record (section " ACO_PLUGIN_RECORD_SECTION
                        "): built for plugin ABI 7 or earlier; rebuild it against this framework";
    else {
      plugin.record = *record;
      plugin.unusable = incompatibility(*record);
    }
  }
  return found;
}

// Loads the library in a child process first: if its initialisers crash (a corrupted library,
// or one built for another processor), the child dies instead of the host, and the host can say
// which file it was. Empty if the child survived (whether or not it could load the library).
std::string crash_while_loading(const fs::path& file) {
  const pid_t child = fork();
  if (child < 0) return {};  // cannot try it apart: the load proper will tell
  if (child == 0) _exit(dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL) != nullptr ? 0 : 1);
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return {};
  if (!WIFSIGNALED(status)) return {};
  return std::string("crashed while loading (signal ") + std::to_string(WTERMSIG(status)) + ", " +
         strsignal(WTERMSIG(status)) +
         ", in a child process that tried it first): the library is corrupt or "
         "was not built for this machine; rebuild or remove it";
}

std::string sha256_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error("cannot read " + file.string() + " to hash it");
  std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> context(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1)
    throw Error("cannot hash " + file.string() + ": OpenSSL's SHA-256 is unavailable");
  std::array<char, 1 << 16> buffer;
  while (in) {
    in.read(buffer.data(), buffer.size());
    EVP_DigestUpdate(context.get(), buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (!in.eof()) throw Error("cannot read " + file.string() + " to hash it");
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest;
  unsigned int size = 0;
  EVP_DigestFinal_ex(context.get(), digest.data(), &size);
  std::string hex;
  constexpr const char* kDigits = "0123456789abcdef";
  for (unsigned int i = 0; i < size; ++i) hex += {kDigits[digest[i] >> 4], kDigits[digest[i] & 15]};
  return hex;
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
      for (auto& plugin : exported_plugins(file)) {
        const auto first = std::find_if(files_.begin(), files_.end(), [&](const PluginFile& p) {
          return p.slot == plugin.slot && p.name == plugin.name;
        });
        if (first == files_.end())
          files_.push_back(std::move(plugin));
        else
          first->shadowed.push_back(file);
      }
  }
}

std::vector<fs::path> PluginRegistry::default_search_dirs(const std::vector<fs::path>& extra) {
  // A folder the user named must be one: a missing folder would otherwise only show later as
  // "unknown plugin", and a plugin file given as the folder would be silently skipped.
  for (const auto& dir : extra) {
    std::error_code error;
    if (fs::is_directory(dir, error)) continue;
    if (fs::exists(dir, error))
      throw Error("--plugin-dir " + dir.string() + ": a file, not a folder; give the folder it is in (--plugin-dir " +
                  (dir.has_parent_path() ? dir.parent_path().string() : std::string(".")) + ")");
    throw Error("--plugin-dir " + dir.string() + ": no such folder");
  }
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

std::vector<std::string> PluginRegistry::names(const std::string& slot) const {
  std::vector<std::string> result;
  for (const auto& p : files_)
    if (p.slot == slot) result.push_back(p.name);
  std::sort(result.begin(), result.end());
  return result;
}

const PluginFile* PluginRegistry::find(const std::string& slot, const std::string& name) const {
  for (const auto& p : files_)
    if (p.slot == slot && p.name == name) return &p;
  return nullptr;
}

const PluginFile& PluginRegistry::get(const std::string& slot, const std::string& name) const {
  if (const PluginFile* plugin = find(slot, name)) return *plugin;
  std::string message = "unknown " + slot + " plugin '" + name + "'";
  const auto known = names(slot);
  if (const auto near = nearest(name, known); !near.empty()) message += "; did you mean '" + near + "'?";
  message += known.empty() ? " (no " + slot + " plugins found" : " (available: ";
  for (std::size_t i = 0; i < known.size(); ++i) message.append(i ? ", " : "").append(known[i]);
  message += "; searched:";
  for (const auto& dir : dirs_) message.append(" ").append(dir.string());
  throw Error(message + ")");
}

const PluginDescriptor& PluginRegistry::load(const std::string& slot, const std::string& name) {
  const PluginFile* plugin = &get(slot, name);
  if (!plugin->unusable.empty()) throw Error("plugin " + label(*plugin) + ": " + plugin->unusable);

  Loaded& state = loaded();
  std::lock_guard lock(state.mutex);
  const std::string key = plugin->file.string() + "|" + alias_of(*plugin);
  if (const auto it = state.descriptors.find(key); it != state.descriptors.end()) return *it->second;

  if (const auto crash = crash_while_loading(plugin->file); !crash.empty())
    throw Error("plugin " + label(*plugin) + ": " + crash);
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
  if (slot != descriptor.slot || name != descriptor.name || descriptor.create == nullptr)
    throw Error("plugin " + label(*plugin) + ": descriptor says " + descriptor.slot + "/" + descriptor.name);
  check_table(descriptor.parameters(), "plugin " + slot + "/" + name);
  state.descriptors[key] = &descriptor;
  // Allowed (a user may mean to replace a bundled plugin), but never silently.
  for (const auto& hidden : plugin->shadowed)
    std::cerr << "warning: plugin " << slot << "/" << name << " from " << plugin->file.string() << " shadows "
              << hidden.string() << " (the first in the plugin search order wins)\n";
  return descriptor;
}

std::unique_ptr<Strategy> PluginRegistry::create(const std::string& slot, const std::string& name,
                                                 const ParameterValues& values) {
  const PluginDescriptor& descriptor = load(slot, name);
  std::unique_ptr<Strategy> strategy;
  const PluginIdentity who = identity(slot, name);
  try {
    const PluginCallScope scope(who, "its factory", -1);
    strategy.reset(descriptor.create(values));
  } catch (...) {
    rethrow_from_plugin(who, "its factory");
  }
  if (!strategy) throw Error("plugin " + slot + "/" + name + ": factory returned nothing");
  return strategy;
}

PluginProvenance PluginRegistry::provenance(const std::string& slot, const std::string& name) const {
  const PluginFile& plugin = get(slot, name);
  const std::string file = plugin.file.string();
  Loaded& state = loaded();
  std::lock_guard lock(state.mutex);
  auto hash = state.sha256.find(file);
  if (hash == state.sha256.end()) hash = state.sha256.emplace(file, sha256_of(plugin.file)).first;
  return {slot, name, plugin.record.version, file, hash->second, plugin.record.build};
}

PluginIdentity PluginRegistry::identity(const std::string& slot, const std::string& name) const {
  const PluginFile* file = find(slot, name);
  return {slot, name, file ? file->file.string() : std::string()};
}

}  // namespace aco
