#pragma once
// The error boundary between the host and a plugin. Whatever a plugin throws, from its factory or
// from any hook, on any thread (a std::exception or not: `throw 42`), leaves it as an aco::Error
// that names the slot, the plugin, its file, the hook and the iteration, so a host reports it and
// exits 1 (or acobench records the trial as failed) instead of std::terminate.
#include <cstddef>
#include <memory>
#include <string>

#include "aco/error.hpp"
#include "aco/map_reader.hpp"
#include "aco/slots.hpp"
#include "aco/strategies.hpp"

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

// "plugin update/max_min (FILE)" for a plugin made by the registry (behind the guard); "the
// update plugin" (the slot given) for an object made otherwise, such as a test's own strategy.
std::string describe_plugin(const Strategy& plugin, const char* slot);

// Throws the Error for the exception being handled, thrown by `who` in `hook` (iteration < 0:
// none to name); a PluginFault, which names the plugin already, passes unchanged. Call inside a
// catch block only.
[[noreturn]] void rethrow_from_plugin(const PluginIdentity& who, const char* hook, int iteration = -1);

// `plugin` behind a decorator of its interface that calls it inside the boundary: one per slot.
// (A map reader's Map is not behind it: its methods run in the graph's hot loops.)
#define ACO_DECLARE_GUARD_(NAME, INTERFACE) \
  std::unique_ptr<INTERFACE> guard(std::unique_ptr<INTERFACE> plugin, PluginIdentity who);
ACO_SLOTS(ACO_DECLARE_GUARD_)
#undef ACO_DECLARE_GUARD_

}  // namespace aco
