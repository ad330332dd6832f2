#pragma once
// Every file a user names (maps, scenarios, experiments, config files) is checked before it is
// read: a directory is not an input, and a device or a pipe (/dev/zero) may never end. Without
// the check, a directory reads as an empty config file (a run with defaults, silently) or as a
// stream error from the parser's library.
#include <boost/config.hpp>
#include <filesystem>
#include <string>

namespace aco {

// Throws Error naming `file` unless it is an existing regular file (or a link to one). `kind`
// ("config", "scenario", ...) names what the file should be in the message.
BOOST_SYMBOL_VISIBLE void check_input_file(const std::filesystem::path& file, const std::string& kind = "");

}  // namespace aco
