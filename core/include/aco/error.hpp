#pragma once
// One exception type for every user-facing failure: bad maps, bad options, bad plugins.
// Hosts print what() and exit non-zero; nothing in the framework aborts on bad input.
#include <boost/config.hpp>
#include <stdexcept>
#include <string>

namespace aco {

class BOOST_SYMBOL_VISIBLE Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~Error() override;
};

// A plugin's allocation failed (std::bad_alloc in a hook): acobench stores the trial as "out of
// memory" rather than as an error.
class BOOST_SYMBOL_VISIBLE OutOfMemoryError : public Error {
 public:
  using Error::Error;
  ~OutOfMemoryError() override;
};

// A fault the engine found in what a plugin did, its message naming the plugin, the hook and the
// iteration already (a figure recorded as NaN): the error boundary passes it on unchanged.
class BOOST_SYMBOL_VISIBLE PluginFault : public Error {
 public:
  using Error::Error;
  ~PluginFault() override;
};

}  // namespace aco
