#!/usr/bin/env bash
# One paper's contribution against plain ant_system, with the paper's own parameters, over 30
# seeds (1-30): the traditional colony, each of the paper's plugins alone, and all of them
# together. Prints mean, standard deviation, min and max of length, cells, turns, best iteration
# and iterations run for every configuration.
#   tools/paper-experiment.sh 000|001|002|003|004 [SCENARIO]
# SCENARIO defaults to the paper's look-alike map (data/maps/papers/, data/terrain/); any Moving
# AI .scen file works, e.g. data/maps/classic20/map1.txt.scen. Paper 000 runs its three terrains
# (20x20, 30x30, 50x50) unless a SCENARIO is given. Results and their discussion:
# data/experiments/README.md. The traditional colony is --preset ant-system, the paper's whole
# pipeline --preset paperNNN (data/presets/).
set -euo pipefail
cd "$(dirname "$0")/.."
acoplan=build/release/hosts/acoplan/acoplan
[ -x "$acoplan" ] || tools/build.sh release >/dev/null
paper=${1:-}
seeds=30

run() {
  local title=$1
  shift
  echo "== $paper $title"
  echo "   acoplan $*"
  "$acoplan" --repeat "$seeds" "$@" | sed -n '/^runs:/,$p' || true
  echo
}

case "$paper" in
  000)
    # 50 ants, 100 iterations, alpha 1, beta 7; EPF-ACO: q0 0.8, local evaporation 0.1, global
    # 0.2, repulsion range 2, 16-neighbourhood, bidirectional search. Classic ACO: Ant System
    # with the same evaporation on the 8-neighbourhood. PSO: 50 particles, 100 iterations.
    seeds=${SEEDS:-20}
    for scen in ${2:-data/terrain/epf20.asc.scen data/terrain/epf30.asc.scen data/terrain/epf50.asc.scen}; do
      common=(--scen "$scen" --preset ant-system --ants 50 --iterations 100 --alpha 1 --beta 7)
      run "$scen: PSO (50 particles, 100 iterations)" --scen "$scen" --planner pso
      run "$scen: classic ACO (ant_system rho 0.2)" "${common[@]}" --update.rho 0.2
      run "$scen: EPF-ACO (potential-field init + heuristic, elite, bidirectional, 16-nbhd)" --scen "$scen" --preset paper000
    done
    ;;
  001)
    # m = 20 ants, N = 200 iterations, alpha = beta = 1, stop when 90 % of an iteration's ants
    # follow the same path.
    common=(--scen "${2:-data/maps/papers/paper001.map.scen}" --preset ant-system --corner-cutting --ants 20 --iterations 200 --alpha 1 --beta 1
            --same-path-stop --same-path-fraction 0.9)
    run "traditional ACO (ant_system, distance heuristic, stuck ants dropped)" "${common[@]}"
    run "direction heuristic" "${common[@]}" --heuristic direction
    run "ant death with backtrack penalty" "${common[@]}" --deadlock backtrack_penalty
    run "improved: direction heuristic + backtrack penalty" --scen "${2:-data/maps/papers/paper001.map.scen}" --preset paper001
    ;;
  002)
    # M = 50, alpha 1, beta 7, rho 0.3, Q 1, 100 iterations; psi 300, mu 0, sigma 1.
    common=(--scen "${2:-data/maps/papers/paper002.map.scen}" --preset ant-system --corner-cutting --ants 50 --iterations 100 --alpha 1 --beta 7)
    gaussian=(--update gaussian --update.psi 300 --update.mu 0 --update.sigma 1 --update.rho 0.3 --update.q 1)
    run "traditional ACO (ant_system rho 0.3 Q 1)" "${common[@]}" --update.rho 0.3 --update.q 1
    run "Gaussian deposition" "${common[@]}" "${gaussian[@]}"
    run "deadlock clearing with tabu set" "${common[@]}" --update.rho 0.3 --update.q 1 --deadlock clear_and_tabu
    run "improved: Gaussian deposition + deadlock clearing" --scen "${2:-data/maps/papers/paper002.map.scen}" --preset paper002
    ;;
  003)
    # Traditional / improved: N_max 100/100, m 50/50, alpha 1/1, beta 15/13.7, Q 1/10,
    # rho 0.95/0.35, lambda -/0.05; then the secondary optimisation (prune).
    common=(--scen "${2:-data/maps/papers/paper003_20.map.scen}" --preset ant-system --corner-cutting --ants 50 --iterations 100 --alpha 1)
    traditional=(--beta 15 --update.rho 0.95 --update.q 1)
    wolf=(--update wolf_pack --update.q 10 --update.rho 0.35 --update.lambda 0.05)
    run "traditional ACO (ant_system, beta 15, rho 0.95, Q 1)" "${common[@]}" "${traditional[@]}"
    run "obstacle-density init" "${common[@]}" "${traditional[@]}" --init obstacle_density
    run "adaptive heuristic" "${common[@]}" "${traditional[@]}" --heuristic adaptive
    run "wolf-pack update (beta 13.7)" "${common[@]}" --beta 13.7 "${wolf[@]}"
    run "improved: all three (beta 13.7)" "${common[@]}" --beta 13.7 --init obstacle_density --heuristic adaptive "${wolf[@]}"
    run "improved + secondary optimisation (prune)" --scen "${2:-data/maps/papers/paper003_20.map.scen}" --preset paper003
    ;;
  004)
    # IFWA: 50 generations, 15 fireworks, 10 mutation sparks, m 5, radius 3, a 0.3, b 0.5.
    # ACO alone: 50 iterations, 50 ants, alpha 1, beta 3, rho 0.5, Q 5. Hybrid: the fireworks'
    # best path seeds the pheromone, then 50 iterations, 50 ants, alpha 2, beta 8, rho 0.9, Q 1,
    # dead-end ants back off.
    scen=${2:-data/terrain/paper004.map.scen}
    run "IFWA alone" --scen "$scen" --preset ant-system --corner-cutting --planner ifwa
    run "ACO alone (ant_system)" --scen "$scen" --preset ant-system --corner-cutting --ants 50 --iterations 50 --alpha 1 --beta 3 \
      --update.rho 0.5 --update.q 5
    run "hybrid: fireworks-seeded ACO with backtracking" --scen "$scen" --preset paper004
    ;;
  *)
    echo "usage: $0 000|001|002|003|004 [SCENARIO]" >&2
    exit 2
    ;;
esac
