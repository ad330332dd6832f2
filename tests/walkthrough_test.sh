#!/usr/bin/env bash
# Runs the shell blocks of docs/writing-plugins.md's "Walk-through" section as written: in order,
# in one shell, from the checkout, with HOME a temporary folder (the walk-through installs into
# ~/aco-sdk and works in ~). The walk-through builds the release preset, so the test runs in that
# preset's build only (elsewhere it reports itself skipped, exit 77).
#   tests/walkthrough_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source=$(cd "$1" && pwd) build=$(cd "$2" && pwd)
if [ "$build" != "$source/build/release" ]; then
  echo "walkthrough: skipped: the walk-through builds build/release, this is $build"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The ```sh blocks between "## Walk-through" and the next "## " heading.
awk '/^## / { inside = ($0 == "## Walk-through") } inside && /^```sh$/ { code = 1; next }
     code && /^```$/ { code = 0; next } code { print }' "$source/docs/writing-plugins.md" > "$work/walkthrough.sh"
[ "$(grep -c . "$work/walkthrough.sh")" -ge 10 ] || { echo "walkthrough: found no walk-through in the doc" >&2; exit 1; }
mkdir "$work/home"
(cd "$source" && HOME="$work/home" bash -euo pipefail "$work/walkthrough.sh") > "$work/log" 2>&1 ||
  { cat "$work/log" >&2; echo "walkthrough: a command of the walk-through failed (above)" >&2; exit 1; }
# What the walk-through says it makes.
[ -x "$work/home/aco-sdk/bin/aco-new-plugin" ]
[ -f "$work/home/my_rule/build/plugins/aco_update_my_rule.so" ]
grep -q "100% tests passed" "$work/log"
grep -q "^aco-plugin-check: [0-9]* checks, 0 failed" "$work/log"
[ -s "$work/home/my_study-report/report.html" ]
grep -q "^--update my_rule --update.value " "$work/home/my_rule-tuning/best-options.txt"
echo "walkthrough: ok"
