#include "aco/parameters.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include "aco/error.hpp"

namespace aco {
namespace {

bool parse_real(const std::string& text, double& value) {
  if (text == "inf" || text == "+inf") return value = INFINITY, true;
  if (text == "-inf") return value = -INFINITY, true;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

bool parse_integer(const std::string& text, std::int64_t& value) {
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> parts;
  std::istringstream s(text);
  for (std::string part; std::getline(s, part, sep);) parts.push_back(part);
  return parts;
}

std::string format_number(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  std::ostringstream s;
  s.precision(12);
  s << v;
  // Readable for the usual values, exact for the rest: the text must read back as v.
  double back = 0.0;
  const std::string text = s.str();
  if (parse_real(text, back) && back == v) return text;
  char exact[64];
  return std::string(exact, std::to_chars(exact, exact + sizeof exact, v).ptr);
}

std::string describe_range(const NumericRange& r) {
  return std::string(r.low_open ? "(" : "[") + format_number(r.low) + ", " + format_number(r.high) +
         (r.high_open ? ")" : "]");
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

const char* to_string(ParamType type) {
  switch (type) {
    case ParamType::integer:
      return "int";
    case ParamType::real:
      return "real";
    case ParamType::boolean:
      return "bool";
    case ParamType::categorical:
      return "categorical";
    case ParamType::text:
      return "text";
  }
  return "?";
}

std::string shown_default(const ParamSpec& spec) {
  return spec.type == ParamType::text && *spec.default_value == '\0' ? "\"\"" : spec.default_value;
}

KeyError::~KeyError() = default;

std::string to_string(const ParamValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>)
          return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, double>)
          return format_number(v);
        else if constexpr (std::is_same_v<T, std::string>)
          return v;
        else
          return std::to_string(v);
      },
      value);
}

const ParamValue& ParameterValues::at(const std::string& name) const {
  const auto it = values_.find(name);
  // A plugin asking for a parameter it did not declare is a bug in the plugin, not user input.
  if (it == values_.end()) throw Error("parameter '" + name + "' was not declared in the plugin's table");
  return it->second;
}

template <class T>
static const T& typed(const ParamValue& v, const std::string& name, const char* type) {
  if (const T* p = std::get_if<T>(&v)) return *p;
  throw Error("parameter '" + name + "' is not of type " + type);
}

std::int64_t ParameterValues::integer(const std::string& name) const {
  return typed<std::int64_t>(at(name), name, "int");
}
double ParameterValues::real(const std::string& name) const { return typed<double>(at(name), name, "real"); }
bool ParameterValues::boolean(const std::string& name) const { return typed<bool>(at(name), name, "bool"); }
const std::string& ParameterValues::text(const std::string& name) const {
  return typed<std::string>(at(name), name, "categorical or text");
}

std::optional<NumericRange> numeric_range(const ParamSpec& spec) {
  if (spec.type != ParamType::integer && spec.type != ParamType::real) return std::nullopt;
  std::string text = spec.range ? spec.range : "";
  NumericRange r;
  r.low = -INFINITY;
  r.high = INFINITY;
  if (text.empty()) return r;
  if (text.front() == '(' || text.front() == '[') {
    r.low_open = text.front() == '(';
    text.erase(0, 1);
  }
  if (!text.empty() && (text.back() == ')' || text.back() == ']')) {
    r.high_open = text.back() == ')';
    text.pop_back();
  }
  const auto parts = split(text, ':');
  double step = 0;
  const bool ok = (parts.size() == 2 || parts.size() == 3) && parse_real(parts.front(), r.low) &&
                  parse_real(parts.back(), r.high) && (parts.size() == 2 || parse_real(parts[1], step)) &&
                  r.low <= r.high;
  if (!ok) throw Error(std::string("parameter '") + spec.name + "': malformed range '" + spec.range + "'");
  if (parts.size() == 3) r.step = step;
  return r;
}

std::vector<std::string> choices(const ParamSpec& spec) {
  if (spec.type != ParamType::categorical) return {};
  return split(spec.range ? spec.range : "", ',');
}

