// Back-off (paper 004, section 3.3): an ant with nowhere to go steps back instead of dying; the
// nodes it leaves stay in its tabu list, so it never re-enters the dead end in this walk.
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  int steps = 1;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field(
        "steps", &Parameters::steps, "1:1000000",
        "nodes a stuck ant steps back at once; 1 = depth-first back-off, which on a connected map always arrives"),
});

class Backtrack final : public aco::DeadlockPolicy {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit Backtrack(const aco::ParameterValues& values) : p_(kParams.read(values)) {}
  // How often ants backed off: a measure of how maze-like the map is for this colony.
  int on_stuck(const aco::Context& c, std::span<const aco::NodeId>) const override {
    c.add("backoffs");
    return p_.steps;
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(deadlock, backtrack, Backtrack, "1.0",
           "paper 004: a stuck ant steps back and keeps the dead end tabu; with steps = 1 every ant arrives on a "
           "connected map",
           kParams)
