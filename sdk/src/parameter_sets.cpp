// The parameter sets a plugin is checked with: its defaults, then each end of each range.
#include <algorithm>
#include <cmath>

#include "aco/sdk/conformance.hpp"
#include "trace.hpp"

namespace aco::conformance {

std::vector<ParameterSet> parameter_sets(std::span<const ParamSpec> table, std::int64_t integer_cap) {
  std::vector<ParameterSet> sets{{"defaults", {}, ""}};
  for (const ParamSpec& spec : table) {
    const std::string name = spec.name, default_value = spec.default_value;
    auto add = [&](const std::string& value, const std::string& note = "", const std::string& if_refused = "") {
      if (value != default_value) sets.push_back({name + "=" + value + note, {{name, value}}, if_refused});
    };
    if (spec.type == ParamType::boolean) {
      add(default_value == "true" ? "false" : "true", "", "a categorical with the one value it takes");
      continue;
    }
    if (spec.type == ParamType::categorical) {
      for (const auto& choice : choices(spec)) add(choice, "", "no choice '" + choice + "'");
      continue;
    }
    if (spec.type == ParamType::text) continue;  // no other value to try
    const auto range = numeric_range(spec);
    if (!range) continue;
    const bool integer = spec.type == ParamType::integer;
    const double span = range->high - range->low;
    for (const bool low_end : {true, false}) {
      double value = low_end ? range->low : range->high;
      if (!std::isfinite(value)) continue;  // no run at infinity
      if (!low_end && range->step) value = range->low + std::floor(span / *range->step) * *range->step;
      if (low_end ? range->low_open : range->high_open) {
        // Just inside an open end: a thousandth of its size (at least of 1) in, enough for a
        // resolution such as a sampling step not to turn into millions of samples.
        double inward = integer ? 1.0 : std::max(std::abs(value), 1.0) * 1e-3;
        if (std::isfinite(span)) inward = std::min(inward, span / 2);
        value += low_end ? inward : -inward;
      }
      // An end the plugin refuses should have been declared open.
      const std::string declared = spec.range;
      const bool closed = !(low_end ? range->low_open : range->high_open);
      const std::string open_end =
          closed ? "the range " + (low_end ? "(" + declared : declared + ")") : "a narrower range";
      if (!integer) {
        add(number(value), "", open_end);
      } else if (value > static_cast<double>(integer_cap)) {
        add(std::to_string(std::max<std::int64_t>(integer_cap, static_cast<std::int64_t>(std::ceil(range->low)))),
            " (range end " + number(value) + " capped)", "a narrower range");
      } else {
        add(std::to_string(static_cast<std::int64_t>(value)), "", open_end);
      }
    }
  }
  return sets;
}

}  // namespace aco::conformance
