#include "aco/value_parsers.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

#include "aco/error.hpp"

namespace aco {

std::uint64_t parse_memory_size(const std::string& text, const std::string& option) {
  const auto fail = [&](const std::string& why) -> std::uint64_t {
    throw Error(option + ": '" + text + "' " + why +
                " (expected bytes or a whole number with K, M, G or T, e.g. 512M, 4G)");
  };
  std::uint64_t number = 0;
  const char* end = text.data() + text.size();
  const auto [rest, error] = std::from_chars(text.data(), end, number);
  if (rest == text.data()) return fail("is not a size");
  if (error == std::errc::result_out_of_range) return fail("is too large");
  std::string unit(rest, end);
  for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  int shift = 0;
  if (!unit.empty()) {
    const std::string units = "KMGT";
    const auto k = units.find(unit[0]);
    if (k == std::string::npos || !(unit.size() == 1 || unit.substr(1) == "B" || unit.substr(1) == "IB"))
      return fail("has an unknown unit");
    shift = 10 * static_cast<int>(k + 1);
  }
  if (number == 0) return fail("is not a positive size");
  if (number > (std::numeric_limits<std::uint64_t>::max() >> shift)) return fail("is too large");
  return number << shift;
}

double parse_seconds(const std::string& text, const std::string& option) {
  double seconds = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, seconds);
  if (error != std::errc() || stop != end || !(seconds > 0) || !std::isfinite(seconds))
    throw Error(option + ": '" + text + "' is not a time in seconds (a positive number, such as 30 or 0.5)");
  return seconds;
}

}  // namespace aco
