#!/usr/bin/env bash
# libFuzzer runs of every loader and parser of hostile input (tests/fuzz/targets.cpp) under
# AddressSanitizer and UndefinedBehaviorSanitizer; builds the "fuzz" preset (clang) first.
#   tools/fuzz.sh short          CI: each harness, one at a time, for a fixed number of executions
#                                (short_runs below, about 15 s each) with a fixed libFuzzer seed,
#                                from its seeds and an empty corpus: the same inputs, so the same
#                                verdict and figures, on every run of the same checkout
#   tools/fuzz.sh long [RUNS]    RUNS executions per harness (default 1000000), two at a time, niced,
#                                random seeds, growing the corpus kept in build/fuzz/corpus/<target>
#   tools/fuzz.sh TARGET [libFuzzer options...]   one harness, e.g. tools/fuzz.sh esri_ascii -runs=1000
#     A slow harness on both cores, sharing one corpus (each job's log is fuzz-N.log here):
#     tools/fuzz.sh experiment -jobs=2 -workers=2 -runs=500000
# FUZZ_TARGETS="esri_ascii pgm_heights" limits short and long runs (and the build) to those.
# Seeds: the small files of data/ of each format, tests/fuzz/corpus/<target>
# and the regression inputs. A crash leaves its input in build/fuzz/crashes/<target>/: fix the
# loader, then keep the input in tests/fuzz/regressions/<target>/, which the test suite replays.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-short}"
shift || true
read -r -a targets <<<"${FUZZ_TARGETS:-movingai_map movingai_scen matrix_map ros_map esri_ascii pgm_heights movingai_voxels voxel_scen ini_config experiment}"
[[ "$mode" =~ ^(short|long)$ ]] || targets=("$mode")
out=build/fuzz
# short's executions per harness, each about 15 s on 2 busy shared cores: a number, not a time,
# so that a slower or busier machine runs the same inputs. A new harness needs its entry.
declare -A short_runs=(
  [movingai_map]=120000 [movingai_scen]=120000 [matrix_map]=250000 [ros_map]=3500 [esri_ascii]=120000
  [pgm_heights]=200000 [movingai_voxels]=120000 [voxel_scen]=120000 [ini_config]=3500 [experiment]=3000
)

# libFuzzer mutates with the operands of the comparisons an input made, and pointers are among
# them: with address randomisation, or another environment above the stack, the same seed tries
# other inputs. So every harness runs with a fixed environment and, where the system allows it,
# without address randomisation.
fixed_addresses=(setarch "$(uname -m)" -R)
if ! "${fixed_addresses[@]}" true 2>/dev/null; then
  echo "fuzz: address randomisation cannot be turned off here (setarch -R): short's runs may differ" >&2
  fixed_addresses=()
fi

tools/setup.sh
cmake --preset fuzz >/dev/null
nice -n 10 cmake --build --preset fuzz -j 2 --target "${targets[@]/#/fuzz_}"

# The seed files of a target's format: small ones only, so each input runs quickly.
seed_files() {
  case "$1" in
    movingai_map) find data/maps data/terrain -name '*.map' ;;
    movingai_scen) find data/maps data/terrain -name '*.scen' ;;
    movingai_voxels) find data/maps/voxel -name '*.3dmap' ;;
    voxel_scen) find data/maps/voxel -name '*.3dscen' ;;
    matrix_map) find data/maps/classic20 -name '*.txt' ;;
    esri_ascii) find data/terrain -name '*.asc' ;;
    ini_config) find data/presets data/scenarios -name '*.ini' ;;
    experiment) find data/experiments -name '*.yaml' ;;
  esac 2>/dev/null | while read -r f; do
    if [ "$(stat -c %s "$f")" -le 65536 ]; then echo "$f"; fi
  done
  for dir in tests/fuzz/corpus/"$1" tests/fuzz/regressions/"$1"; do
    [ -d "$dir" ] && find "$dir" -type f
  done
  return 0
}

# Runs one harness over its seeds, adding what it finds to CORPUS, with extra libFuzzer options;
# its log goes to build/fuzz/logs/<target>.log.
run_target() {
  local target="$1" corpus="$2"
  shift 2
  local seeds="$out/seeds/$target" crashes="$out/crashes/$target"
  rm -rf "$seeds"
  mkdir -p "$seeds" "$corpus" "$crashes" "$out/logs"
  seed_files "$target" | while read -r f; do cp "$f" "$seeds/$(echo "$f" | tr / _)"; done
  # -rss_limit_mb / -malloc_limit_mb: the harness sets a 32 MiB planning-memory limit, so a
  # huge header must be refused, never allocated; 2 GiB means a loader ignored it.
  local status=0
  nice -n 10 env -i PATH=/usr/bin:/bin ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "${fixed_addresses[@]}" "$out/tests/fuzz/fuzz_$target" "$corpus" "$seeds" -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -timeout=20 -print_final_stats=1 -artifact_prefix="$crashes/" "$@" >"$out/logs/$target.log" 2>&1 || status=$?
  echo "$status" >"$out/logs/$target.status"
}

# One line per harness: executions, seconds, coverage and whether it crashed.
summary() {
  local target="$1" status log="$out/logs/$1.log"
  status=$(cat "$out/logs/$target.status")
  local runs seconds
  # With -jobs=J the log holds each job's figures: executions add up, seconds are the longest job's.
  runs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | awk '{n += $2} END {print NR ? n : "?"}')
  seconds=$(grep -o 'Done [0-9]* runs in [0-9]* second' "$log" | awk 'NR == 1 || $5 > s {s = $5} END {print NR ? s : "?"}')
  # Coverage and features reached: with short's fixed inputs, the same on every run.
  local coverage
  coverage=$(grep -o 'DONE *cov: [0-9]* ft: [0-9]*' "$log" | awk '{c = $3; f = $5} END {if (NR == 1) printf ", cov %s ft %s", c, f}')
  if [ "$status" -eq 0 ]; then
    printf 'fuzz: %-14s %10s executions in %5s s%s, no crash\n' "$target" "$runs" "$seconds" "$coverage"
  else
    printf 'fuzz: %-14s FAILED (exit %s), see %s and %s\n' "$target" "$status" "$log" "$out/crashes/$target/"
    return 1
  fi
}

failed=0
case "$mode" in
  short)
    for target in "${targets[@]}"; do
      # A fresh corpus: inputs an earlier run found would change what this one runs. -reload=0:
      # libFuzzer re-reads its corpus folder every second, which makes a run depend on its speed.
      corpus="$out/short-corpus/$target"
      rm -rf "$corpus"
      run_target "$target" "$corpus" -seed=1 -runs="${short_runs[$target]}" -reload=0 "$@"
      rm -rf "$corpus"
      summary "$target" || failed=1
    done
    ;;
  long)
    runs="${1:-1000000}"
    for target in "${targets[@]}"; do
      while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n || true; done
      run_target "$target" "$out/corpus/$target" -runs="$runs" &
    done
    wait
    for target in "${targets[@]}"; do summary "$target" || failed=1; done
    ;;
  *)
    run_target "$mode" "$out/corpus/$mode" "$@"
    summary "$mode" || failed=1
    ;;
esac
exit "$failed"
