#!/usr/bin/env bash
# The C++ sources in the project's style (.clang-format, Debian's clang-format-14).
#   tools/format.sh           formats every .cpp and .hpp in place
#   tools/format.sh --check   changes nothing; fails naming each file that is not formatted (CI)
set -euo pipefail
cd "$(dirname "$0")/.."
clang_format=clang-format-14
command -v "$clang_format" >/dev/null || { echo "format: $clang_format is missing (tools/setup.sh installs it)" >&2; exit 2; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else
  mapfile -t files < <(find . -path ./build -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print | sort)
fi
if [ "${1:-}" = "--check" ]; then
  "$clang_format" --dry-run --Werror "${files[@]}"
  echo "format: ${#files[@]} files formatted as .clang-format says"
else
  "$clang_format" -i "${files[@]}"
fi
