#!/usr/bin/env bash
# SDK check: install the framework into a temporary prefix, then with the installed tools only:
# scaffold one out-of-tree plugin of every slot with aco-new-plugin, build them and run their
# generated unit tests, build examples/ against the prefix and run their tests, run
# aco-plugin-check on the example and on every installed bundled plugin, and plan with all of
# them in installed acoplan (acosim's local slot included), and link the installed libraries
# (aco::simulation, aco::studies) into a program of its own. The installed host must find the
# installed plugins and data only, never the build tree's.
#   tests/sdk_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
unset ACO_PLUGIN_PATH
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
bin="$prefix/bin"
# The SDK of a sanitizer build (presets sanitize, tsan) is instrumented: out-of-tree code is built
# with the same flags, as its users would, so the sanitizer's runtime is linked first.
flags=()
for variable in CMAKE_CXX_FLAGS CMAKE_EXE_LINKER_FLAGS CMAKE_SHARED_LINKER_FLAGS CMAKE_MODULE_LINKER_FLAGS; do
  value=$(sed -n "s/^$variable:[A-Z]*=//p" "$build/CMakeCache.txt")
  if [ -n "$value" ]; then flags+=("-D$variable=$value"); fi
done
for tool in acoplan aco-new-plugin aco-plugin-check aco-irace; do
  [ -x "$bin/$tool" ] || { echo "sdk: $tool is not installed in bin/" >&2; exit 1; }
  [ -n "$("$bin/$tool" --help)" ] || { echo "sdk: $tool --help printed nothing" >&2; exit 1; }
done

# One scaffold of every slot, built together, each with its generated unit test.
mkdir -p "$work/plugins"
printf 'cmake_minimum_required(VERSION 3.25)\nproject(my_plugins LANGUAGES CXX)\nenable_testing()\n' > "$work/plugins/CMakeLists.txt"
for slot in init heuristic update deadlock smoother local map; do
  "$bin/aco-new-plugin" "$slot" "my_$slot" "$work/plugins/$slot" >/dev/null
  echo "add_subdirectory($slot)" >> "$work/plugins/CMakeLists.txt"
