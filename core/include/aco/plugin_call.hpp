#pragma once
// Which plugin call a thread is in, and how messages name a plugin, a hook and an iteration.
// In the core library because what a plugin calls back (Context::record(), add()) needs to know
// which plugin called; the boundary itself, a decorator per slot, is the engine's
// (aco/engine/plugin_guard.hpp).
#include <cstddef>
#include <string>

namespace aco {

// Which plugin a guarded call went to.
struct PluginIdentity {
  std::string slot;
  std::string name;
  std::string file;
};

// A guarded call: the plugin, its hook and the iteration (< 0: none to name).
struct PluginCall {
  const PluginIdentity* who = nullptr;
  const char* hook = nullptr;
  int iteration = -1;
};

// The innermost guarded call the calling thread is in (who null: none), for what a plugin calls
// back (Context::record()) to know which plugin called.
PluginCall current_plugin_call() noexcept;

// Marks the calling thread as inside `who`'s `hook` while it lives (iteration < 0: none to
// name), so a crash report can say where the thread was. The guard opens one around every call.
class PluginCallScope {
 public:
  PluginCallScope(const PluginIdentity& who, const char* hook, int iteration) noexcept;
  ~PluginCallScope();
  PluginCallScope(const PluginCallScope&) = delete;
  PluginCallScope& operator=(const PluginCallScope&) = delete;

 private:
  const PluginIdentity* who_;
  const char* hook_;
  int iteration_;
};

// Where the calling thread is: "plugin update/crash (FILE) in update() in iteration 3 (0-based,
// as Context::iteration)", or "" outside every plugin. Async-signal-safe (a crash handler calls it): writes at most
// size - 1 characters and a NUL into `out` and returns how many.
std::size_t describe_plugin_call(char* out, std::size_t size) noexcept;

// What the exception being handled says: what() of a std::exception, else its type ("int").
// Call inside a catch block only.
std::string describe_current_exception();

// "update() in iteration 3 (0-based, as Context::iteration)": a hook and the iteration it ran in
// (iteration < 0: the hook alone), as every message numbers iterations.
std::string describe_hook(const char* hook, int iteration);

// "plugin update/max_min (FILE)" (the file left out when unknown).
std::string describe(const PluginIdentity& who);

// Throws the Error for the exception being handled, thrown by `who` in `hook` (iteration < 0:
// none to name), with that exception nested (std::rethrow_if_nested); a PluginFault, which names
// the plugin already, passes unchanged. Call inside a catch block only.
[[noreturn]] void rethrow_from_plugin(const PluginIdentity& who, const char* hook, int iteration = -1);

}  // namespace aco
