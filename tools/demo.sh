#!/usr/bin/env bash
# The main job: set up, build, and plan on the bundled classic map (extra arguments go to acoplan).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh release >/dev/null
exec build/release/hosts/acoplan/acoplan "$@"
