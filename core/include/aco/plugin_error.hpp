#pragma once
// What went wrong in a plugin, told apart from the host's own errors (aco::Error) so that acobench
// can count its failed trials by reason. Hosts that print what() need not care: both are Errors.
#include <boost/config.hpp>

#include "aco/error.hpp"

namespace aco {

// A plugin threw, from its factory or a hook (plugin_guard.hpp): the message names the plugin, its
// file, the hook and the iteration.
class BOOST_SYMBOL_VISIBLE PluginError : public Error {
 public:
  using Error::Error;
  ~PluginError() override;
};

// A value a plugin wrote or returned that the engine refuses (a non-finite or negative pheromone
// or heuristic, a waypoint on an obstacle, a command outside the dynamic window): the message
// names the plugin, the hook, the iteration and the value.
class BOOST_SYMBOL_VISIBLE InvalidValueError : public Error {
 public:
  using Error::Error;
  ~InvalidValueError() override;
};

}  // namespace aco
