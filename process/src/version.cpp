#include "aco/process/version.hpp"

namespace aco {

#ifdef __clang__
#define ACO_COMPILER "clang " __clang_version__
#else
#define ACO_COMPILER "GCC " __VERSION__
#endif

std::string version() { return ACO_VERSION; }

std::string version_text(const std::string& program) {
  return program + " " + version() + " (commit " ACO_COMMIT ", " ACO_BUILD_TYPE " build, " ACO_COMPILER ")";
}

}  // namespace aco
