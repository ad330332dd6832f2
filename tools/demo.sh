#!/usr/bin/env bash
# The main job: set up, build, and plan on the bundled classic map (extra arguments go to acoplan).
# It installs and builds only what acoplan and the plugins need (the preset demo); tools/test.sh
# builds the rest.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/build.sh demo >/dev/null
exec build/demo/hosts/acoplan/acoplan "$@"
