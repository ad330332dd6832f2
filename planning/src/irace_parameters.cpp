#include "aco/planning/irace_parameters.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "aco/engine/colony.hpp"
#include "aco/error.hpp"
#include "aco/parameters.hpp"
#include "aco/engine/pipeline.hpp"

namespace aco {
namespace {

// irace rounds real parameters to 4 decimal places (its default `digits`), so real bounds are
// put on that grid, inwards: every value irace can sample is then valid for acoplan.
constexpr double kRealUnit = 1e-4;
// Ranges such as 0:1e12 or 1:1000000 say "no real limit"; irace samples uniformly, so they are
// capped at this multiple of the default's magnitude (or at this value when the default is 0).
constexpr double kCapFactor = 100;

const char* const kHeader =
    "# irace parameters for acoplan, written by acoplan --dump-irace-params from the parameter tables.\n"
    "# name  switch  type  (domain)  [| condition]\n"
    "# Numeric ranges: an end beyond 100 x |default| (100 if the default is 0) is capped there; an open end\n"
    "# moves in by 1 (integers) or 0.0001 (reals, irace's default 4 digits); real bounds are rounded inwards\n"
    "# to 4 decimals. A parameter left with no interval is listed as skipped.\n";

// irace names are R identifiers: letters, digits and underscores (dots are refused by some versions).
std::string irace_name(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](unsigned char c) { return !std::isalnum(c); }, '_');
  return text;
}

// Fixed notation without trailing zeros: at most 4 decimals, never an exponent.
std::string number(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.4f", x);
  std::string text = buffer;
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text == "-0" ? "0" : text;
}

struct Domain {
  std::string type;  // i, r or c
  std::string values;  // "(low, high)" or "(a, b, c)"
  std::string skipped;  // why the parameter cannot be tuned, or ""
};

Domain numeric_domain(const aco::ParamSpec& spec) {
  const bool integer = spec.type == aco::ParamType::integer;
  const aco::NumericRange range = *aco::numeric_range(spec);
  const double magnitude = std::abs(std::stod(spec.default_value));
  const double cap = magnitude > 0 ? kCapFactor * magnitude : kCapFactor;
  double low = std::max(range.low, -cap), high = std::min(range.high, cap);
  const double unit = integer ? 1 : kRealUnit;
  if (range.low_open && low == range.low) low += unit;
  if (range.high_open && high == range.high) high -= unit;
  // The tolerance keeps a bound already on the grid (0.0001 is 1.0000000000000002 units) in place.
  low = std::ceil(low / unit - 1e-6) * unit;
  high = std::floor(high / unit + 1e-6) * unit;
  if (!(low < high))
    return {"", "",
            std::string("range ") + spec.range + " capped at 100 x default " + spec.default_value +
                " leaves no interval on irace's 4-decimal grid"};
  return {integer ? "i" : "r", std::string("(").append(number(low)).append(", ").append(number(high)).append(")"), ""};
}

Domain domain(const aco::ParamSpec& spec) {
  switch (spec.type) {
    case aco::ParamType::boolean:
      return {"c", "(true, false)", ""};
    case aco::ParamType::categorical: {
      std::string values;
      for (const auto& choice : aco::choices(spec)) values += (values.empty() ? "" : ", ") + choice;
      return {"c", "(" + values + ")", ""};
    }
    case aco::ParamType::integer:
    case aco::ParamType::real:
      return numeric_domain(spec);
    // irace samples numbers and choices; a text (a Python class, a file) is for the user to fix.
    case aco::ParamType::text:
      return {"", "", "free text is not tuned"};
  }
  return {"", "", "unknown parameter type"};
}

class ParameterFile {
 public:
  ParameterFile() { out_ << kHeader; }

  void comment(const std::string& text) { out_ << "# " << text << "\n"; }

  // `option` without its dashes, e.g. "update.rho". acoplan's booleans only take a value after
  // "=", so their switch ends with "=" (irace joins switch and value without a space).
  // Returns whether the parameter is tuned (false: written as skipped, with the reason).
  bool add(const std::string& name, const std::string& option, const aco::ParamSpec& spec,
           const std::string& condition = "") {
    const Domain d = domain(spec);
    if (!d.skipped.empty()) {
      comment("skipped --" + option + ": " + d.skipped);
      return false;
    }
    const std::string flag = "--" + option + (spec.type == aco::ParamType::boolean ? "=" : " ");
    line(name, flag, d.type + " " + d.values, condition);
    return true;
  }

