#!/usr/bin/env bash
# Tunes acoplan with irace: prepares TUNING_DIR and runs irace on tools/irace/scenario.txt there.
#   tools/irace/run.sh [--slots SLOTS | --plugin SLOT/NAME | --params FILE [--forbidden FILE]] TUNING_DIR [IRACE_OPTIONS...]
# (installed with the SDK: aco-irace, the same arguments).
# --slots: the slots whose plugin irace chooses (acoplan --irace-slots; default all but local).
# --plugin: only that plugin's parameters, its slot fixed to it (acoplan --irace-plugin).
# --params: a parameter file of your own instead of acoplan's dump (tools/irace/presets has the
# presets'), with its forbidden expressions from --forbidden FILE (default: none).
# IRACE_OPTIONS go to irace as they are, e.g. --max-experiments 200 --parallel 2 --seed 1.
# ACOPLAN, ACOPLAN_OPTIONS: as for target-runner; the parameter file is written by that acoplan
# with those options too, so a --plugin-dir there finds the same plugins. An option set in
# ACOPLAN_OPTIONS is fixed, so its line is taken out of the parameter file (acoplan refuses an
# option given twice).
# Leaves in TUNING_DIR: parameters.txt, forbidden.txt, irace.log (irace's output), irace.Rdata,
# and best-options.txt: the acoplan options of the best configuration, one line (when irace raced).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
usage="usage: $(basename "$0") [--slots SLOTS | --plugin SLOT/NAME | --params FILE [--forbidden FILE]] TUNING_DIR [IRACE_OPTIONS...]"
choice=()
params=""
forbidden="$here/forbidden.txt"
case "${1:-}" in
  --help | -h) echo "$usage"; echo "(tools/irace/README.md, installed as share/aco/irace/README.md, says more)"; exit 0 ;;
  --slots | --plugin | --params)
    [ $# -ge 2 ] || { echo "run.sh: $1 needs a value" >&2; exit 2; }
    case "$1" in
      --slots) choice=(--irace-slots "$2") ;;
      --plugin) choice=(--irace-plugin "$2") ;;
      --params)
        [ -f "$2" ] || { echo "run.sh: no parameter file $2" >&2; exit 2; }
        params="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"
        forbidden=/dev/null ;;
    esac
    shift 2
    if [ -n "$params" ] && [ "${1:-}" = --forbidden ]; then
      [ $# -ge 2 ] && [ -f "$2" ] || { echo "run.sh: --forbidden needs a file" >&2; exit 2; }
      forbidden="$2"
      shift 2
    fi ;;
esac
if [ $# -lt 1 ] || [[ "$1" == -* ]]; then
  echo "$usage" >&2
  exit 2
fi
dir="$1"
shift
# The target runner (irace's child) runs the same acoplan.
export ACOPLAN="${ACOPLAN:-$here/../../build/release/hosts/acoplan/acoplan}"
acoplan="$ACOPLAN"
[ -x "$acoplan" ] || { echo "run.sh: no acoplan at $acoplan: set ACOPLAN, or build the tree (tools/build.sh release)" >&2; exit 1; }
if ! Rscript -e 'library(irace)' >/dev/null 2>&1; then
  echo "run.sh: irace is not installed (tools/setup.sh installs the Debian package r-cran-irace)" >&2
  exit 1
fi
mkdir -p "$dir"
dir="$(cd "$dir" && pwd)"

if [ -n "$params" ]; then
  cp "$params" "$dir/parameters.txt"
else
  # shellcheck disable=SC2086  # the options are words, as target-runner passes them
  "$acoplan" --dump-irace-params "$dir/parameters.txt" "${choice[@]}" ${ACOPLAN_OPTIONS-}
fi
# shellcheck disable=SC2086  # the options are words, as target-runner passes them
for word in ${ACOPLAN_OPTIONS-}; do
  [[ "$word" == --* ]] || continue
  switch="${word%%=*}"
  grep -v -e "\"$switch \"" -e "\"$switch=\"" "$dir/parameters.txt" > "$dir/parameters.tmp" || true
  mv "$dir/parameters.tmp" "$dir/parameters.txt"
done

# irace refuses a forbidden expression naming a parameter the file does not have: keep only the
# expressions about tuned parameters.
names=" $(grep -o '^[A-Za-z][A-Za-z0-9_]*' "$dir/parameters.txt" | tr '\n' ' ') "
: > "$dir/forbidden.txt"
while IFS= read -r line; do
  [[ -z "$line" || "$line" == \#* ]] && continue
  known=1
  for word in $(sed 's/"[^"]*"//g' <<< "$line" | grep -o '[A-Za-z][A-Za-z0-9_]*'); do
    [[ "$names" == *" $word "* ]] || known=0
  done
  ((known)) && echo "$line" >> "$dir/forbidden.txt"
done < "$forbidden"

Rscript -e 'irace::irace.cmdline()' --scenario "$here/scenario.txt" --exec-dir "$dir" \
  --parameter-file "$dir/parameters.txt" --forbidden-file "$dir/forbidden.txt" "$@" | tee "$dir/irace.log"

# irace ends with the elites as command lines, best first: "ID  --switch value ...". A run that
# raced nothing (--check, --help) has none; a failed one stopped above (irace exits non-zero).
best="$(awk '/^# Best configurations as commandlines/ { getline; sub(/^[0-9]+ +/, ""); print; exit }' "$dir/irace.log")"
rm -f "$dir/best-options.txt"
if [ -z "$best" ]; then
  echo "run.sh: irace raced nothing, so there is no best configuration"
  exit 0
fi
echo "$best" > "$dir/best-options.txt"
echo "best configuration as acoplan options (in $dir/best-options.txt):"
echo "$best"
