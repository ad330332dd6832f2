#!/usr/bin/env bash
# aco-plugin-check must fail, naming plugin, parameters and check, on plugins that break its
# rules: tests/fixtures/nonconforming_update.cpp (not deterministic; NaN at q = 10; refuses
# rho = 0, which its range admits), lingering_update.cpp (keeps per-run state across runs) and
# throwing_update.cpp (throws 42 from its factory when asked; throws in iteration 3, as Context::iteration, by default)
# and flat_init.cpp (claims voxel worlds but measures steps in the plane: fails in 3D only).
#   tests/plugin_check_catches_test.sh ACO_PLUGIN_CHECK FAULTY_PLUGIN_DIR
set -euo pipefail
check=$1 dir=$2
expect_failures() {  # FILE LINE...: the checker exits 1 and prints every LINE (a regex)
  local file=$1 out status=0
  shift
  out=$("$check" "$file") || status=$?
  [ "$status" = 1 ] || { echo "plugin-check: exit $status on $file, expected 1" >&2; exit 1; }
  for line in "$@"; do
    grep -q "$line" <<< "$out" || { echo "plugin-check: no line '$line' for $file in:" >&2; echo "$out" >&2; exit 1; }
  done
}
expect_failures "$dir/aco_update_nonconforming.so" \
  '^FAIL update/nonconforming \[defaults\] deterministic: ' \
  '^FAIL update/nonconforming \[defaults\] threads: 1 vs 4 threads: ' \
  '^FAIL update/nonconforming \[q=10\] values: .*nan' \
  '^PASS update/nonconforming \[q=0\] values$' \
  '^FAIL update/nonconforming \[rho=0\] constructs: refused rho=0, which its declared range 0:1 admits (evaporation must be positive); declare the range (0:1 or accept the value$'
# Not claiming voxel worlds: not run in 3D, said once, not a failure.
expect_failures "$dir/aco_update_nonconforming.so" \
  '^SKIP update/nonconforming \[defaults\] 3D: not run in 3D: it does not claim voxel worlds (supports_voxel_worlds() is false)$'
[ "$("$check" "$dir/aco_update_nonconforming.so" | grep -c ' 3D')" = 1 ]
# Claiming them and failing there: the 2D checks pass, the 3D values check fails, saying where.
expect_failures "$dir/aco_init_flat.so" \
  '^PASS init/flat \[defaults\] values$' \
  '^PASS init/flat \[defaults\] reused$' \
  '^FAIL init/flat \[defaults\] 3D values: voxels: tau after initialize()\[[0-9]*\] = inf (must be finite and > 0) (and [0-9]* more) \[in a voxel world cells have z and moves dz: use cost(e), reverse_edge(e) and position(n)\]$' \
  '^PASS init/flat \[defaults\] 3D deterministic$' \
  '^PASS init/flat \[defaults\] 3D threads$' \
  '^PASS init/flat \[defaults\] 3D reused$'
expect_failures "$dir/aco_update_lingering.so" \
  '^PASS update/lingering \[defaults\] deterministic$' \
  '^FAIL update/lingering \[defaults\] reused: a second run of the same object, after runs on other maps, differs from its first: '
expect_failures "$dir/aco_update_throwing.so" \
  '^FAIL update/throwing \[in_factory=true\] constructs: the factory threw an exception of type int' \
  '^FAIL update/throwing \[defaults\] values: .*failed in update() in iteration 3 (0-based, as Context::iteration): an exception of type int' \
  '^PASS update/throwing \[at_iteration=-1\] deterministic$'
# A folder: every plugin library in it, one that cannot load among them, and the failures listed
# again after the count.
expect_failures "$dir" \
  '^FAIL .*/aco_update_incomplete.so loads: .*undefined symbol' \
  '^PASS update/throwing \[at_iteration=-1\] deterministic$' \
  '^aco-plugin-check: [0-9]* checks, [0-9]* failed$' \
  '^  FAIL update/nonconforming \[rho=0\] constructs: '
"$check" --version | grep -q "^aco-plugin-check [0-9.]* (commit "
echo "plugin-check: catches what it must"
