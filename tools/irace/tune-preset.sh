#!/usr/bin/env bash
# Tunes a recommended pipeline with irace on generated training maps, never on the bundled ones:
#   tools/irace/tune-preset.sh robust|robust-any-angle|robust-corridors|terrain|voxel TUNING_DIR [IRACE_OPTIONS...]
# robust, the 2D preset: `aco_mapgen --benchmark` maps of seed TUNE_SEED (default 4242; the
# bundled ones are seed 1), every family at 64 cells a side and more (random, room, maze: 64 and
# 512; cave and hall: 256 and 512), scenarios 9, 14 and 19 of each (the middle and the long half).
# terrain, the height-map preset: aco_terraingen hills of 40, 64, 100 and 128 cells a side (three
# seeds each from TUNE_SEED), corner to corner both ways.
# voxel, the voxel-world preset: aco_mapgen --voxel cities, forests and caves of 48x48x24 (two
# seeds each from TUNE_SEED; the bundled worlds are seed 1 at 64x64x32), five scenarios each, with
# the 26-neighbourhood. VOXEL_KINDS (default "city forest caves") and VOXEL_SIZE (default
# 48x48x24) choose other worlds, e.g. caves only, where pipelines' gaps differ.
# robust-any-angle: robust's maps, judged by the final path: the preset's taut smoother runs and a
# run costs its final path's gap to the exact any-angle optimum (--irace-cost
# any-angle-gap-penalised); the search adds presets/any-angle.params (line-of-sight walks).
# robust-corridors: robust's maps and the building families (aco_mapgen's office, 8room and doors
# of the same seeds), the robust preset as it is plus presets/corridors.params (islands, epochs,
# goal memory, MAX-MIN's restarts, the band search: docs/corridors.md), starting from the preset,
# the preset before issue 52 and two colonies (presets/corridors.configurations).
# The others search presets/common.params (terrain adds presets/terrain.params) on top of
# presets/fixed.ini, with acoplan --irace-cost gap-penalised (a run costs its gap g in % plus g
# squared, so the worst runs count) --irace-effort TUNE_EFFORT (default 0.25 times the ants'
# moves per walk over the optimal length: time, which the effort follows, counts too, and the
# preset must also fit its time on maps 16 times larger than the training maps) and irace's
# t-test, which races on those costs (its default Friedman test ranks them, and a rank cannot
# tell a 5 % gap from a 0.5 % one).
# Leaves in TUNING_DIR what run.sh does (irace.log, irace.Rdata, best-options.txt), the maps and
# instances.txt. ACOPLAN names the acoplan to tune (run.sh); give it an installed copy
# (cmake --install build/release --prefix DIR) to go on building the tree while irace runs.
# docs/learning-findings.md has the runs and their results, e.g.
#   tools/irace/tune-preset.sh robust /tmp/tune-robust --max-experiments 5000 --parallel 2 --seed 1
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
usage="usage: $(basename "$0") robust|robust-any-angle|robust-corridors|terrain|voxel TUNING_DIR [IRACE_OPTIONS...]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
preset="$1"
dir="$2"
shift 2
mkdir -p "$dir/maps"
dir="$(cd "$dir" && pwd)"
seed="${TUNE_SEED:-4242}"
cost=gap-penalised
final=()
base=(--config "$dir/fixed.ini")  # what every candidate keeps
first=()  # irace's first candidates
acoplan="${ACOPLAN:-$root/build/release/hosts/acoplan/acoplan}"
: > "$dir/instances.txt"
case "$preset" in
  robust | robust-any-angle | robust-corridors)
    [ -e "$dir/maps/hall512-64-s$((seed + 1)).map.scen" ] ||
      "$root/build/release/tools/aco_mapgen" --benchmark "$dir/maps" "$seed" > "$dir/maps.log"
    [ "$preset" != robust-corridors ] || [ -e "$dir/maps/doors512-32-s$((seed + 1)).map.scen" ] ||
      "$root/build/release/tools/aco_mapgen" --benchmark "$dir/maps" "$seed" office,8room,doors >> "$dir/maps.log"
    for scen in "$dir"/maps/*.map.scen; do
      [[ "$(basename "$scen")" =~ ^[a-z]+32- ]] && continue  # the 32x32 maps: every pipeline solves them
      for index in 9 14 19; do echo "$scen --scen-index $index" >> "$dir/instances.txt"; done
    done
    cp "$here/presets/common.params" "$dir/search.params"
    if [ "$preset" = robust-any-angle ]; then
      cost=any-angle-gap-penalised
      final=(--smoother taut)  # fixed.ini's smoother is none: the grid gap does not need one
      cat "$here/presets/any-angle.params" >> "$dir/search.params"
    fi
    if [ "$preset" = robust-corridors ]; then
      cp "$here/presets/corridors.params" "$dir/search.params"
      base=(--preset robust --smoother none)
      first=(--configurations-file "$here/presets/corridors.configurations")
    fi ;;
  terrain)
    for size in 40 64 100 128; do
      for s in 0 1 2; do
        terrain="$dir/maps/hills$size-s$((seed + s)).asc"
        [ -e "$terrain" ] || "$root/build/release/tools/aco_terraingen" --width "$size" --height "$size" \
          --seed "$((seed + s))" --hills "$((size / 3))" --out "$terrain" > /dev/null
        # A Moving AI scenario file for the terrain (acoplan's --scen reads its map): both
        # diagonals, each with A*'s length on the terrain's graph.
        {
          echo "version 1"
          last=$((size - 1))
          for problem in "0 0 $last $last" "0 $last $last 0"; do
            read -r sx sy gx gy <<< "$problem"
            length="$("$acoplan" --planner astar --map "$terrain" --start "$sx,$sy" --goal "$gx,$gy" --json |
              /usr/bin/python3 -c 'import json, sys; print(json.load(sys.stdin)["length"])')"
            printf '0\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$(basename "$terrain")" "$size" "$size" "$sx" "$sy" "$gx" "$gy" "$length"
          done
        } > "$terrain.scen"
        for index in 0 1; do echo "$terrain.scen --scen-index $index" >> "$dir/instances.txt"; done
      done
    done
    cat "$here/presets/common.params" "$here/presets/terrain.params" > "$dir/search.params" ;;
  voxel)
    size="${VOXEL_SIZE:-48x48x24}"
    for kind in ${VOXEL_KINDS:-city forest caves}; do
      for s in 0 1; do
        world="$dir/maps/${kind}${size}-s$((seed + s)).3dmap"
        [ -e "$world.3dscen" ] ||
          "$root/build/release/tools/aco_mapgen" --voxel "$kind" "$size" "$((seed + s))" "$dir/maps" 5 > /dev/null
        for index in 0 1 2 3 4; do echo "$world.3dscen --scen-index $index" >> "$dir/instances.txt"; done
      done
    done
    cp "$here/presets/common.params" "$dir/search.params"
    final=(--neighbourhood 26) ;;
  *) echo "tune-preset.sh: no search space for preset '$preset' (robust, robust-any-angle, robust-corridors, terrain or voxel)" >&2; exit 2 ;;
esac
# Copies in TUNING_DIR: the tuning reads nothing of the tree while it runs.
cp "$here/presets/fixed.ini" "$dir/fixed.ini"
export ACOPLAN_OPTIONS="--threads 1 ${base[*]} ${final[*]} --irace-cost $cost --irace-effort ${TUNE_EFFORT:-0.25}"
export ACOPLAN_TIMEOUT="${ACOPLAN_TIMEOUT:-60}"
exec "$here/run.sh" --params "$dir/search.params" --forbidden "$here/presets/budget.forbidden" "$dir" \
  --train-instances-dir / --train-instances-file "$dir/instances.txt" --test-type t-test "${first[@]}" "$@"
