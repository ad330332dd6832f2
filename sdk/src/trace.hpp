#pragma once
// What a plugin produced in one run of the conformance checks, and the comparisons of two runs
// (deterministic, threads, reused). Internal to the checks.
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace aco::conformance {

// A value as the checks' messages write it: "%.15g".
std::string number(double value);

// Everything a plugin produced in one run of the checks, in order, and what was wrong with it.
struct Trace {
  std::vector<double> values;
  std::vector<std::pair<std::size_t, std::string>> sections;  // where each labelled part starts
  std::vector<std::string> problems;
  std::string section;  // the label of the part being recorded, for messages

  void begin(const std::string& label);
  void add(std::span<const double> v) { values.insert(values.end(), v.begin(), v.end()); }
  void add(double v) { values.push_back(v); }
  void problem(const std::string& what) { problems.push_back(section + ": " + what); }
  // Records the values, labelled for messages, and notes the first bad one (bad_value()).
  void add_checked(std::span<const double> v, const std::string& what, double minimum = 0.0, bool strict = false);
  // "open: tau after start(): value 12", for the value at `index`.
  std::string describe(std::size_t index) const;
};

bool same_bits(std::span<const double> a, std::span<const double> b);

// "" if the traces hold the same values bit for bit, else where they first differ.
std::string difference(const Trace& a, const Trace& b);

}  // namespace aco::conformance
