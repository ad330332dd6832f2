#include "aco/plugin_guard.hpp"
#include "aco/plugin_error.hpp"

#include <cxxabi.h>

#include <cstdlib>
#include <exception>
#include <new>
#include <typeinfo>

namespace aco {
namespace {

// How every message numbers an iteration: as Context::iteration does, and saying so, since
// plugin authors compare it with what their hook saw.
constexpr const char* kIterationNumbering = " (0-based, as Context::iteration)";

// The innermost guarded call of this thread. Plain pointers and an int: a signal handler reads
// them without allocating.
thread_local PluginCall current_call;

// Appends `text` to out[0, size - 1) at `length`; signal-safe (no library call).
void append(char* out, std::size_t size, std::size_t& length, const char* text) noexcept {
  for (; text && *text && length + 1 < size; ++text) out[length++] = *text;
}

void append_number(char* out, std::size_t size, std::size_t& length, long value) noexcept {
  char digits[24];
  int n = 0;
  const bool negative = value < 0;
  unsigned long v = negative ? 0ul - static_cast<unsigned long>(value) : static_cast<unsigned long>(value);
  do digits[n++] = static_cast<char>('0' + v % 10);
  while ((v /= 10) != 0);
  if (negative) digits[n++] = '-';
  char text[24];
  for (int i = 0; i < n; ++i) text[i] = digits[n - 1 - i];
  text[n] = '\0';
  append(out, size, length, text);
}

}  // namespace

std::string describe(const PluginIdentity& who) {
  std::string plugin = "plugin " + who.slot + "/" + who.name;
  if (!who.file.empty()) plugin += " (" + who.file + ")";
  return plugin;
}

PluginCallScope::PluginCallScope(const PluginIdentity& who, const char* hook, int iteration) noexcept
    : who_(current_call.who), hook_(current_call.hook), iteration_(current_call.iteration) {
  current_call = {&who, hook, iteration};
}

PluginCallScope::~PluginCallScope() { current_call = {who_, hook_, iteration_}; }

PluginCall current_plugin_call() noexcept { return current_call; }

std::size_t describe_plugin_call(char* out, std::size_t size) noexcept {
  if (size == 0) return 0;
  std::size_t length = 0;
  const PluginCall call = current_call;
  if (call.who) {
    append(out, size, length, "plugin ");
    append(out, size, length, call.who->slot.c_str());
    append(out, size, length, "/");
    append(out, size, length, call.who->name.c_str());
    if (!call.who->file.empty()) {
      append(out, size, length, " (");
      append(out, size, length, call.who->file.c_str());
      append(out, size, length, ")");
    }
    append(out, size, length, " in ");
    append(out, size, length, call.hook);
    if (call.iteration >= 0) {
      append(out, size, length, " in iteration ");
      append_number(out, size, length, call.iteration);
      append(out, size, length, kIterationNumbering);
    }
  }
  out[length] = '\0';
  return length;
}

std::string describe_current_exception() {
  try {
    throw;
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    // Not a std::exception: its type is all there is to say.
    const std::type_info* type = abi::__cxa_current_exception_type();
    if (!type) return "an exception of unknown type";
    int status = 0;
    std::unique_ptr<char, decltype(&std::free)> name(abi::__cxa_demangle(type->name(), nullptr, nullptr, &status),
                                                     std::free);
    return std::string("an exception of type ") + (status == 0 && name ? name.get() : type->name());
  }
}

std::string describe_hook(const char* hook, int iteration) {
  std::string in = hook;
  if (iteration >= 0) in += " in iteration " + std::to_string(iteration) + kIterationNumbering;
  return in;
}

PluginError::~PluginError() = default;
InvalidValueError::~InvalidValueError() = default;

void rethrow_from_plugin(const PluginIdentity& who, const char* hook, int iteration) {
  const std::string plugin = describe(who);
  const std::string in = describe_hook(hook, iteration);
  try {
    throw;
  } catch (const PluginFault&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw OutOfMemoryError("out of memory in " + plugin + " in " + in + " (std::bad_alloc)");
  } catch (...) {
    throw PluginError(plugin + " failed in " + in + ": " + describe_current_exception());
  }
}

namespace {

// Who a guarded plugin is, found from the interface by describe_plugin().
struct Identified {
  PluginIdentity who_;
};

// A decorator of `Interface`: holds the plugin and calls it inside the boundary.
template <class Interface>
class Guarded : public Interface, public Identified {
 public:
  Guarded(std::unique_ptr<Interface> plugin, PluginIdentity who) : Identified{std::move(who)}, p_(std::move(plugin)) {}

  void begin_run(const Context& c) override {
    call("begin_run()", -1, [&] { p_->begin_run(c); });
  }

 protected:
  template <class F>
  auto call(const char* hook, int iteration, F&& f) const -> decltype(f()) {
    try {
      const PluginCallScope scope(who_, hook, iteration);
      return f();
    } catch (...) {
      rethrow_from_plugin(who_, hook, iteration);
    }
  }

