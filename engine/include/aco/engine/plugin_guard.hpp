#pragma once
// The error boundary between the host and a plugin. Whatever a plugin throws, from its factory or
// from any hook, on any thread (a std::exception or not: `throw 42`), leaves it as an aco::Error
// that names the slot, the plugin, its file, the hook and the iteration, so a host reports it and
// exits 1 (or acobench records the trial as failed) instead of std::terminate.
#include <memory>
#include <string>

#include "aco/map_reader.hpp"
#include "aco/plugin_call.hpp"
#include "aco/slots.hpp"
#include "aco/strategies.hpp"

namespace aco {

// "plugin update/max_min (FILE)" for a plugin made by the registry (behind the guard); "the
// update plugin" (the slot given) for an object made otherwise, such as a test's own strategy.
std::string describe_plugin(const Strategy& plugin, const char* slot);

// `plugin` behind a decorator of its interface that calls it inside the boundary: one per slot.
// (A map reader's Map is not behind it: its methods run in the graph's hot loops.)
#define ACO_DECLARE_GUARD_(NAME, INTERFACE) \
  std::unique_ptr<INTERFACE> guard(std::unique_ptr<INTERFACE> plugin, PluginIdentity who);
ACO_SLOTS(ACO_DECLARE_GUARD_)
#undef ACO_DECLARE_GUARD_

}  // namespace aco
