// Direction heuristic (paper 001, eq. 6-7): eta_ab = 1 / (d + gamma * |dtheta| / pi), dtheta =
// heading change between the ant's previous move and the candidate move.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "aco/plugin.hpp"

namespace {

struct Parameters {
  double gamma = 20.0;
  bool to_goal = true;
  double min_distance = 0.01;
};

const aco::SettingsTable<Parameters> kParams({
    aco::field("gamma", &Parameters::gamma, "0:1000",
               "weight of the heading change, in cells: a U-turn adds gamma to d"),
    aco::choice(
        "distance", &Parameters::to_goal, {"goal", "step"}, {true, false},
        "d: distance from the next node to the goal (goal), or the step length d_ab (step, eq. 6 read literally)"),
    aco::field("min_distance", &Parameters::min_distance, "1e-6:1",
               "floor of d, so stepping onto the goal stays finite"),
});

// Moves are told apart by (dx, dy) in [-2, 2]^2, the reach of a 16-neighbourhood; in a voxel
// world by the graph's own move index (Graph::edge_moves, one of 26).
constexpr int kMoveKinds = 25;
int move_kind(aco::Cell from, aco::Cell to) { return (to.x - from.x + 2) * 5 + (to.y - from.y + 2); }
constexpr int kVoxelMoveKinds = 26;

class DirectionHeuristic final : public aco::Heuristic {
 public:
  explicit DirectionHeuristic(const aco::ParameterValues& values) : p_(kParams.read(values)) {}

  aco::HeuristicSpecs specs() const override { return {.uses_walk = true}; }
  // In 3D the heading change is the angle between two moves in space.
  bool supports_voxel_worlds() const override { return true; }

  // The table part: eta = 1 / d with no turn. Also prepares the per-step lookups: the engine
  // asks step_factors() once per step, and it must not call pow() there.
  void compute(const aco::Context& c, std::span<double> eta) override {
    const aco::Graph& g = *c.graph;
    kinds_ = g.volumetric ? kVoxelMoveKinds : kMoveKinds;
    g.volumetric ? build_voxel_turn_classes(g) : build_turn_classes();
    // A voxel world's edges know their move already: no copy of hundreds of millions of them.
    if (g.volumetric) std::vector<std::uint8_t>().swap(move_);
    if (!g.volumetric) move_.resize(g.num_edges());
    moves_ = g.volumetric ? g.edge_moves.data() : move_.data();
    const int keys = p_.to_goal ? g.num_nodes() : kinds_;
    std::vector<double> d(keys, 1.0);
    for (aco::EdgeId e = 0; e < g.num_edges(); ++e) {
      const aco::NodeId to = g.targets[e];
      if (!g.volumetric) move_[e] = static_cast<std::uint8_t>(move_kind(g.cell(g.source(e)), g.cell(to)));
      const double dist = p_.to_goal ? g.distance(to, c.goal) : g.cost(e);
      d[key(g, e)] = std::max(dist, p_.min_distance);
      eta[e] = 1.0 / d[key(g, e)];
    }
    // factor = (eta with the turn / eta without)^beta = (d / (d + gamma * turn))^beta
    factor_.assign(static_cast<std::size_t>(keys) * turn_values_.size(), 1.0);
    for (int k = 0; k < keys; ++k)
      for (std::size_t t = 0; t < turn_values_.size(); ++t)
        factor_[k * turn_values_.size() + t] = std::pow(d[k] / (d[k] + p_.gamma * turn_values_[t]), c.beta);
  }

  void step_factors(const aco::Context& c, const aco::Ant& ant, std::span<const aco::EdgeId> candidates,
                    std::span<double> factors) const override {
    if (ant.edges.empty()) {  // no heading yet
      std::fill(factors.begin(), factors.end(), 1.0);
      return;
    }
    const std::uint8_t* turn = &turn_class_[moves_[ant.edges.back()] * kinds_];
    const std::size_t classes = turn_values_.size();
    if (p_.to_goal) {
      const aco::NodeId* targets = c.graph->targets.data();
      for (std::size_t i = 0; i < candidates.size(); ++i)
        factors[i] = factor_[targets[candidates[i]] * classes + turn[moves_[candidates[i]]]];
    } else {
      for (std::size_t i = 0; i < candidates.size(); ++i)
        factors[i] = factor_[moves_[candidates[i]] * classes + turn[moves_[candidates[i]]]];
    }
  }

 private:
  std::size_t key(const aco::Graph& g, aco::EdgeId e) const {
    return p_.to_goal ? static_cast<std::size_t>(g.targets[e]) : static_cast<std::size_t>(moves_[e]);
  }

  // The turn classes of a voxel world: the angle between the two moves, over pi.
  void build_voxel_turn_classes(const aco::Graph& g) {
    const auto moves = aco::moves(g.options.neighbourhood);
    turn_values_.clear();
    turn_class_.assign(kVoxelMoveKinds * kVoxelMoveKinds, 0);
    for (std::size_t a = 0; a < moves.size(); ++a) {
      for (std::size_t b = 0; b < moves.size(); ++b) {
        const Eigen::Vector3d va(moves[a].dx, moves[a].dy, moves[a].dz), vb(moves[b].dx, moves[b].dy, moves[b].dz);
        const double turn = std::acos(std::clamp(va.dot(vb) / (va.norm() * vb.norm()), -1.0, 1.0)) / M_PI;
        turn_class_[a * kVoxelMoveKinds + b] = turn_class_of(turn);
      }
    }
  }

  std::uint8_t turn_class_of(double turn) {
    auto found =
        std::find_if(turn_values_.begin(), turn_values_.end(), [&](double v) { return std::fabs(v - turn) < 1e-9; });
    if (found == turn_values_.end()) found = turn_values_.insert(turn_values_.end(), turn);
    return static_cast<std::uint8_t>(found - turn_values_.begin());
  }

  // |dtheta| / pi for every pair of move kinds, as a small class index: 5 classes on an
  // 8-neighbourhood (0, 45, 90, 135, 180 degrees), a few more with knight moves.
  void build_turn_classes() {
    turn_values_.clear();
    turn_class_.assign(kMoveKinds * kMoveKinds, 0);
    for (int a = 0; a < kMoveKinds; ++a) {
      for (int b = 0; b < kMoveKinds; ++b) {
        const double ta = std::atan2(a % 5 - 2, a / 5 - 2), tb = std::atan2(b % 5 - 2, b / 5 - 2);
        double turn = std::fabs(tb - ta);
        if (turn > M_PI) turn = 2 * M_PI - turn;
        turn /= M_PI;
        turn_class_[a * kMoveKinds + b] = turn_class_of(turn);
      }
    }
  }

  Parameters p_;
  std::vector<std::uint8_t> move_;  // per edge: its move kind (grids and terrains)
  const std::uint8_t* moves_ = nullptr;  // per edge: move_, or the voxel graph's edge_moves
  int kinds_ = kMoveKinds;
  std::vector<double> turn_values_;  // |dtheta| / pi of each turn class
  std::vector<std::uint8_t> turn_class_;  // [previous move kind][move kind] -> turn class
  std::vector<double> factor_;  // [key][turn class] -> (d / (d + gamma * turn))^beta
};

}  // namespace

ACO_PLUGIN(heuristic, direction, DirectionHeuristic, "1.0",
           "paper 001: eta = 1 / (d + gamma * |heading change| / pi), favouring straight moves", kParams)
