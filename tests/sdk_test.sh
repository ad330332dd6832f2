#!/usr/bin/env bash
# SDK check: install the framework, scaffold one out-of-tree plugin of every kind with
# tools/new-plugin.sh, build them against the installed package, and plan with all six (acoplan loads the local one, acosim drives with it).
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" >/dev/null
mkdir -p "$work/plugins"
echo 'cmake_minimum_required(VERSION 3.25)
project(my_plugins LANGUAGES CXX)' > "$work/plugins/CMakeLists.txt"
for kind in init heuristic update deadlock smoother local; do
  "$source/tools/new-plugin.sh" "$kind" "my_$kind" "$work/plugins/$kind" >/dev/null
  echo "add_subdirectory($kind)" >> "$work/plugins/CMakeLists.txt"
done
cmake -S "$work/plugins" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" -j 2 >/dev/null
acoplan="$work/prefix/bin/acoplan"
listed=$("$acoplan" --plugin-dir "$work/build/plugins" --list-plugins)
grep -q "heuristic/my_heuristic  0.1" <<< "$listed"
out=$("$acoplan" --plugin-dir "$work/build/plugins" --init my_init --heuristic my_heuristic --heuristic.value 2 \
      --update my_update --deadlock my_deadlock --smoother my_smoother --local my_local --json)
grep -q '"solved":true' <<< "$out"
grep -q '"heuristic":"my_heuristic","heuristic.value":2.0' <<< "$out"
grep -q '"local":"my_local"' <<< "$out"
# The installed host uses the plugins installed next to it.
described=$("$acoplan" --describe update/max_min)
grep -q "file: $work/prefix/lib/aco/plugins/aco_update_max_min.so" <<< "$described"
# The scaffold refuses to write over a project, warns on a bundled plugin's name, and builds
# optimised when no build type is given.
before=$(cat "$work/plugins/update/my_update.cpp")
if "$source/tools/new-plugin.sh" update my_update "$work/plugins/update" 2>/dev/null; then
  echo "sdk: new-plugin.sh wrote over an existing project" >&2; exit 1
fi
[ "$before" = "$(cat "$work/plugins/update/my_update.cpp")" ]
"$source/tools/new-plugin.sh" update ant_system "$work/shadow" 2>&1 >/dev/null | grep -q "also a bundled plugin"
cmake -S "$work/shadow" -B "$work/shadow/build" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
grep -q "CMAKE_BUILD_TYPE:STRING=Release" "$work/shadow/build/CMakeCache.txt"
echo "sdk: ok"
