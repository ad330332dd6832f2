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
echo "sdk: ok"
