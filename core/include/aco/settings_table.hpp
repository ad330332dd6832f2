#pragma once
// A settings struct declared once: each field's key, range and help next to the member it fills.
// The parameter table (help texts, checking, irace), the reader and the writer all come from
// it, and the defaults are the struct's own member initialisers.
//
//   const SettingsTable<ColonySettings> table({
//       field("ants", &ColonySettings::ants, "1:1000000", "ants per iteration"),
//       choice("search", &ColonySettings::bidirectional, {"single", "bidirectional"}, "..."),
//   });
//   ColonySettings s = table.read(values);
//
// field() takes a std::string member as categorical (its range lists the values); text_field()
// takes one as free text.
//
// A plugin declares its parameters the same way (a struct, its table, ACO_PLUGIN(..., kParams));
// a group of fields shared by several owners (the potential field's gains) joins a table
// through nested().
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "aco/error.hpp"
#include "aco/parameters.hpp"

namespace aco {

template <class Settings>
struct SettingsField {
  const char* name;
  ParamType type;
  std::string range;
  const char* help;
  std::function<ParamValue(const Settings&)> get;
  std::function<void(Settings&, const ParamValue&)> set;
};

// A whole number, a real, a boolean or (std::string member) one of the values listed in `range`.
template <class Settings, class Member>
SettingsField<Settings> field(const char* name, Member Settings::*member, const char* range, const char* help) {
  SettingsField<Settings> f{name, ParamType::real, range, help, {}, {}};
  if constexpr (std::is_same_v<Member, bool>) {
    f.type = ParamType::boolean;
    f.get = [member](const Settings& s) { return ParamValue(s.*member); };
    f.set = [member](Settings& s, const ParamValue& v) { s.*member = std::get<bool>(v); };
  } else if constexpr (std::is_same_v<Member, std::string>) {
    f.type = ParamType::categorical;
    f.get = [member](const Settings& s) { return ParamValue(s.*member); };
    f.set = [member](Settings& s, const ParamValue& v) { s.*member = std::get<std::string>(v); };
  } else if constexpr (std::is_integral_v<Member>) {
    f.type = ParamType::integer;
    f.get = [member](const Settings& s) { return ParamValue(static_cast<std::int64_t>(s.*member)); };
    f.set = [member](Settings& s, const ParamValue& v) { s.*member = static_cast<Member>(std::get<std::int64_t>(v)); };
  } else {
    static_assert(std::is_floating_point_v<Member>, "a settings field is a number, a boolean or a string");
    f.get = [member](const Settings& s) { return ParamValue(static_cast<double>(s.*member)); };
    f.set = [member](Settings& s, const ParamValue& v) { s.*member = static_cast<Member>(std::get<double>(v)); };
  }
  return f;
}

// Any text: a Python class, a file name. No range to check; irace does not tune it.
template <class Settings>
SettingsField<Settings> text_field(const char* name, std::string Settings::*member, const char* help) {
  SettingsField<Settings> f{name, ParamType::text, "", help, {}, {}};
  f.get = [member](const Settings& s) { return ParamValue(s.*member); };
  f.set = [member](Settings& s, const ParamValue& v) { s.*member = std::get<std::string>(v); };
  return f;
}

// A categorical key over a member of another type: `names[i]` stands for `values[i]`
// ({"single", "bidirectional"} for false, true; {"4", "8", "16"} for an enum).
template <class Settings, class Member>
SettingsField<Settings> choice(const char* name, Member Settings::*member, std::vector<std::string> names,
                               std::vector<Member> values, const char* help) {
  std::string range;
  for (const auto& n : names) range += (range.empty() ? "" : ",") + n;
  SettingsField<Settings> f{name, ParamType::categorical, range, help, {}, {}};
  f.get = [member, names, values](const Settings& s) {
    for (std::size_t i = 0; i < values.size(); ++i)
      if (values[i] == s.*member) return ParamValue(names[i]);
    throw Error("setting has a value that has no name");
  };
  f.set = [name, member, names, values, range](Settings& s, const ParamValue& v) {
    const std::string& given = std::get<std::string>(v);
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == given) {
        s.*member = values[i];
        return;
      }
    // resolve() checks a key's value against its range; a caller that skips it must not get the old value silently.
    throw Error(std::string(name) + ": '" + given + "' is not one of " + range);
  };
  return f;
}

// The fields of a group (a struct of its own, with its own table) as fields of the struct that
// holds the group in `member`.
template <class Settings, class Group>
std::vector<SettingsField<Settings>> nested(Group Settings::*member, const std::vector<SettingsField<Group>>& group) {
  std::vector<SettingsField<Settings>> fields;
  for (const auto& f : group) {
    fields.push_back({f.name, f.type, f.range, f.help,
                      [member, get = f.get](const Settings& s) { return get(s.*member); },
                      [member, set = f.set](Settings& s, const ParamValue& v) { set(s.*member, v); }});
  }
  return fields;
}

template <class Settings>
class SettingsTable {
 public:
  // The owner's own fields, then those of a shared group (see nested()).
  explicit SettingsTable(std::vector<SettingsField<Settings>> fields, std::vector<SettingsField<Settings>> group = {})
      : fields_(std::move(fields)) {
    fields_.insert(fields_.end(), group.begin(), group.end());
    const Settings defaults{};
    defaults_.reserve(fields_.size());
    for (const auto& f : fields_) defaults_.push_back(to_string(f.get(defaults)));
    for (std::size_t i = 0; i < fields_.size(); ++i)
      specs_.push_back(
          {fields_[i].name, fields_[i].type, defaults_[i].c_str(), fields_[i].range.c_str(), fields_[i].help});
  }
  SettingsTable(const SettingsTable&) = delete;  // specs_ points into defaults_ and fields_

  std::span<const ParamSpec> parameters() const { return specs_; }
  const std::vector<SettingsField<Settings>>& fields() const { return fields_; }

  // `values` must hold every key of the table (as resolve() gives them).
  Settings read(const ParameterValues& values) const {
    Settings s{};
    for (const auto& f : fields_) f.set(s, values.all().at(f.name));
    return s;
  }
  ParameterValues write(const Settings& s) const {
    ParameterValues values;
    for (const auto& f : fields_) values.set(f.name, f.get(s));
    return values;
  }

 private:
  std::vector<SettingsField<Settings>> fields_;
  std::vector<std::string> defaults_;
  std::vector<ParamSpec> specs_;
};

}  // namespace aco
