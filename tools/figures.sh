#!/usr/bin/env bash
# Regenerates the figures the pages of docs/ quote (docs/benchmarks.md, docs/results.md, ...) and the pictures in docs/images/,
# section by section: each section replaces only its own regions (between
# <!-- figures:NAME begin ... --> and <!-- figures:NAME end -->) and stamps them with the machine,
# its load, the date, the commit and the commands it ran.
#   tools/figures.sh --list              the sections, and about how long each takes
#   tools/figures.sh engine pictures     those sections only
#   tools/figures.sh                     every section (the experiments take hours)
# The experiment sections keep their databases in build/results/<name>.db and resume them.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  --list|-h|--help) ;;
  *) if [ -d build/release ]; then nice -n 10 cmake --build build/release -j"$(nproc)" >/dev/null
     else tools/build.sh release >/dev/null; fi ;;
esac
# The sections are the package tools/figures/.
exec env PYTHONPATH=tools /usr/bin/python3 -m figures "$@"
