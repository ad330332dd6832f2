#pragma once
// Parameter tables (OMPL style): every plugin, and the colony itself, declares its parameters
// as plain data; hosts turn them into command-line options and config-file keys.
#include <boost/config.hpp>

#include "aco/error.hpp"
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace aco {

// text: any string (a Python class, a file name); no range, and never tuned by irace.
enum class ParamType { integer, real, boolean, categorical, text };

// Range syntax: "low:high" or "low:step:high" (closed, "inf" allowed; a leading "(" or a
// trailing ")" makes that end open), or "a,b,c" for categorical values. Booleans and texts need none.
struct ParamSpec {
  const char* name;
  ParamType type;
  const char* default_value;
  const char* range;
  const char* help;
};

using ParamValue = std::variant<std::int64_t, double, bool, std::string>;

std::string to_string(const ParamValue& value);
const char* to_string(ParamType type);
// The default as help texts show it: "" for an empty text, which would otherwise show as nothing.
std::string shown_default(const ParamSpec& spec);

class BOOST_SYMBOL_VISIBLE ParameterValues {
 public:
  std::int64_t integer(const std::string& name) const;
  double real(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& text(const std::string& name) const;
  void set(const std::string& name, ParamValue value) { values_[name] = std::move(value); }
  bool contains(const std::string& name) const { return values_.count(name) != 0; }
  const std::map<std::string, ParamValue>& all() const { return values_; }

 private:
  const ParamValue& at(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
};

struct NumericRange {
  double low = 0.0;
  double high = 0.0;
  bool low_open = false;
  bool high_open = false;
  std::optional<double> step;
};

std::optional<NumericRange> numeric_range(const ParamSpec& spec);
std::vector<std::string> choices(const ParamSpec& spec);

// Parses one value and checks type and range. `key` names it in the message, e.g. "--update.rho".
ParamValue parse_value(const ParamSpec& spec, const std::string& text, const std::string& key);

// Throws if a table is malformed: duplicate names, bad range, default outside its range.
void check_table(std::span<const ParamSpec> table, const std::string& owner);

// An error about one key, which it names as the host writes it ("--update.rho", "update.rho").
class BOOST_SYMBOL_VISIBLE KeyError : public Error {
 public:
  KeyError(std::string key, const std::string& message) : Error(message), key_(std::move(key)) {}
  ~KeyError() override;
  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

// Defaults of a table overridden by the given texts. An unknown name is an error naming the
// nearest valid one; `key_prefix` ("--update.") is used in messages. Throws KeyError.
ParameterValues resolve(std::span<const ParamSpec> table, const std::map<std::string, std::string>& given,
                        const std::string& key_prefix);

// The candidate closest to `word` by edit distance, or "" if none is reasonably close.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace aco
