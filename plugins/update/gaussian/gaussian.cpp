// Gaussian pheromone deposition (paper 002, eq. 7): an arrived ant deposits around its path, not
// only on it. Every cell of the path spreads y(x) = psi / sqrt(2 pi sigma) * exp(-(x - mu)^2 /
// (2 sigma^2)) to the cells within the cutoff radius (x = distance between the two cells), and the
// contributions add up, so cells inside a bend, near several path cells, collect the most.
#include <cmath>
#include <vector>

#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

constexpr aco::ParamSpec kParams[] = {
    {"rho", aco::ParamType::real, "0.3", "0:1", "evaporation rate (paper 002: 0.3)"},
    {"q", aco::ParamType::real, "1", "(0:1e12]", "deposit constant Q: ant k's spread is scaled by Q / L_k (paper 002: 1)"},
    {"psi", aco::ParamType::real, "300", "0:1e12", "balance factor psi (paper 002: 300)"},
    {"mu", aco::ParamType::real, "0", "-100:100", "mean mu of the Gaussian (paper 002: 0)"},
    {"sigma", aco::ParamType::real, "1", "(0:100]", "spread sigma of the Gaussian (paper 002: 1)"},
    {"cutoff", aco::ParamType::real, "2", "0:20", "radius in cells around each path cell that receives pheromone"},
};

class GaussianUpdate final : public aco::PheromoneUpdate {
 public:
  explicit GaussianUpdate(const aco::ParameterValues& p)
      : rho_(p.real("rho")), q_(p.real("q")), psi_(p.real("psi")), mu_(p.real("mu")), sigma_(p.real("sigma")),
        cutoff_(p.real("cutoff")) {
    // The kernel depends only on the offset between the two cells: tabulate it once.
    const int r = static_cast<int>(std::floor(cutoff_));
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const double x = std::hypot(dx, dy);
        if (x > cutoff_) continue;
        const double y = psi_ / std::sqrt(2 * M_PI * sigma_) * std::exp(-(x - mu_) * (x - mu_) / (2 * sigma_ * sigma_));
        kernel_.push_back({dx, dy, y});
      }
  }

  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    const aco::Graph& g = *c.graph;
    spread_.resize(g.num_nodes(), 0.0);
    aco::evaporate(tau, rho_);
    for (const aco::Ant& ant : it.ants) {
      if (!ant.arrived) continue;
      touched_.clear();
      for (aco::NodeId p : ant.nodes) {
        const aco::Cell cell = g.cell(p);
        for (const auto& k : kernel_) {
          const aco::Cell near{cell.x + k.dx, cell.y + k.dy};
          if (near.x < 0 || near.y < 0 || near.x >= g.width || near.y >= g.height) continue;
          const aco::NodeId n = g.node(near);
          if (spread_[n] == 0.0) touched_.push_back(n);
          spread_[n] += k.weight;
        }
      }
      // The pheromone of a cell is that of every edge into it.
      const double scale = q_ / ant.length;
      for (aco::NodeId n : touched_) {
        for (aco::EdgeId e = g.edges_begin(n); e < g.edges_end(n); ++e) tau[g.reverse[e]] += scale * spread_[n];
        spread_[n] = 0.0;
      }
    }
  }

 private:
  struct Offset {
    int dx;
    int dy;
    double weight;
  };
  double rho_, q_, psi_, mu_, sigma_, cutoff_;
  std::vector<Offset> kernel_;
  std::vector<double> spread_;       // per node, zero between ants
  std::vector<aco::NodeId> touched_;  // nodes with a non-zero spread_
};

}  // namespace

ACO_PLUGIN(update, gaussian, GaussianUpdate, "1.0",
           "paper 002: evaporate, then every arrived ant spreads Q/L_k * psi * N(x; mu, sigma) around its path", kParams)
