// Gaussian pheromone deposition (paper 002, eq. 7): an arrived ant deposits around its path, not
// only on it. Every step of the path spreads y(x) = psi / sqrt(2 pi sigma) * exp(-(x - mu)^2 /
// (2 sigma^2)) to its neighbourhood within the cutoff radius (x = length of the offset), scaled
// by Q / L_k, and the contributions add up, so the inside of a bend, near both of its legs,
// collects the most. In a voxel world the neighbourhood is the ball of that radius.
#include <cmath>
#include <vector>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double rho = 0.3;
  double q = 1.0;
  double psi = 300.0;
  double mu = 0.0;
  double sigma = 1.0;
  double cutoff = 2.0;
  bool onto_edges = true;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("rho", &Parameters::rho, "0:1", "evaporation rate (paper 002: 0.3)"),
    aco::field("q", &Parameters::q, "(0:1e12]",
               "deposit constant Q: ant k's spread is scaled by Q / L_k (paper 002: 1)"),
    aco::field("psi", &Parameters::psi, "0:1e12", "balance factor psi (paper 002: 300)"),
    aco::field("mu", &Parameters::mu, "-100:100", "mean mu of the Gaussian (paper 002: 0)"),
    aco::field("sigma", &Parameters::sigma, "0.01:100", "spread sigma of the Gaussian (paper 002: 1)"),
    aco::field("cutoff", &Parameters::cutoff, "0:20", "radius in cells of the neighbourhood that receives pheromone"),
    aco::choice("onto", &Parameters::onto_edges, {"edges", "cells"}, {true, false},
                "edges: each path step, shifted by the offset, gets y (the move keeps its direction); "
                "cells: every edge into each cell near a path cell gets y (direction is lost)"),
});

class GaussianUpdate final : public aco::PheromoneUpdate {
 public:
  bool supports_voxel_worlds() const override { return true; }
  explicit GaussianUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {
    // The kernel depends only on the offset: tabulate it once.
    const double psi = p_.psi, mu = p_.mu, sigma = p_.sigma, cutoff = p_.cutoff;
    const int r = static_cast<int>(std::floor(cutoff));
    const auto y = [&](double x) {
      return psi / std::sqrt(2 * M_PI * sigma) * std::exp(-(x - mu) * (x - mu) / (2 * sigma * sigma));
    };
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const double x = std::hypot(dx, dy);
        if (x <= cutoff) kernel_.push_back({dx, dy, 0, y(x)});
      }
    for (int dz = -r; dz <= r; ++dz)
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const double x = std::sqrt(dx * dx + dy * dy + dz * dz);
          if (x <= cutoff) ball_.push_back({dx, dy, dz, y(x)});
        }
  }

  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    aco::evaporate(tau, p_.rho);
    for (const aco::Ant& ant : it.ants) {
      if (!ant.arrived) continue;
      if (p_.onto_edges)
        spread_onto_edges(*c.graph, ant, tau);
      else
        spread_onto_cells(*c.graph, ant, tau);
    }
  }

 private:
  struct Offset {
    int dx;
    int dy;
    int dz;
    double weight;
  };

  const std::vector<Offset>& kernel(const aco::Graph& g) const { return g.volumetric ? ball_ : kernel_; }

  // Step a -> b deposits y(|o|) on the step a+o -> b+o, where that is an edge of the graph.
  void spread_onto_edges(const aco::Graph& g, const aco::Ant& ant, std::span<double> tau) const {
    const double scale = p_.q / ant.length;
    for (std::size_t i = 0; i < ant.edges.size(); ++i) {
      const aco::Cell a = g.cell(ant.nodes[i]), b = g.cell(ant.nodes[i + 1]);
      const int dx = b.x - a.x, dy = b.y - a.y, dz = b.z - a.z;
      for (const Offset& k : kernel(g)) {
        const aco::Cell from{a.x + k.dx, a.y + k.dy, a.z + k.dz};
        if (!g.map->contains(from)) continue;
        const aco::EdgeId e = g.edge_by_move(g.node(from), dx, dy, dz);
        if (e >= 0) tau[e] += scale * k.weight;
      }
    }
  }

  // Path cell p gives y(|c - p|) to cell c, and every edge into c receives c's total.
  void spread_onto_cells(const aco::Graph& g, const aco::Ant& ant, std::span<double> tau) {
    spread_.resize(g.num_nodes(), 0.0);
    touched_.clear();
    for (aco::NodeId p : ant.nodes) {
      const aco::Cell cell = g.cell(p);
      for (const Offset& k : kernel(g)) {
        const aco::Cell near{cell.x + k.dx, cell.y + k.dy, cell.z + k.dz};
        if (!g.map->contains(near)) continue;
        const aco::NodeId n = g.node(near);
        if (spread_[n] == 0.0) touched_.push_back(n);
        spread_[n] += k.weight;
      }
    }
    const double scale = p_.q / ant.length;
    for (aco::NodeId n : touched_) {
      for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) tau[g.reverse_edge(e)] += scale * spread_[n];
      spread_[n] = 0.0;
    }
  }

  Parameters p_;
  std::vector<Offset> kernel_;  // the disc of the cutoff radius, for grids and terrains
  std::vector<Offset> ball_;  // its ball, for voxel worlds
  std::vector<double> spread_;  // per node, zero between ants (cells mode)
  std::vector<aco::NodeId> touched_;  // nodes with a non-zero spread_
};

}  // namespace

ACO_PLUGIN(update, gaussian, GaussianUpdate, "1.0",
           "paper 002: evaporate, then every arrived ant spreads Q/L_k * psi * N(x; mu, sigma) around its path",
           kParams)