  std::unique_ptr<Interface> p_;
};

// Each decorator forwards every virtual of its interface to the plugin, so the plugin's own
// overrides (or the interface's defaults, run on the plugin) answer; Guarded forwards
// Strategy's. A missed one would run the interface's default on the decorator instead:
// tests/test_plugin_guard.cpp counts each interface's virtuals and calls every one through the
// guard.
class GuardedInit final : public Guarded<PheromoneInit> {
 public:
  using Guarded::Guarded;
  void initialize(const Context& c, std::span<double> tau) override {
    call("initialize()", c.iteration, [&] { p_->initialize(c, tau); });
  }
};

class GuardedHeuristic final : public Guarded<Heuristic> {
 public:
  using Guarded::Guarded;
  void compute(const Context& c, std::span<double> eta) override {
    call("compute()", c.iteration, [&] { p_->compute(c, eta); });
  }
  HeuristicSpecs specs() const override {
    return call("specs()", -1, [&] { return p_->specs(); });
  }
  void compute_powered(const Context& c, std::span<double> eta_beta) override {
    call("compute_powered()", c.iteration, [&] { p_->compute_powered(c, eta_beta); });
  }
  void update_node(const Context& c, NodeId node, int since, std::span<double> eta_beta) const override {
    call("update_node()", c.iteration, [&] { p_->update_node(c, node, since, eta_beta); });
  }
  void step_factors(const Context& c, const Ant& ant, std::span<const EdgeId> candidates,
                    std::span<double> factors) const override {
    call("step_factors()", c.iteration, [&] { p_->step_factors(c, ant, candidates, factors); });
  }
};

class GuardedUpdate final : public Guarded<PheromoneUpdate> {
 public:
  using Guarded::Guarded;
  void update(const Context& c, const Iteration& iteration, std::span<double> tau) override {
    call("update()", c.iteration, [&] { p_->update(c, iteration, tau); });
  }
  void start(const Context& c, std::span<double> tau) override {
    call("start()", c.iteration, [&] { p_->start(c, tau); });
  }
  // Named update() in reports: it is the update hook, whose default calls update().
  void update_trail(const Context& c, const Iteration& iteration, Trail& trail) override {
    call("update()", c.iteration, [&] { p_->update_trail(c, iteration, trail); });
  }
};

class GuardedDeadlock final : public Guarded<DeadlockPolicy> {
 public:
  using Guarded::Guarded;
  int on_stuck(const Context& c, std::span<const NodeId> walk) const override {
    return call("on_stuck()", c.iteration, [&] { return p_->on_stuck(c, walk); });
  }
  void after_iteration(const Context& c, const Iteration& iteration, Trail& trail,
                       std::vector<std::uint8_t>& forbidden) override {
    call("after_iteration()", c.iteration, [&] { p_->after_iteration(c, iteration, trail, forbidden); });
  }
};

class GuardedSmoother final : public Guarded<Smoother> {
 public:
  using Guarded::Guarded;
  std::vector<Eigen::Vector3d> smooth(const Context& c, std::span<const NodeId> path) const override {
    return call("smooth()", -1, [&] { return p_->smooth(c, path); });
  }
};

class GuardedLocal final : public Guarded<LocalPlanner> {
 public:
  using Guarded::Guarded;
  VelocityCommand command(const LocalView& view) override {
    return call("command()", -1, [&] { return p_->command(view); });
  }
};

class GuardedMapReader final : public Guarded<MapReader> {
 public:
  using Guarded::Guarded;
  std::unique_ptr<Map> read(const std::filesystem::path& file, const TerrainOptions& terrain) const override {
    return call("read()", -1, [&] { return p_->read(file, terrain); });
  }
  std::vector<std::string> extensions() const override {
    return call("extensions()", -1, [&] { return p_->extensions(); });
  }
  std::string sample() const override {
    return call("sample()", -1, [&] { return p_->sample(); });
  }
};

}  // namespace

std::string describe_plugin(const Strategy& plugin, const char* slot) {
  if (const auto* guarded = dynamic_cast<const Identified*>(&plugin)) return describe(guarded->who_);
  return std::string("the ") + slot + " plugin";
}

std::unique_ptr<PheromoneInit> guard(std::unique_ptr<PheromoneInit> p, PluginIdentity who) {
  return std::make_unique<GuardedInit>(std::move(p), std::move(who));
}
std::unique_ptr<Heuristic> guard(std::unique_ptr<Heuristic> p, PluginIdentity who) {
  return std::make_unique<GuardedHeuristic>(std::move(p), std::move(who));
}
std::unique_ptr<PheromoneUpdate> guard(std::unique_ptr<PheromoneUpdate> p, PluginIdentity who) {
  return std::make_unique<GuardedUpdate>(std::move(p), std::move(who));
}
std::unique_ptr<DeadlockPolicy> guard(std::unique_ptr<DeadlockPolicy> p, PluginIdentity who) {
  return std::make_unique<GuardedDeadlock>(std::move(p), std::move(who));
}
std::unique_ptr<Smoother> guard(std::unique_ptr<Smoother> p, PluginIdentity who) {
  return std::make_unique<GuardedSmoother>(std::move(p), std::move(who));
}
std::unique_ptr<LocalPlanner> guard(std::unique_ptr<LocalPlanner> p, PluginIdentity who) {
  return std::make_unique<GuardedLocal>(std::move(p), std::move(who));
}
std::unique_ptr<MapReader> guard(std::unique_ptr<MapReader> p, PluginIdentity who) {
  return std::make_unique<GuardedMapReader>(std::move(p), std::move(who));
}

}  // namespace aco
