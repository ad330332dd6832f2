// update/rank_based_as: the rank-based Ant System (AS_rank) of Bullnheimer, Hartl and Strauss,
// "A new rank based version of the Ant System: a computational study", Central European Journal
// of Operations Research 7(1), 25-38, 1999. After evaporation, the w - 1 shortest arrived ants
// of the iteration deposit by rank, (w - r) Q / L_r for rank r = 1 .. w - 1, and the best path
// so far deposits w Q / L_best (see README.md).
#include "aco/pheromone.hpp"
#include "aco/plugin.hpp"

namespace {

struct Parameters {
  int w = 6;  // Dorigo and Stuetzle's setting (Ant Colony Optimization, 2004, table 3.1)
  double rho = 0.1;  // evaporation rate, same source
  double q = 1.0;  // deposit constant Q
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("w", &Parameters::w, "1:1000",
               "the best-so-far path deposits w Q / L; the w - 1 best ants of the iteration rank"),
    aco::field("rho", &Parameters::rho, "0:1", "evaporation rate: tau <- (1 - rho) tau first"),
    aco::field("q", &Parameters::q, "(0:1e12]", "deposit constant Q"),
});

class RankBasedUpdate final : public aco::PheromoneUpdate {
 public:
  explicit RankBasedUpdate(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  // Every run's figures hold the count, the runs with no ranked deposit too.
  void start(const aco::Context& c, std::span<double>) override { c.add("ranked_deposits", 0); }

  void update(const aco::Context& c, const aco::Iteration& it, std::span<double> tau) override {
    aco::evaporate(tau, p_.rho);
    // Shortest first, ties in ant order: the ranking, and so the run, is deterministic.
    const std::vector<const aco::Ant*> ranked = aco::arrived_by_length(it.ants);
    std::size_t r = 1;
    for (; r <= ranked.size() && r < static_cast<std::size_t>(p_.w); ++r)
      deposit(tau, *ranked[r - 1], (p_.w - static_cast<double>(r)) * p_.q);
    // Deposits by rank over the run: below (w - 1) per iteration, too few ants arrived to rank.
    c.add("ranked_deposits", static_cast<std::int64_t>(r - 1));
    if (it.best_so_far) deposit(tau, *it.best_so_far, p_.w * p_.q);
  }

 private:
  // weight Q / L on every edge of the walk; a walk of no edge (start == goal) has nothing to mark.
  static void deposit(std::span<double> tau, const aco::Ant& ant, double weight) {
    if (!ant.edges.empty()) aco::deposit(tau, ant, weight / ant.length);
  }

  Parameters p_;
};

}  // namespace

ACO_PLUGIN(
    update, rank_based_as, RankBasedUpdate, "1.0",
    "rank-based Ant System (Bullnheimer et al. 1999): the w-1 best ants deposit (w-r)Q/L_r, the best so far wQ/L",
    kParams)
