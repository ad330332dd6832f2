#!/usr/bin/env bash
# The experiment sections of tools/figures.sh (docs/results.md), kept under its old name:
#   tools/results.sh [NAME ...]     default: the papers, ablation, movingai, terrain, generated, dwa
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -gt 0 ] || set -- paper000 paper001 paper002 paper003 paper004 ablation movingai terrain generated dwa
exec tools/figures.sh "$@"
