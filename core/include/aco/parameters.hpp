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

// How a host writes a key in its messages, so an error names it as its user typed it: acoplan's
// options ("--update.rho"), YAML's keys ("update.rho") or Python's keywords ("update_rho").
class BOOST_SYMBOL_VISIBLE KeySpelling {
 public:
  // A key as written, after a literal prefix: "" for YAML, "--" for options, "--update." within a
  // slot. Implicit, so a prefix text reads as its spelling.
  KeySpelling(std::string prefix = "") : prefix_(std::move(prefix)) {}  // NOLINT(google-explicit-constructor)
  KeySpelling(const char* prefix) : prefix_(prefix) {}  // NOLINT(google-explicit-constructor)
  // Python's keyword arguments: dots and dashes as underscores.
  static KeySpelling keyword();

  // The key as the user writes it: "--update.rho", "update_rho".
  std::string operator()(const std::string& key) const;
  // The key as the user gives it a value, in "change it with ...": "--max-memory", "max_memory=";
  // with a `value`: "--map-format NAME", "map_format=NAME", YAML's "map-format: NAME".
  std::string to_give(const std::string& key, const std::string& value = "") const;
  // The spelling of the keys of one table, e.g. a slot's: within("update.")("rho") is "--update.rho".
  KeySpelling within(const std::string& scope) const;
  // How this host's user lists the plugins: "--list-plugins", Python's "aco.plugins()".
  std::string plugin_list() const;

 private:
  std::string prefix_;
  bool keyword_ = false;
};

// Defaults of a table overridden by the given texts. An unknown name is an error naming the
// nearest valid one; `spelling` writes the keys in messages ("--update." for acoplan's options of
// the update slot). Throws KeyError.
ParameterValues resolve(std::span<const ParamSpec> table, const std::map<std::string, std::string>& given,
                        const KeySpelling& spelling);

// The candidate closest to `word` by edit distance, or "" if none is reasonably close.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace aco
