// A pheromone update written in Python: the hooks of the object --update.class names (see README.md).
#include "aco/plugin.hpp"
#include "bridge.hpp"

namespace {

class PythonUpdate final : public aco::python::Adapter<aco::PheromoneUpdate> {
 public:
  explicit PythonUpdate(const aco::ParameterValues& values)
      : Adapter("update", values, {"update(self, context, iteration, tau)"}), has_start_(object_->has("start")) {}
  void update(const aco::Context& context, const aco::Iteration& iteration, std::span<double> tau) override {
    object_->call("update", context, &iteration, tau);
  }
  void start(const aco::Context& context, std::span<double> tau) override {
    if (has_start_) object_->call("start", context, nullptr, tau);
  }

 private:
  bool has_start_;
};

}  // namespace

ACO_PLUGIN(update, python, PythonUpdate, "1.0", "a pheromone update written in Python: update() of --update.class",
           aco::python::settings_table())
