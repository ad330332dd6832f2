#pragma once
// Whether a host may load a plugin library: its records (aco/plugin_record.hpp) read from the file
// without loading it, and what in them this build refuses.
#include <filesystem>
#include <string>
#include <vector>

#include "aco/plugin_record.hpp"

namespace aco {

// The records in a library file, read from its section headers without loading it. Empty if the
// file has no ".aco_plugins" section (a plugin built for ABI 7 or earlier); Error if the file is
// not a readable ELF shared object for this machine or its records are malformed.
std::vector<PluginRecord> read_plugin_records(const std::filesystem::path& file);

// Why a host of this build must not load the plugin of `record`; empty if it may.
std::string incompatibility(const PluginRecord& record);

}  // namespace aco
