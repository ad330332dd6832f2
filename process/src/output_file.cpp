#include "aco/process/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "aco/error.hpp"

namespace aco {
namespace fs = std::filesystem;

namespace {

void write_in_place(const fs::path& file, std::string_view text, const std::string& failure) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw Error(failure + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw Error(failure + std::strerror(errno));
}

}  // namespace

void write_output_file(const fs::path& file, std::string_view text, const std::string& kind) {
  const std::string failure = file.string() + ": cannot write the " + (kind.empty() ? "" : kind + " ") + "file: ";
  std::error_code error;
  const auto status = fs::status(file, error);
  if (fs::is_directory(status)) throw Error(failure + "it is a folder");
  if (fs::exists(status) && !fs::is_regular_file(status)) return write_in_place(file, text, failure);
  // A link is followed: the file it names is replaced, the link stays.
  fs::path target = file;
  if (fs::is_symlink(fs::symlink_status(file, error)))
    if (auto resolved = fs::canonical(file, error); !error) target = std::move(resolved);
  if (target.has_parent_path() && !fs::is_directory(target.parent_path(), error)) {
    fs::create_directories(target.parent_path(), error);
    if (error)
      throw Error(failure + "cannot make its folder " + target.parent_path().string() + ": " + error.message());
  }
  fs::path partial = target;
  partial += ".partial-" + std::to_string(::getpid());
  try {
    write_in_place(partial, text, failure);
  } catch (...) {
    fs::remove(partial, error);
    throw;
  }
  fs::rename(partial, target, error);
  if (error) {
    const std::string reason = error.message();
    fs::remove(partial, error);
    throw Error(failure + reason);
  }
}

}  // namespace aco
