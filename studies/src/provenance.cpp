#include "aco/studies/provenance.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

namespace aco::studies {
namespace {

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

// Where two canonical texts part, for telling the user what changed.
std::string first_difference(const std::string& stored, const std::string& now) {
  std::istringstream a(stored), b(now);
  std::string line_a, line_b;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a && !more_b) return "they differ only in line endings";
    if (!more_a || !more_b || line_a != line_b)
      return "first difference at line " + std::to_string(line) + ": stored " + (more_a ? in_quotes(line_a) : "(end)") +
             ", now " + (more_b ? in_quotes(line_b) : "(end)");
  }
}

std::string shortened(const std::string& text) { return text.size() > 300 ? text.substr(0, 300) + "..." : text; }

}  // namespace

// acobench's fingerprints are JSON objects (Experiment::fingerprint); of any other text, the first
// differing line is told.
std::string fingerprint_change(const std::string& stored, const std::string& now) {
  const auto a = nlohmann::json::parse(stored, nullptr, false), b = nlohmann::json::parse(now, nullptr, false);
  if (!a.is_object() || !b.is_object())
    return "the experiment file changed since (" + first_difference(stored, now) + ")";
  if (b.contains("plugins") && !a.contains("plugins"))
    return "its trials were stored by an acobench that did not record which plugin binaries ran them, so "
           "resuming could mix the trials of two builds (the database can still be reported)";
  if (a.value("plugins", nlohmann::json::object()) != b.value("plugins", nlohmann::json::object())) {
    const auto pa = a.at("plugins"), pb = b.at("plugins");
    for (const auto& [plugin, then] : pa.items())
      if (pb.contains(plugin) && pb.at(plugin) != then)
        return "another binary of plugin " + plugin + " (stored: version " + then.value("version", "?") + ", sha256 " +
               then.value("sha256", "?") + "; now: version " + pb.at(plugin).value("version", "?") + ", sha256 " +
               pb.at(plugin).value("sha256", "?") + ", " + pb.at(plugin).value("file", "?") +
               "): resuming would mix the trials of two binaries; run the stored binary again";
  }
  for (const auto& [key, then] : a.items())
    if (!b.contains(key) || b.at(key) != then)
      return "the experiment file changed since (" + key + ": stored " + shortened(then.dump()) + ", now " +
             (b.contains(key) ? shortened(b.at(key).dump()) : "(missing)") + ")";
  for (const auto& [key, value] : b.items())
    if (!a.contains(key))
      return "the experiment file changed since (" + key + ": new, " + shortened(value.dump()) + ")";
  return "the experiment file changed since (" + first_difference(stored, now) + ")";
}

}  // namespace aco::studies
