#pragma once
// How the report's tables and figure titles write numbers: "-" for what is not finite.
#include <cmath>
#include <cstdio>
#include <string>

namespace aco::studies {

// `digits` significant digits.
inline std::string number(double v, int digits = 4) {
  if (!std::isfinite(v)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

// `decimals` digits after the point.
inline std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, v);
  return text;
}

}  // namespace aco::studies