ParamValue parse_value(const ParamSpec& spec, const std::string& text, const std::string& key) {
  const std::string quoted = "'" + text + "'";
  switch (spec.type) {
    case ParamType::boolean: {
      static const std::set<std::string> yes{"true", "1", "yes", "on"}, no{"false", "0", "no", "off"};
      if (yes.count(text)) return true;
      if (no.count(text)) return false;
      throw Error(key + ": " + quoted + " is not a boolean (use true or false)");
    }
    case ParamType::text:
      return text;
    case ParamType::categorical: {
      const auto options = choices(spec);
      if (std::find(options.begin(), options.end(), text) != options.end()) return text;
      throw Error(key + ": " + quoted + " is not one of " + spec.range);
    }
    case ParamType::integer:
    case ParamType::real: {
      double number = 0;
      ParamValue value;
      if (spec.type == ParamType::integer) {
        std::int64_t i = 0;
        if (!parse_integer(text, i)) throw Error(key + ": " + quoted + " is not a whole number");
        number = static_cast<double>(i);
        value = i;
      } else {
        if (!parse_real(text, number)) {
          double ignored = 0.0;
          const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), ignored);
          if (ec == std::errc::result_out_of_range && end == text.data() + text.size())
            throw Error(key + ": " + text + " is beyond what a double holds (above 1.8e308, or a nonzero value " +
                        "below 4.9e-324 in size)");
          throw Error(key + ": " + quoted + " is not a finite number");
        }
        // Read, but with its precision lost: a plugin's arithmetic on it overflows ("wrote inf"),
        // and printing it back failed ("stod").
        if (std::fpclassify(number) == FP_SUBNORMAL)
          throw Error(key + ": " + text + " is too close to 0 to compute with (a subnormal number); give 0 or a " +
                      "value of at least " + format_number(std::numeric_limits<double>::min()) + " in size");
        value = number;
      }
      const NumericRange r = *numeric_range(spec);
      const bool below = r.low_open ? number <= r.low : number < r.low;
      const bool above = r.high_open ? number >= r.high : number > r.high;
      if (below || above) throw Error(key + ": " + text + " is outside the range " + describe_range(r));
      return value;
    }
  }
  throw Error(key + ": unknown parameter type");
}

void check_table(std::span<const ParamSpec> table, const std::string& owner) {
  std::set<std::string> names;
  for (const ParamSpec& spec : table) {
    if (spec.name == nullptr || *spec.name == '\0') throw Error(owner + ": a parameter has no name");
    if (!names.insert(spec.name).second) throw Error(owner + ": parameter '" + spec.name + "' is declared twice");
    if (spec.default_value == nullptr || spec.help == nullptr)
      throw Error(owner + ": parameter '" + spec.name + "' lacks a default or a help text");
    if (spec.type == ParamType::categorical && choices(spec).empty())
      throw Error(owner + ": categorical parameter '" + spec.name + "' lists no values");
    try {
      parse_value(spec, spec.default_value, spec.name);
    } catch (const Error& e) {
      throw Error(owner + ": bad default: " + e.what());
    }
  }
}

KeySpelling KeySpelling::keyword() {
  KeySpelling spelling;
  spelling.keyword_ = true;
  return spelling;
}

std::string KeySpelling::operator()(const std::string& key) const {
  std::string written = prefix_ + key;
  if (keyword_)
    std::replace_if(
        written.begin(), written.end(), [](char c) { return c == '.' || c == '-'; }, '_');
  return written;
}

std::string KeySpelling::to_give(const std::string& key, const std::string& value) const {
  if (keyword_) return (*this)(key) + "=" + value;
  if (value.empty()) return (*this)(key);
  return (*this)(key) + (prefix_.starts_with("--") ? " " : ": ") + value;
}

std::string KeySpelling::plugin_list() const { return keyword_ ? "aco.plugins()" : "--list-plugins"; }

KeySpelling KeySpelling::within(const std::string& scope) const {
  KeySpelling inner = *this;
  inner.prefix_ += scope;
  return inner;
}

ParameterValues resolve(std::span<const ParamSpec> table, const std::map<std::string, std::string>& given,
                        const KeySpelling& spelling) {
  ParameterValues values;
  std::vector<std::string> names;
  for (const ParamSpec& spec : table) {
    names.push_back(spec.name);
    const auto it = given.find(spec.name);
    try {
      values.set(spec.name,
                 parse_value(spec, it == given.end() ? spec.default_value : it->second, spelling(spec.name)));
    } catch (const KeyError&) {
      throw;
    } catch (const Error& e) {
      throw KeyError(spelling(spec.name), e.what());
    }
  }
  for (const auto& [name, text] : given) {
    if (values.contains(name)) continue;
    std::string message = "unknown parameter '" + spelling(name) + "'";
    if (const std::string near = nearest(name, names); !near.empty())
      message += "; did you mean '" + spelling(near) + "'?";
    else if (names.empty())
      message += " (this plugin has no parameters)";
    else {
      message += " (valid: ";
      for (std::size_t i = 0; i < names.size(); ++i) message += (i ? ", " : "") + spelling(names[i]);
      message += ")";
    }
    throw KeyError(spelling(name), message);
  }
  return values;
}

std::string nearest(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::string::npos;
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) best_distance = d, best = c;
  }
  // Close means at most a third of the word differs; a prefix also counts (--update.rh).
  const bool prefix = !best.empty() && (best.rfind(word, 0) == 0 || word.rfind(best, 0) == 0);
  return best_distance <= std::max<std::size_t>(2, word.size() / 3) || prefix ? best : "";
}

}  // namespace aco
