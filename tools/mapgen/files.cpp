// Writing aco_mapgen's output files: see files.hpp.
#include "files.hpp"

#include "aco/process/output_file.hpp"

namespace mapgen {

void write_file(const std::filesystem::path& file, const std::string& text) {
  aco::write_output_file(file, text);  // whole or not at all: a failed write leaves no partial file
}

}  // namespace mapgen
