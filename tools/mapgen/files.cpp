// Writing aco_mapgen's output files: see files.hpp.
#include "files.hpp"

#include <fstream>

#include "aco/error.hpp"

namespace mapgen {

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw aco::Error(file.string() + ": cannot open for writing");
  out << text;
  if (!out.flush()) throw aco::Error(file.string() + ": write failed");
}

}  // namespace mapgen
