#!/usr/bin/env bash
# A real irace run through tools/irace/run.sh with a small budget: it must end with an elite
# configuration, whose options acoplan must accept and solve a problem with. irace missing is a
# failure, not a skip: tools/setup.sh installs it.
#   tests/irace_run.sh ACOPLAN SOURCE_DIR WORK_DIR
set -euo pipefail
acoplan=$1 source=$2 work=$3
fail() { echo "irace run: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
export ACOPLAN="$acoplan"
export ACOPLAN_OPTIONS="--threads 1 --ants 10 --iterations 20 --corner-cutting"
# --iterations 2 (irace's, not acoplan's): fewer races, so this small budget is enough.
"$source/tools/irace/run.sh" --slots update,heuristic "$work/tuning" \
  --max-experiments 150 --iterations 2 --parallel 2 --seed 1 > "$work/run.log" 2>&1 ||
  { cat "$work/run.log"; fail "tools/irace/run.sh failed"; }
log="$work/tuning/irace.log"

parameters="$work/tuning/parameters.txt"
grep -q '^update ' "$parameters" && grep -q '^heuristic_floor ' "$parameters" || fail "update or heuristic not tuned"
! grep -q '^ants \|^iterations ' "$parameters" || fail "--ants or --iterations tuned although ACOPLAN_OPTIONS fixes them"
grep -q '^# Best configurations (first number is the configuration ID' "$log" || fail "no elite configurations in $log"
# The best one's mean cost: below the penalty of an unsolved run (1e9), so it solved every instance it ran on.
mean=$(sed -n 's/^Best-so-far configuration: *[0-9]* *mean value: *\([0-9.e+]*\).*/\1/p' "$log" | tail -1)
echo "best mean cost: $mean"
awk -v m="$mean" 'BEGIN { exit !(m != "" && m > 0 && m < 1e9) }' || fail "best mean cost '$mean' is not a solved run's"

options=$(cat "$work/tuning/best-options.txt") || fail "run.sh wrote no best-options.txt"
echo "best configuration: $options"
[[ "$options" == *"--update "* && "$options" == *"--heuristic "* ]] || fail "best configuration has no plugin choice"
# shellcheck disable=SC2086  # the options are words
"$acoplan" --scen "$source/data/maps/classic20/map2.txt.scen" --seed 7 $ACOPLAN_OPTIONS $options --json > "$work/check.json" ||
  fail "acoplan refused or did not solve with the best configuration"
grep -q '"solved": *true' "$work/check.json" || fail "acoplan's JSON does not say solved"
