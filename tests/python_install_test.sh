#!/usr/bin/env bash
# README.md's pip install of the package (python/pyproject.toml) into a fresh venv, offline, then
# the examples run with the venv's python from another folder: the installed package with its own
# libraries, plugins and data, nothing of the checkout's build tree.
#   tests/python_install_test.sh SOURCE_DIR CMAKE_BUILD_DIR PYTHON
# CMAKE_BUILD_DIR keeps pip's CMake build (ACO_CMAKE_BUILD_DIR) between runs, so that a later run
# compiles only what changed; pip's own build folder is a temporary one, out of the checkout.
set -euo pipefail
unset ACO_PLUGIN_PATH PYTHONPATH
source=$1 cmake_build=$2 python=$3  # the interpreter the build's package is for
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "python install: $*" >&2; exit 1; }

"$python" -m venv --system-site-packages "$work/v"
ACO_CMAKE_BUILD_DIR="$cmake_build" ACO_SETUPTOOLS_BUILD_DIR="$work/setuptools" \
  "$work/v/bin/pip" install --no-build-isolation --no-index "$source/python" > "$work/pip.log" 2>&1 ||
  { cat "$work/pip.log" >&2; fail "pip install failed"; }
grep -q "^Successfully installed aco-" "$work/pip.log" || { cat "$work/pip.log" >&2; fail "pip did not install aco"; }

mkdir "$work/elsewhere"
cd "$work/elsewhere"
site=$("$work/v/bin/python" -c "import sysconfig; print(sysconfig.get_path('platlib'))")
# The package, and every plugin it finds, are the venv's.
"$work/v/bin/python" - "$site" <<'PYTHON' || fail "the installed package is not the venv's alone"
import sys, aco
site = sys.argv[1]
assert aco.__file__.startswith(site), aco.__file__
outside = [p["file"] for p in aco.plugins() if not p["file"].startswith(site)]
assert not outside, outside
assert aco.presets(), "no presets: the package's data is missing"
PYTHON
"$work/v/bin/python" "$source/examples/python/plan_numpy_grid.py" grid.png > plan.out || fail "plan_numpy_grid.py failed"
grep -q "^<aco.Result length" plan.out || fail "plan_numpy_grid.py printed: $(cat plan.out)"
[ "$(head -c 4 grid.png | tail -c 3)" = PNG ] || fail "plan_numpy_grid.py wrote no PNG picture"
# A study whose update plugin is a Python class: the python bridge plugins, installed.
"$work/v/bin/python" "$source/examples/python/compare_bwas.py" bwas.db > study.out 2> study.err ||
  { cat study.err >&2; fail "compare_bwas.py failed"; }
grep -q "ran 20 trials, 0 failed" study.out || fail "compare_bwas.py printed: $(cat study.out)"
echo "python install: pip installed aco $("$work/v/bin/python" -c 'import aco; print(aco.__version__)') into a venv; its examples ran"
