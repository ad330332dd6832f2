#include "aco/figures.hpp"

#include <tbb/enumerable_thread_specific.h>

#include <cmath>
#include <mutex>
#include <vector>

#include "aco/error.hpp"
#include "aco/plugin_call.hpp"
#include "aco/strategies.hpp"

namespace aco {
namespace {

constexpr std::size_t kMaxFigureName = 64;

// "deadlock/backtrack." (the key's prefix), or "plugin." for a strategy the registry did not make.
std::string key_prefix(const PluginIdentity* plugin) {
  return plugin ? plugin->slot + "/" + plugin->name + "." : std::string("plugin.");
}

// "plugin update/x (FILE)", or "a strategy" outside the registry's plugins.
std::string recorder(const PluginCall& call) { return call.who ? describe(*call.who) : "a strategy"; }

// " in update() in iteration 3 (0-based, as Context::iteration)", or "" outside a guarded call.
std::string where(const PluginCall& call) { return call.hook ? " in " + describe_hook(call.hook, call.iteration) : ""; }

[[noreturn]] void reject(const PluginCall& call, const std::string& what, const std::string& rule) {
  throw PluginFault(recorder(call) + " " + what + where(call) + "; " + rule);
}

void check_name(const PluginCall& call, std::string_view name, const char* function) {
  if (const std::string problem = figure_name_problem(name); !problem.empty())
    reject(call, std::string("called Context::") + function + "() with the figure name '" + std::string(name) + "'",
           problem);
}

// One count of one plugin, as one thread added it up.
struct Count {
  const PluginIdentity* plugin;
  std::string name;
  std::string key;
  std::int64_t value;
};

}  // namespace

std::string figure_name_problem(std::string_view name) {
  const auto allowed = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; };
  bool ok = !name.empty() && name.size() <= kMaxFigureName && name[0] >= 'a' && name[0] <= 'z';
  for (char c : name) ok = ok && allowed(c);
  if (ok) return "";
  return "a figure's name is lower-case letters, digits and '_', starting with a letter, at most " +
         std::to_string(kMaxFigureName) + " characters (as 'restarts' or 'nodes_forbidden')";
}

// Counts are kept per thread (on_stuck() adds on every construction thread, often), without a
// lock, and summed when read: integers, so the sum does not depend on how the calls were split.
struct FigureSink::Impl {
  tbb::enumerable_thread_specific<std::vector<Count>> counts;
  std::map<std::string, double> values;  // record(): single-threaded hooks only
  std::map<std::string, std::string> recorders;  // key -> the plugin, for messages
};

FigureSink::FigureSink() : impl_(std::make_unique<Impl>()) {}
FigureSink::~FigureSink() = default;

void FigureSink::record(const PluginIdentity* plugin, std::string_view name, double value) {
  const std::string key = key_prefix(plugin) + std::string(name);
  impl_->values[key] = value;
  impl_->recorders.emplace(key, recorder({plugin, nullptr, -1}));
}

void FigureSink::add(const PluginIdentity* plugin, std::string_view name, std::int64_t delta) {
  std::vector<Count>& mine = impl_->counts.local();
  for (Count& count : mine)
    if (count.plugin == plugin && count.name == name) {
      count.value += delta;
      return;
    }
  mine.push_back({plugin, std::string(name), key_prefix(plugin) + std::string(name), delta});
}

std::map<std::string, ParamValue> FigureSink::figures() const {
  std::map<std::string, std::int64_t> sums;
  for (const std::vector<Count>& thread : impl_->counts)
    for (const Count& count : thread) sums[count.key] += count.value;
  std::map<std::string, ParamValue> all;
  for (const auto& [key, value] : impl_->values) all[key] = value;
  for (const auto& [key, sum] : sums) {
    if (all.contains(key))
      throw Error(impl_->recorders.at(key) + " gave the figure '" + key.substr(key.find('.') + 1) +
                  "' to both Context::record() and Context::add(); a figure is either a value or a count: give the "
                  "other one another name");
    all[key] = sum;
  }
  return all;
}

void Context::record(std::string_view name, double value) const {
  const PluginCall call = current_plugin_call();
  check_name(call, name, "record");
  if (!std::isfinite(value))
    reject(call, "recorded " + to_string(ParamValue(value)) + " as the figure '" + std::string(name) + "'",
           "a figure must be finite");
  if (!figures) return;
  if (figures->parallel())
    reject(call, "called Context::record() for the figure '" + std::string(name) + "'",
           "this hook runs on the construction threads, where which call comes last depends on the thread count: "
           "count with Context::add(), or record in a single-threaded hook (strategies.hpp lists them)");
  figures->record(call.who, name, value);
}

void Context::add(std::string_view name, std::int64_t delta) const {
  const PluginCall call = current_plugin_call();
  check_name(call, name, "add");
  if (figures) figures->add(call.who, name, delta);
}

}  // namespace aco
