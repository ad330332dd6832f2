#include "aco/engine/input_file.hpp"

#include "aco/error.hpp"

namespace aco {

void check_input_file(const std::filesystem::path& file, const std::string& kind) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (error || !std::filesystem::exists(status))
    throw Error(file.string() + ": cannot open " + (kind.empty() ? "file" : "the " + kind + " file"));
  if (std::filesystem::is_directory(status)) {
    const std::string article = !kind.empty() && std::string("aeiou").find(kind[0]) != std::string::npos ? "an " : "a ";
    throw Error(file.string() + ": is a directory, not " + article + (kind.empty() ? "" : kind + " ") + "file");
  }
  if (!std::filesystem::is_regular_file(status))
    throw Error(file.string() + ": not a regular file (a device, pipe or socket may never end): refused");
}

}  // namespace aco
