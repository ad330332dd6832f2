#!/usr/bin/env bash
# Installs missing packages, configures and builds one CMake preset (default: release).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
if [ "$preset" = demo ]; then tools/setup.sh --demo; else tools/setup.sh; fi
# ccache, when installed, gives back what an earlier build compiled: pip install ./python (and
# the test python_pip_install) builds the package's libraries again, in a tree of its own.
# Paths relative to the checkout make one preset's objects another's (build/demo's are build/release's).
options=()
if command -v ccache >/dev/null; then
  options=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$PWD"
fi
# CI sets ACO_WARNINGS_AS_ERRORS=ON: a new compiler warning fails it.
if [ -n "${ACO_WARNINGS_AS_ERRORS:-}" ]; then options+=(-DACO_WARNINGS_AS_ERRORS="$ACO_WARNINGS_AS_ERRORS"); fi
cmake --preset "$preset" "${options[@]}" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
[ "$preset" = demo ] && exit 0  # acoplan alone, which tools/demo.sh runs
echo "$0: built build/$preset; its programs are in build/$preset/bin: put them on the PATH with" \
     "'. tools/env.sh'$([ "$preset" = release ] || echo " (ACO_PRESET=$preset . tools/env.sh)")" >&2
