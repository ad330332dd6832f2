// An initial pheromone written in Python: initialize() of the object --init.class names (see README.md).
#include "aco/plugin.hpp"
#include "bridge.hpp"

namespace {

class PythonInit final : public aco::python::Adapter<aco::PheromoneInit> {
 public:
  explicit PythonInit(const aco::ParameterValues& values)
      : Adapter("init", values, {"initialize(self, context, tau)"}) {}
  void initialize(const aco::Context& context, std::span<double> tau) override {
    object_->call("initialize", context, nullptr, tau);
  }
};

}  // namespace

ACO_PLUGIN(init, python, PythonInit, "1.0", "an initial pheromone written in Python: initialize() of --init.class",
           aco::python::settings_table())
