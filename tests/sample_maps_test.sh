#!/usr/bin/env bash
# The sample maps of data/maps/ros and data/maps/heights are what the commands of their READMEs
# ("How ... made") write: runs those commands as written, with the build's tools and a temporary
# folder for the maps' own, and compares every file byte for byte. Other folders of data/maps
# (octomap) when named.
#   tests/sample_maps_test.sh SOURCE_DIR TOOLS_DIR [FOLDER...]
set -euo pipefail
source=$(cd "$1" && pwd) tools=$(cd "$2" && pwd)
folders=("${@:3}")
((${#folders[@]})) || folders=(ros heights)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for folder in "${folders[@]}"; do
  shipped="$source/data/maps/$folder"
  mkdir "$work/$folder"
  grep -E '^build/release/tools/aco_' "$shipped/README.md" |
    sed -e "s#build/release/tools/#$tools/#" -e "s#data/maps/$folder#$work/$folder#g" > "$work/$folder.sh" ||
    { echo "sample maps: no build/release/tools/aco_... command in $shipped/README.md" >&2; exit 1; }
  (cd "$source" && bash -euo pipefail "$work/$folder.sh" > /dev/null)
  for file in "$shipped"/*; do
    name=$(basename "$file")
    [ "$name" = README.md ] && continue
    [ -f "$work/$folder/$name" ] || { echo "sample maps: $folder/$name is not made by its README's commands" >&2; exit 1; }
    cmp "$work/$folder/$name" "$file" || { echo "sample maps: $folder/$name differs from what its README's commands make" >&2; exit 1; }
  done
done
echo "sample maps: every file reproduced"
