#include "trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "aco/sdk/conformance.hpp"

namespace aco::conformance {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", value);
  return text;
}

std::string bad_value(std::span<const double> values, const std::string& what, double minimum, bool strict) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!std::isfinite(v) || v < minimum || (strict && v == minimum))
      return what + "[" + std::to_string(i) + "] = " + number(v) + " (must be finite and " + (strict ? "> " : ">= ") +
             number(minimum) + ")";
  }
  return "";
}

void Trace::begin(const std::string& label) {
  section = label;
  sections.emplace_back(values.size(), label);
}

void Trace::add_checked(std::span<const double> v, const std::string& what, double minimum, bool strict) {
  if (const auto bad = bad_value(v, what, minimum, strict); !bad.empty()) problem(bad);
  sections.emplace_back(values.size(), section + ": " + what);
  add(v);
}

std::string Trace::describe(std::size_t index) const {
  std::string label = "value " + std::to_string(index);
  for (const auto& [start, name] : sections)
    if (start <= index) label = name + ": value " + std::to_string(index - start);
  return label;
}

bool same_bits(std::span<const double> a, std::span<const double> b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

std::string difference(const Trace& a, const Trace& b) {
  const std::size_t n = std::min(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < n; ++i)
    if (!same_bits(std::span(a.values).subspan(i, 1), std::span(b.values).subspan(i, 1)))
      return a.describe(i) + " is " + number(a.values[i]) + " in one run and " + number(b.values[i]) + " in the other";
  if (a.values.size() != b.values.size())
    return "one run produced " + std::to_string(a.values.size()) + " values, the other " +
           std::to_string(b.values.size());
  return "";
}

}  // namespace aco::conformance
