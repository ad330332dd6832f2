// Writing aco_mapgen's output files.
#pragma once

#include <filesystem>
#include <string>

namespace mapgen {

// Writes `text` to `file` (replacing it); an Error naming the file if it cannot.
void write_file(const std::filesystem::path& file, const std::string& text);

}  // namespace mapgen
