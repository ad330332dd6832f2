#!/usr/bin/env bash
# tools/irace/tune-preset.sh prepares the presets' tuning on generated maps and irace accepts it
# (--check: irace reads the scenario, the parameter file and the forbidden expressions, and runs
# two configurations): robust's 69 instances from aco_mapgen --benchmark at 64 cells and more,
# terrain's 24 from aco_terraingen with A*'s lengths, only terrain's search has `search`,
# robust-any-angle has robust's instances and adds walk-length, robust-corridors adds the building
# families (99 instances) and starts from the preset's own configuration, and voxel has 30
# instances on generated voxel worlds.
#   tests/irace_tune_preset.sh ACOPLAN SOURCE_DIR WORK_DIR
set -euo pipefail
acoplan=$1 source=$2 work=$3
fail() { echo "tune-preset: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
export ACOPLAN="$acoplan"
for preset in robust robust-any-angle robust-corridors terrain voxel; do
  "$source/tools/irace/tune-preset.sh" "$preset" "$work/$preset" --check > "$work/$preset.log" 2>&1 ||
    { cat "$work/$preset.log"; fail "$preset: tune-preset.sh failed"; }
  grep -q "Check successful" "$work/$preset.log" || { cat "$work/$preset.log"; fail "$preset: irace's check failed"; }
done
[ "$(wc -l < "$work/robust/instances.txt")" -eq 69 ] || fail "robust: $(wc -l < "$work/robust/instances.txt") instances, not 69"
! grep -qE '/[a-z]+32-' "$work/robust/instances.txt" || fail "robust: a 32x32 map among the instances"
grep -q '/hall512-64-s4243.map.scen --scen-index 19$' "$work/robust/instances.txt" || fail "robust: no hall instance"
[ "$(wc -l < "$work/terrain/instances.txt")" -eq 24 ] || fail "terrain: not 24 instances"
grep -q '^search ' "$work/terrain/parameters.txt" || fail "terrain: the search is not tuned"
! grep -q '^search ' "$work/robust/parameters.txt" || fail "robust: the search is tuned"
grep -q '^walk_length ' "$work/robust-any-angle/parameters.txt" || fail "robust-any-angle: walk-length is not tuned"
! grep -q '^walk_length ' "$work/robust/parameters.txt" || fail "robust: walk-length is tuned"
cmp -s "$work/robust/instances.txt" <(sed "s|/robust-any-angle/|/robust/|" "$work/robust-any-angle/instances.txt") ||
  fail "robust-any-angle: not robust's instances"
[ "$(wc -l < "$work/robust-corridors/instances.txt")" -eq 99 ] ||
  fail "robust-corridors: $(wc -l < "$work/robust-corridors/instances.txt") instances, not 99"
for family in office256-12 office512-25 8room512 doors256-16 doors512-32; do
  grep -q "/$family-s4243.map.scen --scen-index 19$" "$work/robust-corridors/instances.txt" ||
    fail "robust-corridors: no $family instance"
done
grep -q '^colonies ' "$work/robust-corridors/parameters.txt" || fail "robust-corridors: colonies are not tuned"
grep -q 'target-runner 1 .* --colonies 1 --restart-after 0 --goal-memory=false --update max_min --update.rho 0.3 --update.p_best 0.05 --update.restart_after 0 --q0 0.7 --band-search 16"' "$work/robust-corridors.log" ||
  fail "robust-corridors: irace did not run the preset's configurations"
# Each terrain scenario's length is A*'s on its terrain.
read -r _ map _ _ sx sy gx gy length < <(sed -n 2p "$work/terrain/maps/hills40-s4242.asc.scen")
astar="$("$acoplan" --planner astar --map "$work/terrain/maps/$map" --start "$sx,$sy" --goal "$gx,$gy" --json |
  /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["length"])')"
[ "$astar" = "$length" ] || fail "terrain scenario length $length, A* $astar"
# voxel: 30 instances on generated voxel worlds of other seeds than the bundled ones.
[ "$(wc -l < "$work/voxel/instances.txt")" -eq 30 ] || fail "voxel: not 30 instances"
! grep -q -- '-s1.3dmap' "$work/voxel/instances.txt" || fail "voxel: a bundled world's seed among the instances"
echo "tune-preset.sh: robust, robust-any-angle, robust-corridors, terrain and voxel prepared, irace's check passed"
