// The checks themselves: each parameter set's passes on 1 and 4 threads, compared, and reported.
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cctype>

#include "aco/sdk/conformance.hpp"
#include "aco/engine/plugin_guard.hpp"
#include "plugin_files.hpp"
#include "slot_runs.hpp"
#include "trace.hpp"

namespace aco::conformance {

namespace fs = std::filesystem;

std::string CheckResult::line() const {
  const char* word = status == Status::pass ? "PASS" : status == Status::fail ? "FAIL" : "SKIP";
  return std::string(word) + " " + plugin + " [" + parameters + "] " + check + (detail.empty() ? "" : ": " + detail);
}

namespace {

// One pass of every check's runs over the standard problems with one instance of the plugin,
// then the first problem once more with the same instance: the lifecycle's rule (strategies.hpp)
// is that a reused object's run gives what a fresh object's gives.
template <class Interface>
struct Pass {
  static constexpr bool kHasRuns = !std::is_same_v<Interface, MapReader>;
  Trace trace;
  std::string reuse;  // how the second run on the first problem differed, or ""

  Pass(Interface& plugin, const std::vector<Problem>& problems, const Options& options, bool colony) {
    auto run = [&](const Problem& problem, Trace& into) {
      try {
        into.begin(problem.name);
        // A run of the hooks begins as a host's does (the colony run below begins its own).
        if constexpr (kHasRuns) plugin.begin_run(problem.context(0, kIterations));
        run_slot(plugin, problem, into);
        if constexpr (!std::is_same_v<Interface, Smoother> && !std::is_same_v<Interface, LocalPlanner> &&
                      !std::is_same_v<Interface, MapReader>)
          if (colony) run_colony_with(plugin, problem, options.colony, into);
      } catch (const std::exception& e) {
        into.problem(e.what());
      }
    };
    std::size_t first_end = 0;
    for (const auto& problem : problems) {
      run(problem, trace);
      if (first_end == 0) first_end = trace.values.size();
    }
    if constexpr (!kHasRuns) return;
    Trace again;
    run(problems.front(), again);
    Trace first = trace;
    first.values.resize(first_end);
    reuse = difference(first, again);
  }
};

template <class Interface>
void check_typed(PluginRegistry& registry, const PluginFile& plugin, const Options& options, const Report& report) {
  const PluginDescriptor& descriptor = registry.load(plugin.slot, plugin.name);
  const PluginIdentity who{plugin.slot, plugin.name, plugin.file.string()};
  const std::string label = plugin.slot + "/" + plugin.name;
  const std::vector<Problem> problems = standard_problems();
  const std::vector<Problem> voxels = options.voxel_worlds ? voxel_problems() : std::vector<Problem>{};
  bool said_not_3d = false;  // the SKIP line of a plugin that does not claim voxel worlds, once
  const bool colony = !std::is_same_v<Interface, Smoother> && !std::is_same_v<Interface, LocalPlanner> &&
                      !std::is_same_v<Interface, MapReader>;
  const std::vector<ParameterSet> sets = parameter_sets(descriptor.parameters(), options.integer_cap);
  // Whether a refusal of `set`'s value is of a combination the table cannot express (a < b):
  // the message names another parameter, or the factory takes the value beside another
  // parameter's tried value.
  auto taken_in_some_combination = [&](const ParameterSet& set, const std::string& message) {
    for (const ParamSpec& spec : descriptor.parameters()) {
      const std::string name = spec.name;
      if (name == set.given.begin()->first) continue;
      for (auto at = message.find(name); at != std::string::npos; at = message.find(name, at + 1)) {
        const auto word = [&](std::size_t i) {
          return i < message.size() && (std::isalnum(static_cast<unsigned char>(message[i])) || message[i] == '_');
        };
        if ((at == 0 || !word(at - 1)) && !word(at + name.size())) return true;
      }
    }
    for (const auto& other : sets) {
      if (other.given.empty() || other.given.begin()->first == set.given.begin()->first) continue;
      std::map<std::string, std::string> given = set.given;
      given.insert(other.given.begin(), other.given.end());
      given.insert(options.fixed.begin(), options.fixed.end());
      try {
        std::unique_ptr<Strategy>(descriptor.create(resolve(descriptor.parameters(), given, plugin.slot + ".")));
        return true;
      } catch (const Error&) {}
    }
    return false;
  };
  for (const auto& set : sets) {
    auto result = [&](const std::string& check, const std::string& detail, CheckResult::Status status) {
      report({label, set.label, check, status, detail});
    };
    std::map<std::string, std::string> given = set.given;
    given.insert(options.fixed.begin(), options.fixed.end());  // the set's own value wins
    const ParameterValues values = resolve(descriptor.parameters(), given, plugin.slot + ".");
    // A fresh instance per pass; the factory refusing a value with aco::Error is its right.
    auto make = [&]() -> std::unique_ptr<Interface> {
      std::unique_ptr<Strategy> strategy(descriptor.create(values));
      auto* typed = dynamic_cast<Interface*>(strategy.get());
      if (!typed) throw Error("the factory made an object that does not implement the " + plugin.slot + " interface");
      strategy.release();
      return guard(std::unique_ptr<Interface>(typed), who);
    };
    std::unique_ptr<Interface> first;
    try {
      first = make();
    } catch (const Error& e) {
      if (set.if_refused.empty() || taken_in_some_combination(set, e.what())) {
        result("constructs", std::string("refused with an error: ") + e.what(), CheckResult::Status::skip);
      } else {
        const ParamSpec& spec = *std::find_if(descriptor.parameters().begin(), descriptor.parameters().end(),
                                              [&](const ParamSpec& p) { return set.given.count(p.name); });
        result("constructs",
               "refused " + set.label + ", which its declared " +
                   (spec.range && *spec.range ? "range " + std::string(spec.range) : "type") + " admits (" + e.what() +
                   "); declare " + set.if_refused + " or accept the value",
               CheckResult::Status::fail);
      }
      continue;
    } catch (...) {
      result("constructs", "the factory threw " + describe_current_exception(), CheckResult::Status::fail);
      continue;
    }
    using S = CheckResult::Status;
    // The four checks on `worlds`, the first pass with `fresh`; `prefix` ("" or "3D ") names them.
    auto run_checks = [&](const std::string& prefix, const std::vector<Problem>& worlds,
                          std::unique_ptr<Interface> fresh) {
      auto pass = [&](std::unique_ptr<Interface> instance, int threads) {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
        tbb::task_arena arena(threads);
        return arena.execute([&] { return Pass<Interface>(*instance, worlds, options, colony); });
      };
      // A run on 1 thread and one on 4: the same output shows determinism and thread independence
      // at once. Only when they differ does another run on 1 thread tell which of the two failed.
      const Pass<Interface> one = pass(std::move(fresh), 1);
      std::string by_threads = difference(one.trace, pass(make(), 4).trace);
      std::string nondeterminism;
      if (!by_threads.empty()) {
        nondeterminism = difference(one.trace, pass(make(), 1).trace);
        if (!nondeterminism.empty()) by_threads = "not separable: two runs on 1 thread differ as well";
      }
      const auto& problems_found = one.trace.problems;
      // In a voxel world, what a plugin written for grids gets wrong.
      const std::string hint = prefix.empty() ? ""
                                              : " [in a voxel world cells have z and moves dz: use cost(e), "
                                                "reverse_edge(e) and position(n)]";
      result(
          prefix + "values",
          problems_found.empty()
              ? ""
              : problems_found.front() +
                    (problems_found.size() > 1 ? " (and " + std::to_string(problems_found.size() - 1) + " more)" : "") +
                    hint,
          problems_found.empty() ? S::pass : S::fail);
      result(prefix + "deterministic", nondeterminism, nondeterminism.empty() ? S::pass : S::fail);
      result(prefix + "threads", by_threads.empty() ? "" : "1 vs 4 threads: " + by_threads,
             by_threads.empty() ? S::pass : S::fail);
      if (!Pass<Interface>::kHasRuns) return;
      if (!nondeterminism.empty())
        result(prefix + "reused", "two runs of fresh objects differ already", S::skip);
      else
        result(prefix + "reused",
               one.reuse.empty()
                   ? ""
                   : "a second run of the same object, after runs on other maps, differs from its first: " + one.reuse,
               one.reuse.empty() ? S::pass : S::fail);
    };
    // Whether this object plans in voxel worlds, asked before its first run (as plan() asks).
    // A map reader has no runs to check there (its sample is read whatever its dimension).
    const bool in_3d = options.voxel_worlds && Pass<Interface>::kHasRuns;
    bool claims_3d = false;
    std::string claim_failed;
    if (in_3d) {
      try {
        claims_3d = first->supports_voxel_worlds();
      } catch (...) {
        claim_failed = describe_current_exception();
      }
    }
    if (options.grids) run_checks("", problems, std::move(first));
    if (!in_3d) continue;
    if (!claim_failed.empty()) {
      result("3D", "supports_voxel_worlds() threw " + claim_failed, S::fail);
    } else if (!claims_3d) {
      // Once per plugin: every set after the first that does not claim them would say the same.
      if (!said_not_3d)
        result("3D", "not run in 3D: it does not claim voxel worlds (supports_voxel_worlds() is false)", S::skip);
      said_not_3d = true;
    } else if (std::is_same_v<Interface, LocalPlanner>) {
      result("3D", "not run in 3D: a local planner drives in the plane (acosim); no voxel world reaches it", S::skip);
    } else {
      run_checks("3D ", voxels, first ? std::move(first) : make());
    }
  }
}

}  // namespace

void check_plugin(const PluginFile& plugin, const Options& options, const Report& report) {
  PluginRegistry& registry = *plugins_of(plugin.file).first;
#define ACO_CHECK_SLOT_(NAME, INTERFACE) \
  if (plugin.slot == #NAME) return check_typed<INTERFACE>(registry, plugin, options, report);
  ACO_SLOTS(ACO_CHECK_SLOT_)
#undef ACO_CHECK_SLOT_
  throw Error("plugin " + plugin.slot + "/" + plugin.name + ": unknown slot '" + plugin.slot + "'");
}

int check_file(const fs::path& file, const Options& options, const Report& report) {
  int failures = 0;
  for (const auto& plugin : plugins_in(file)) {
    check_plugin(plugin, options, [&](const CheckResult& r) {
      if (r.status == CheckResult::Status::fail) ++failures;
      report(r);
    });
  }
  return failures;
}

}  // namespace aco::conformance
