#!/usr/bin/env bash
# Installs missing packages, configures and builds one CMake preset (default: release).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
tools/setup.sh
# ccache, when installed, gives back what an earlier build compiled: pip install ./python (and
# the test python_pip_install) builds the package's libraries again, in a tree of its own.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake --preset "$preset" "${launcher[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
echo "$0: built build/$preset; its programs are in build/$preset/bin: put them on the PATH with" \
     "'. tools/env.sh'$([ "$preset" = release ] || echo " (ACO_PRESET=$preset . tools/env.sh)")" >&2