  void line(const std::string& name, const std::string& flag, const std::string& domain, const std::string& condition) {
    if (!names_.insert(name).second)
      throw aco::Error("--dump-irace-params: two parameters would both be called '" + name +
                       "' in irace (the second is " + flag + ")");
    out_ << name << " \"" << flag << "\" " << domain << (condition.empty() ? "" : " | " + condition) << "\n";
  }

  std::string text() const { return out_.str(); }

 private:
  std::ostringstream out_;
  std::set<std::string> names_;
};

void add_slot(ParameterFile& file, aco::PluginRegistry& registry, const std::string& slot) {
  std::vector<std::pair<std::string, const aco::PluginDescriptor*>> plugins;
  for (const auto& name : registry.names(slot)) {
    try {
      const aco::PluginDescriptor& descriptor = registry.load(slot, name);
      // Such a plugin needs its text set (python needs its class): irace would run it without.
      const auto params = descriptor.parameters();
      const auto text =
          std::find_if(params.begin(), params.end(), [](const auto& p) { return p.type == aco::ParamType::text; });
      if (text != params.end()) {
        file.comment("skipped " + slot + "/" + name + ": its text parameter " + text->name +
                     " is not tuned (to tune the other slots around it, pass --" + slot + " " + name + " and its --" +
                     slot + "." + text->name + " in the target runner)");
        continue;
      }
      plugins.emplace_back(name, &descriptor);
    } catch (const aco::Error& e) {
      file.comment("skipped " + slot + "/" + name + ": " + e.what());
    }
  }
  if (plugins.empty()) return file.comment("no usable " + slot + " plugin found");
  std::string names;
  for (const auto& [name, descriptor] : plugins) names += (names.empty() ? "" : ", ") + name;
  file.line(slot, "--" + slot + " ", "c (" + names + ")", "");
  // A name declared by several plugins of the slot gets the plugin appended: the same name can
  // mean different things (and ranges) in two plugins.
  std::map<std::string, int> declared;
  for (const auto& [name, descriptor] : plugins)
    for (const auto& spec : descriptor->parameters()) ++declared[spec.name];
  for (const auto& [name, descriptor] : plugins)
    for (const auto& spec : descriptor->parameters()) {
      const std::string irace = slot + "_" + spec.name + (declared[spec.name] > 1 ? "_" + name : "");
      file.add(irace_name(irace), slot + "." + spec.name, spec, slot + " == \"" + name + "\"");
    }
}

}  // namespace

std::string irace_plugin_parameters(aco::PluginRegistry& registry, const std::string& plugin) {
  const auto slash = plugin.find('/');
  const std::string slot = plugin.substr(0, slash), name = slash == std::string::npos ? "" : plugin.substr(slash + 1);
  if (name.empty()) throw aco::Error("--irace-plugin: '" + plugin + "' is not SLOT/NAME (e.g. update/acs)");
  if (std::find(aco::kSlots.begin(), aco::kSlots.end(), slot) == aco::kSlots.end()) {
    std::string message = "--irace-plugin " + plugin + ": '" + slot + "' is not a slot (slots:";
    for (const char* known : aco::kSlots) message += std::string(" ") + known;
    throw aco::Error(message + ")");
  }
  const aco::PluginDescriptor& descriptor = registry.load(slot, name);
  ParameterFile file;
  file.comment(plugin +
               " only: its slot fixed to it; the colony and the other slots as the target runner's options set them");
  file.line(slot, "--" + slot + " ", "c (" + name + ")", "");
  std::size_t tuned = 0;
  for (const auto& spec : descriptor.parameters())
    tuned += file.add(irace_name(slot + "_" + spec.name), slot + "." + spec.name, spec);
  if (tuned == 0)
    throw aco::Error("--irace-plugin " + plugin +
                     ": no parameter irace can tune (a plugin needs a numeric, boolean or "
                     "categorical parameter; --describe " +
                     plugin + " lists them)");
  return file.text();
}

std::string irace_parameters(aco::PluginRegistry& registry, const std::vector<std::string>& slots) {
  ParameterFile file;
  // The seed is irace's (the target runner passes it); a null model is a question asked of a
  // pipeline, not a setting to tune; a time limit is a budget, like ants and iterations, which
  // irace would simply raise.
  file.comment("colony (seed is irace's: the target runner passes it)");
  for (const auto& spec : aco::colony_parameters())
    if (std::string_view(spec.name) != "seed" && std::string_view(spec.name) != "null-model" &&
        std::string_view(spec.name) != "time-limit")
      file.add(irace_name(spec.name), spec.name, spec);
  for (const auto& slot : slots) {
    file.comment(slot);
    add_slot(file, registry, slot);
  }
  return file.text();
}

}  // namespace aco
