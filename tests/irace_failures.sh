#!/usr/bin/env bash
# irace with configurations whose plugin crashes or hangs (the hostile test plugins): through
# tools/irace/target-runner each such evaluation costs a failure, is logged with the plugin hook,
# and irace goes on to its elites (a runner that printed anything but the cost would stop it).
#   tests/irace_failures.sh ACOPLAN SOURCE_DIR WORK_DIR HOSTILE_PLUGIN_DIR
set -euo pipefail
acoplan=$(realpath "$1") source=$(realpath "$2") work=$3 hostile=$(realpath "$4")
fail() { echo "irace failures: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work"
export ACOPLAN="$acoplan" ACOPLAN_TIMEOUT=1
export ACOPLAN_OPTIONS="--threads 1 --ants 10 --iterations 20 --corner-cutting --plugin-dir $hostile"
# at_iteration 0 to 19 (Context::iteration): every crashing or hanging configuration fails within acoplan's 20
# iterations.
cat > "$work/parameters.txt" <<'PARAMETERS'
update "--update " c (crashing, hanging, acs)
at "--update.at_iteration " i (0, 19) | update %in% c("crashing", "hanging")
PARAMETERS
: > "$work/forbidden.txt"
Rscript -e 'irace::irace.cmdline()' --scenario "$source/tools/irace/scenario.txt" --exec-dir "$work" \
  --parameter-file "$work/parameters.txt" --forbidden-file "$work/forbidden.txt" \
  --max-experiments 100 --parallel 2 --seed 1 > "$work/irace.log" 2>&1 ||
  { cat "$work/irace.log"; fail "irace stopped"; }
grep -q '^# Best configurations as commandlines' "$work/irace.log" || { cat "$work/irace.log"; fail "no elite configurations"; }
log="$work/target-runner-failures.log"
[ -f "$log" ] || fail "no failure log in irace's execution directory"
grep -q ': crashed: SIGSEGV (acoplan: error: crashed: SIGSEGV in plugin update/crashing (.*) in update() in iteration [0-9]* (0-based, as Context::iteration))$' "$log" ||
  { cat "$log"; fail "no crash logged with its plugin hook"; }
grep -q ': timed out after 1 s (acoplan: error: stopped: SIGUSR1 in plugin update/hanging (.*) in update() in iteration [0-9]* (0-based, as Context::iteration))$' "$log" ||
  { cat "$log"; fail "no time-out logged with its plugin hook"; }
echo "irace ended with its elites; $(grep -c '^configuration' "$log") failed evaluations logged"
