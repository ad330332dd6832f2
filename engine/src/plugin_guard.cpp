#include "aco/engine/plugin_guard.hpp"

#include "aco/plugin_error.hpp"

namespace aco {
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
  bool supports_voxel_worlds() const override {
    return call("supports_voxel_worlds()", -1, [&] { return p_->supports_voxel_worlds(); });
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
