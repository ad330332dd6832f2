// A stuck ant is dropped: it deposits nothing and the iteration goes on without it.
#include "aco/plugin.hpp"

namespace {

class DiscardPolicy final : public aco::DeadlockPolicy {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit DiscardPolicy(const aco::ParameterValues&) {}
  int on_stuck(const aco::Context&, std::span<const aco::NodeId>) const override { return 0; }
};

}  // namespace

ACO_PLUGIN(deadlock, discard, DiscardPolicy, "1.0", "a stuck ant is dropped", aco::no_parameters)
