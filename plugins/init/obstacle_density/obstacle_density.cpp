// Obstacle-density initial pheromone (paper 003, eq. 7-8): tau_ij(0) = gamma * f(j), f(j) = share
// of free cells among the 8 neighbours of j (in a voxel world, the 26 neighbours of voxel j).
// Cells outside the map count as blocked, so cells on the map's edge start low, as the paper wants.
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double gamma = 8.0;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("gamma", &Parameters::gamma, "(0:1e12]",
               "enhancement coefficient: a cell with 8 free neighbours gets gamma (8 = the uniform plugin's tau0)"),
});

class ObstacleDensityInit final : public aco::PheromoneInit {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit ObstacleDensityInit(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  void initialize(const aco::Context& c, std::span<double> tau) override {
    const aco::Graph& g = *c.graph;
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) tau[e] = p_.gamma * free_share(*g.map, g.cell(g.targets[e]));
  }

  static double free_share(const aco::Map& map, aco::Cell j) {
    const int layers = map.volumetric() ? 1 : 0;
    int free = 0;
    for (int dz = -layers; dz <= layers; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          if ((dx != 0 || dy != 0 || dz != 0) && map.passable({j.x + dx, j.y + dy, j.z + dz})) ++free;
    return free / (layers ? 26.0 : 8.0);
  }

 private:
  Parameters p_;
};

}  // namespace

ACO_PLUGIN(init, obstacle_density, ObstacleDensityInit, "1.0",
           "paper 003: tau(0) of every edge into j = gamma * (free cells among j's 8 neighbours) / 8", kParams)
