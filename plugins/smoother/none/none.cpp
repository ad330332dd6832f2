// No smoothing: the final path is the grid path's cell centres.
#include "aco/path.hpp"
#include "aco/plugin.hpp"

namespace {

class NoSmoother final : public aco::Smoother {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit NoSmoother(const aco::ParameterValues&) {}
  std::vector<Eigen::Vector3d> smooth(const aco::Context& c, std::span<const aco::NodeId> path) const override {
    return aco::to_waypoints(*c.graph, path);
  }
};

}  // namespace

ACO_PLUGIN(smoother, none, NoSmoother, "1.0", "keeps the grid path as it is", aco::no_parameters)
