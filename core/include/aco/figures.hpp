#pragma once
// Where the figures plugins record about their run go (Context::record() and Context::add(), see
// strategies.hpp). The host that runs the colony owns one per run, puts it in ColonyStrategies::figures
// (or Context::figures for a hook it calls itself, as plan() does for the smoother) and reads it
// afterwards: aco::plan() adds them to PlanOutcome::properties, beside the planner's own.
//
// A figure is stored under "<slot>/<plugin>.<name>" ("update/max_min.restarts"), named after the
// plugin whose hook recorded it; a strategy not made by the plugin registry (a test's own
// object) records under "plugin.<name>".
#include <boost/config.hpp>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <string_view>

#include "aco/parameters.hpp"

namespace aco {

struct PluginIdentity;

class BOOST_SYMBOL_VISIBLE FigureSink {
 public:
  FigureSink();
  ~FigureSink();
  FigureSink(const FigureSink&) = delete;
  FigureSink& operator=(const FigureSink&) = delete;

  // Checked by Context::record() and add() before they get here (name, value, thread).
  void record(const PluginIdentity* plugin, std::string_view name, double value);
  void add(const PluginIdentity* plugin, std::string_view name, std::int64_t delta);

  // The engine marks the ants' construction, whose hooks run on several threads: record() is
  // refused there, since which thread writes last would depend on the thread count.
  void set_parallel(bool parallel) { parallel_ = parallel; }
  bool parallel() const { return parallel_; }

  // Every figure recorded so far, by key: a count (add) as an integer, a value (record) as a
  // real. Error naming the plugin if one name was given to both record() and add().
  std::map<std::string, ParamValue> figures() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  bool parallel_ = false;
};

// Why `name` cannot name a figure ("" if it can): lower-case letters, digits and '_', starting
// with a letter, at most 64 characters, as the keys of the results database and CSV columns take.
std::string figure_name_problem(std::string_view name);

}  // namespace aco
