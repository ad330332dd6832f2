#!/usr/bin/env bash
# The test command: set up, build and run the whole test suite (default preset: release;
# "tools/test.sh sanitize" runs it under AddressSanitizer and UndefinedBehaviorSanitizer,
# "tools/test.sh tsan" under ThreadSanitizer).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
tools/build.sh "$preset"
ctest --preset "$preset" -j "$(nproc)"
