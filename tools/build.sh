#!/usr/bin/env bash
# Installs missing packages, configures and builds one CMake preset (default: release).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
tools/setup.sh
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
echo "$0: built build/$preset; its programs are in build/$preset/bin: put them on the PATH with" \
     "'. tools/env.sh'$([ "$preset" = release ] || echo " (ACO_PRESET=$preset . tools/env.sh)")" >&2
