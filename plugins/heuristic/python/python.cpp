// A heuristic written in Python: compute() of the object --heuristic.class names (see README.md).
#include "aco/plugin.hpp"
#include "bridge.hpp"

namespace {

class PythonHeuristic final : public aco::python::Adapter<aco::Heuristic> {
 public:
  explicit PythonHeuristic(const aco::ParameterValues& values)
      : Adapter("heuristic", values, {"compute(self, context, eta)"}), varies_(object_->flag("varies_by_iteration")) {}
  void compute(const aco::Context& context, std::span<double> eta) override {
    object_->call("compute", context, nullptr, eta);
  }
  aco::HeuristicSpecs specs() const override { return {.varies_by_iteration = varies_}; }

 private:
  bool varies_;
};

}  // namespace

ACO_PLUGIN(heuristic, python, PythonHeuristic, "1.0", "a heuristic written in Python: compute() of --heuristic.class",
           aco::python::settings_table())