done
cmake -S "$work/plugins" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null
cmake --build "$work/build" -j 2 >/dev/null
ctest --test-dir "$work/build" --output-on-failure > "$work/scaffold-tests.log" || { cat "$work/scaffold-tests.log" >&2; exit 1; }
grep -q "100% tests passed, 0 tests failed out of 14" "$work/scaffold-tests.log"
# Each Catch2 case is a ctest test labelled with its tags: the conformance case of each slot.
[ "$(ctest --test-dir "$work/build" -N -L conformance | grep -c "Test *#")" = 7 ]
[ "$(ctest --test-dir "$work/build" -N -L update | grep -c "Test *#")" = 2 ]

# The example plugin, against the installed package, with its own unit test.
cmake -S "$source/examples/rank_based_as" -B "$work/rank_based_as" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null
cmake --build "$work/rank_based_as" -j 2 >/dev/null
ctest --test-dir "$work/rank_based_as" --output-on-failure >/dev/null
example="$work/rank_based_as/plugins/aco_update_rank_based_as.so"

# The example map plugin, map/shapes, against the installed package with its unit test; then its
# format in the three hosts: acoplan, an acobench experiment (problem keys map-format and
# map.resolution) and an acosim scenario. Each run solves.
cmake -S "$source/examples/shapes_map" -B "$work/shapes_map" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null
cmake --build "$work/shapes_map" -j 2 >/dev/null
ctest --test-dir "$work/shapes_map" --output-on-failure >/dev/null
shapes="$work/shapes_map/plugins"
# (Outputs kept in variables: grep -q stopping early would break the pipe of a program still writing.)
checked=$("$bin/aco-plugin-check" "$shapes/aco_map_shapes.so")
grep -q "^PASS map/shapes \[defaults\] values" <<< "$checked"
listed=$("$bin/acoplan" --plugin-dir "$shapes" --list-plugins)
grep -q "^  map/shapes  0.1" <<< "$listed"
out=$("$bin/acoplan" --plugin-dir "$shapes" --map "$source/examples/shapes_map/room.shapes" --start 0,0 --goal 19,15 --json)
grep -q '"solved":true' <<< "$out"
grep -q '"map-format":"shapes","map.resolution":0.5' <<< "$out"
cp "$source"/examples/shapes_map/room* "$work/"
"$bin/acobench" run "$work/room_experiment.yaml" --plugin-dir "$shapes" --db "$work/room.db" > "$work/room.log"
[ "$(sqlite3 "$work/room.db" "SELECT COUNT(*) || ' ' || SUM(solved) FROM runs")" = "8 8" ]
# The report draws the maps again with the plugin (found through --plugin-dir or ACO_PLUGIN_PATH).
for finds_plugin in "--plugin-dir $shapes" "ACO_PLUGIN_PATH=$shapes"; do
  rm -rf "$work/room-report"
  if [ "${finds_plugin%%=*}" = ACO_PLUGIN_PATH ]; then
    ACO_PLUGIN_PATH="$shapes" "$bin/acobench" report "$work/room.db" --out "$work/room-report" >/dev/null
  else
    "$bin/acobench" report "$work/room.db" --out "$work/room-report" --plugin-dir "$shapes" >/dev/null
  fi
  if grep -q "map not drawn" "$work/room-report/report.html"; then
    echo "sdk: the report did not draw the shapes map (plugin found through $finds_plugin)" >&2
    exit 1
  fi
done
# Without the plugin the report still comes, saying why the map is missing.
"$bin/acobench" report "$work/room.db" --out "$work/room-report-bare" >/dev/null
grep -q "map not drawn" "$work/room-report-bare/report.html"
out=$("$bin/acosim" "$work/room_scenario.yaml" --plugin-dir "$shapes" --json)
grep -q '"outcome":"reached"' <<< "$out"

# The conformance checks on the example and on every installed bundled plugin.
"$bin/aco-plugin-check" "$example" > "$work/check-example.log"
grep -q "^PASS update/rank_based_as \[w=1\] threads" "$work/check-example.log"
# One process per plugin, as the suite's conformance_* tests run them (under ThreadSanitizer, one
# process over all plugins once reported TBB's task hand-off unsymbolised, so unsuppressed).
# (aco_*.so: the python plugins' helper library beside them, libaco_python_bridge.so, is none.)
for plugin in "$prefix"/lib/aco/plugins/aco_*.so; do
  "$bin/aco-plugin-check" "$plugin" >> "$work/check-bundled.log" ||
    { grep -v "^PASS" "$work/check-bundled.log" >&2; exit 1; }
done
[ "$(grep -c "^PASS update/ant_system \[defaults\] [a-z]*$" "$work/check-bundled.log")" = 4 ]  # values, deterministic, threads, reused
# ... the same four in voxel worlds for a plugin that claims them; one that does not is not run there.
[ "$(grep -c "^PASS update/ant_system \[defaults\] 3D [a-z]*$" "$work/check-bundled.log")" = 4 ]
grep -q "^SKIP smoother/taut \[defaults\] 3D: not run in 3D: " "$work/check-bundled.log"

# Planning with the installed host: the six scaffolds, then the example.
acoplan="$bin/acoplan"
listed=$("$acoplan" --plugin-dir "$work/build/plugins" --list-plugins)
grep -q "heuristic/my_heuristic  0.1" <<< "$listed"
out=$("$acoplan" --plugin-dir "$work/build/plugins" --init my_init --heuristic my_heuristic --heuristic.value 2 \
      --update my_update --deadlock my_deadlock --smoother my_smoother --local my_local --json)
grep -q '"solved":true' <<< "$out"
grep -q '"heuristic":"my_heuristic","heuristic.value":2.0' <<< "$out"
grep -q '"local":"my_local"' <<< "$out"
out=$("$acoplan" --plugin-dir "$work/rank_based_as/plugins" --update rank_based_as --update.w 4 --json)
grep -q '"solved":true' <<< "$out"
grep -q '"update":"rank_based_as","update.q":1.0,"update.rho":0.1,"update.w":4' <<< "$out"
# The example's own figure (Context::add()) in --json, the summary, and an acobench study's
# database, runs.csv and report, beside IFWA's evaluations.
grep -q '"update/rank_based_as.ranked_deposits":[1-9]' <<< "$out"
summary=$("$acoplan" --plugin-dir "$work/rank_based_as/plugins" --update rank_based_as)
grep -q "^figures:  .*update/rank_based_as.ranked_deposits [1-9]" <<< "$summary"
cat > "$work/figures.yaml" <<YAML
name: figures
seed: 1
repetitions: 2
problems:
  - {map: $prefix/share/aco/maps/classic20/map1.txt, start: [0, 0], goal: [19, 19]}
settings: {ants: 10, iterations: 5}
baseline: {name: ranked, update: rank_based_as}
configurations:
  - {name: fireworks, planner: ifwa, ifwa.iterations: 5}
YAML
"$bin/acobench" run "$work/figures.yaml" --db "$work/figures.db" --plugin-dir "$work/rank_based_as/plugins" >/dev/null
"$bin/acobench" report "$work/figures.db" --out "$work/figures-report" >/dev/null
query() { /usr/bin/python3 -c 'import sqlite3, sys; print(sqlite3.connect(sys.argv[1]).execute(sys.argv[2]).fetchone()[0])' "$work/figures.db" "$1"; }
[ "$(query "SELECT count(*) FROM properties WHERE name = 'update/rank_based_as.ranked_deposits' AND value > 0")" = 2 ]
[ "$(query "SELECT count(*) FROM properties WHERE name = 'evaluations' AND value > 0")" = 2 ]
head -1 "$work/figures-report/runs.csv" | grep -q ",evaluations,optimal_corridor_walked,update/rank_based_as.ranked_deposits$"
grep -q "^| ranked | update/rank_based_as.ranked_deposits | 2 |" "$work/figures-report/report.md"
grep -q "^| ranked | update | rank_based_as | 1.0 | optimised | [0-9a-f]\{64\} | $work/rank_based_as/plugins/aco_update_rank_based_as.so |$" \
  "$work/figures-report/report.md"
# The python plugins, when built: the installed helper library runs a Python class, the example
# Ant System, which plans as the native plugin does.
if [ -e "$prefix/lib/aco/plugins/aco_update_python.so" ]; then
  out=$("$acoplan" --update python --update.class ant_system:AntSystem --update.path "$source/examples/python" --json)
  grep -q '"update":"python","update.class":"ant_system:AntSystem"' <<< "$out"
  grep -q "\"file\":\"$prefix/lib/aco/plugins/aco_update_python.so\"" <<< "$out"
  length() { grep -o '"length":[^,]*' <<< "$1"; }
  [ "$(length "$out")" = "$(length "$("$acoplan" --update ant_system --json)")" ]
fi

# The installed host uses the plugins and data installed with it, and nothing of the build tree:
# every plugin it lists is an installed file, the folders it searches are the installed one and
# the ones it was given, and its default map is the installed copy.
files=$("$acoplan" --list-plugins | sed -n 's/.*  \(\/.*\.so\)$/\1/p')
[ -n "$files" ]
if grep -v "^$prefix/lib/aco/plugins/" <<< "$files"; then echo "sdk: installed acoplan lists plugins outside its prefix" >&2; exit 1; fi
described=$("$acoplan" --describe update/max_min)
grep -q "file: $prefix/lib/aco/plugins/aco_update_max_min.so" <<< "$described"
searched=$("$acoplan" --update no_such_rule 2>&1 >/dev/null || true)
grep -q "searched: $prefix/lib/aco/plugins)" <<< "$searched"
if grep -q "$build" <<< "$searched"; then echo "sdk: installed acoplan searches the build tree: $searched" >&2; exit 1; fi
(cd "$work" && "$acoplan" --iterations 2 --json) | grep -q "\"map\":\"$prefix/share/aco/maps/classic20/map1.txt\""
# Its named presets are the installed ones (--preset NAME, and the default a bare command runs).
presets=$("$acoplan" --list-presets)
grep -q "files in $prefix/share/aco/presets" <<< "$presets"
grep -q "^  paper001  " <<< "$presets"
(cd "$work" && "$acoplan" --preset paper001 --print-config) | grep -q "^heuristic = direction"

# irace tunes an out-of-tree plugin's parameter with the installed SDK alone: bin/aco-irace, its
# --plugin-dir given in ACOPLAN_OPTIONS as the target runner passes it (it must reach the
# parameter dump too: my_update is found only there). Small budget: one race, a few seconds.
export ACOPLAN_OPTIONS="--threads 1 --ants 10 --iterations 10 --plugin-dir $work/build/plugins"
(unset ACOPLAN; cd "$work" && PATH="$bin:/usr/bin:/bin" aco-irace --plugin update/my_update "$work/tuning" \
   --max-experiments 40 --iterations 1 --parallel 2 --seed 1 > "$work/irace.log" 2>&1) ||
  { cat "$work/irace.log" >&2; echo "sdk: aco-irace failed" >&2; exit 1; }
grep -qx 'update "--update " c (my_update)' "$work/tuning/parameters.txt"
grep -q '^update_value "--update.value " r (0.0001, 100)$' "$work/tuning/parameters.txt"
! grep -q '^ants \|^heuristic ' "$work/tuning/parameters.txt"
tuned=$(cat "$work/tuning/best-options.txt")
[[ "$tuned" == "--update my_update --update.value "* ]] || { echo "sdk: irace's best configuration: $tuned" >&2; exit 1; }
# shellcheck disable=SC2086  # the options are words
"$bin/acoplan" $ACOPLAN_OPTIONS $tuned --json | grep -q '"update":"my_update","update.value":'
unset ACOPLAN_OPTIONS

# The scaffold refuses to write over a project, warns on a bundled plugin's name (installed and
# in the checkout), and builds optimised when no build type is given.
before=$(cat "$work/plugins/update/my_update.cpp")
if "$bin/aco-new-plugin" update my_update "$work/plugins/update" 2>/dev/null; then
  echo "sdk: aco-new-plugin wrote over an existing project" >&2; exit 1
fi
[ "$before" = "$(cat "$work/plugins/update/my_update.cpp")" ]
"$bin/aco-new-plugin" update ant_system "$work/shadow" 2>&1 >/dev/null | grep -q "also a bundled plugin"
"$source/tools/new-plugin.sh" update ant_system "$work/shadow2" 2>&1 >/dev/null | grep -q "also a bundled plugin"
cmake -S "$work/shadow" -B "$work/shadow/build" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null
grep -q "CMAKE_BUILD_TYPE:STRING=Release" "$work/shadow/build/CMakeCache.txt"
# The libraries beside libaco, exported by find_package(aco), as a host of one's own uses them.
# examples/study_host (docs/architecture.md's "adding a host") runs a study through aco::studies
# into its own results database and report; a program of the test's runs a simulation through
# aco::simulation; both with the installed plugins and data, as acobench and acosim would.
share="$prefix/share/aco"
cmake -S "$source/examples/study_host" -B "$work/study_host" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null
cmake --build "$work/study_host" -j 2 >/dev/null
"$work/study_host/study_host" "$share/experiments/paper001.yaml" "$work/study_host.db" "$work/study_host-report" \
  > "$work/study_host.log"
grep -q "^ran 210 trials (0 already stored), 0 failed$" "$work/study_host.log"
# docs/architecture.md shows the example as it is.
awk '/^## / { inside = ($0 == "## Adding a host") } inside && /^```cpp$/ { code = 1; next }
     code && /^```$/ { code = 0; next } code { print }' "$source/docs/architecture.md" |
  diff - "$source/examples/study_host/study_host.cpp"
grep -q "^wrote .*/report.html$" "$work/study_host.log"
[ -s "$work/study_host-report/report.html" ]
# The same trials as the installed acobench stores.
"$bin/acobench" run "$share/experiments/paper001.yaml" --db "$work/acobench.db" >/dev/null
"$bin/acobench" report "$work/acobench.db" --out "$work/acobench-report" >/dev/null
trials() { cut -d, -f1-11 "$1/runs.csv"; }  # up to time_s
[ "$(trials "$work/study_host-report")" = "$(trials "$work/acobench-report")" ]
mkdir -p "$work/library_user"
cat > "$work/library_user/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.25)
project(library_user LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(aco REQUIRED)
add_executable(library_user main.cpp)
target_link_libraries(library_user PRIVATE aco::simulation)
CMAKE
cat > "$work/library_user/main.cpp" <<'CPP'
#include <iostream>

#include "aco/engine/plugin_registry.hpp"
#include "aco/simulation/simulation.hpp"

int main(int, char** argv) {
  aco::PluginRegistry registry(aco::PluginRegistry::default_search_dirs());
  const aco::simulation::Scenario scenario = aco::simulation::load_scenario(argv[1], registry);
  std::cout << aco::simulation::summary_json(scenario, aco::simulation::simulate(scenario, registry), registry) << "\n";
}
CPP
cmake -S "$work/library_user" -B "$work/library_user/build" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null
cmake --build "$work/library_user/build" -j 2 >/dev/null
"$work/library_user/build/library_user" "$share/scenarios/paper003_static.yaml" > "$work/library_user.log"
grep -q '"outcome":"reached"' "$work/library_user.log"
# The same simulation as the installed acosim's.
[ "$(cat "$work/library_user.log")" = "$("$bin/acosim" "$share/scenarios/paper003_static.yaml" --json)" ]

# The installed Python package (when the build has it), from outside the checkout, with the
# installed plugins: a run on a numpy grid, and the same run as the installed acoplan's.
site=$(find "$prefix" -type d -path "*/site-packages/aco" | head -1)
python=$(sed -n 's/^ACO_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
# A sanitizer build's module needs the ASan and UBSan runtimes preloaded into Debian's python3,
# which has neither: ctest names them in ACO_PYTHON_PRELOAD (tests/CMakeLists.txt, its sanitizer
# section), and the interpreter runs without leak checks, as the test python_package does.
python_env=()
if [ -n "${ACO_PYTHON_PRELOAD:-}" ]; then
  python_env=("LD_PRELOAD=$ACO_PYTHON_PRELOAD" "ASAN_OPTIONS=detect_leaks=0:abort_on_error=0")
fi
if [ -n "$site" ]; then
  (cd "$work" && env "${python_env[@]}" PYTHONPATH="$(dirname "$site")" "$python" - "$prefix" <<'PY'
import json, subprocess, sys
import numpy as np
import aco
prefix = sys.argv[1]
assert aco.__file__.startswith(prefix), aco.__file__
assert aco.plan(np.zeros((20, 20), bool), (0, 0), (19, 19), seed=2).solved
mine = aco.plan(prefix + "/share/aco/maps/classic20/map1.txt", (0, 0), (19, 19), seed=2, threads=1).json
theirs = json.loads(subprocess.run([prefix + "/bin/acoplan", "--seed", "2", "--threads", "1", "--json"],
                                   capture_output=True, text=True, check=True).stdout)
for run in (mine, theirs):
    run.pop("time_ms"), run.pop("convergence_time_s")
assert mine == theirs
assert mine["plugins"]["update"]["file"].startswith(prefix)
PY
  )
fi

echo "sdk: ok"
