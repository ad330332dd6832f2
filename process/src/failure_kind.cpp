#include "aco/process/failure_kind.hpp"

#include <string>

#include "aco/error.hpp"

namespace aco {

FailureKind failure_kind(std::string_view text) {
  for (std::size_t i = 0; i < std::size(kFailureTexts); ++i)
    if (text == kFailureTexts[i]) return static_cast<FailureKind>(i);
  std::string known;
  for (const char* name : kFailureTexts)
    if (*name) known += (known.empty() ? "'" : ", '") + std::string(name) + "'";
  throw Error("unknown failure '" + std::string(text) + "' (known: " + known + ")");
}

}  // namespace aco
