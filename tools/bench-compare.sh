#!/usr/bin/env bash
# The engine benchmark of this checkout against another commit, run in turn (base, this, base,
# this, ...) so that both see the same machine load:
#   tools/bench-compare.sh REV [ROUNDS] [aco_bench options...]
#   tools/bench-compare.sh HEAD~3 5 --only classic
# Builds REV's aco_bench and plugins in build/compare-<commit> (a detached worktree), this
# checkout's with tools/build.sh, then prints, per table row, the median over the rounds of the
# row's first figure (median ms, or ns per ant step) for both and their ratio (this / base).
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:?usage: tools/bench-compare.sh REV [ROUNDS] [aco_bench options...]}
shift
rounds=5
if [[ ${1:-} =~ ^[0-9]+$ ]]; then rounds=$1; shift; fi
commit=$(git rev-parse --short "$rev^{commit}")
base=build/compare-$commit
tools/build.sh release >/dev/null
if [ ! -e "$base/src/.git" ]; then
  rm -rf "$base"
  git worktree add --detach "$base/src" "$commit" >/dev/null
fi
# A commit from before data/maps/movingai held the large maps read them from ACO_SHARED_DATA_DIR.
cmake -S "$base/src" -B "$base/build" -DCMAKE_BUILD_TYPE=Release -DACO_BUILD_TESTS=OFF -DACO_BUILD_PYTHON=OFF \
  -DACO_WITH_MPI=OFF -DACO_SHARED_DATA_DIR="$PWD/data/maps" --no-warn-unused-cli >/dev/null
plugins=$(cmake --build "$base/build" --target help | grep -oE 'aco_(init|heuristic|update|deadlock|smoother|local)_[a-z_]+' |
  sort -u | tr '\n' ' ')
# shellcheck disable=SC2086
cmake --build "$base/build" -j "$(nproc)" --target aco_bench $plugins >/dev/null
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for ((r = 1; r <= rounds; ++r)); do
  "$base/build/bench/aco_bench" "$@" >"$out/base.$r"
  build/release/bench/aco_bench "$@" >"$out/this.$r"
done
echo "aco_bench $* : $rounds rounds in turn; medians over rounds of each row's first figure"
echo "base $commit ($(git log -1 --format=%cs "$commit")), this $(git rev-parse --short HEAD)$(git diff --quiet HEAD || echo ' + changes')"
python3 - "$out" "$rounds" <<'EOF'
import re, statistics, sys
folder, rounds = sys.argv[1], int(sys.argv[2])
def rows(file):
    found, section = [], ""
    for line in open(file):
        if line.startswith("=="):
            section = line.strip("= \n")[:60]
            continue
        fields = line.split()
        if len(fields) >= 2 and re.fullmatch(r"[0-9.]+", fields[1]):
            found.append(((section, fields[0]), float(fields[1])))
    return found
figures = {}
order = []
for side in ("base", "this"):
    for r in range(1, rounds + 1):
        for key, value in rows(f"{folder}/{side}.{r}"):
            if key not in figures:
                figures[key] = {"base": [], "this": []}
                order.append(key)
            figures[key][side].append(value)
section = None
for key in order:
    if key[0] != section:
        section = key[0]
        print(f"\n{section}\n{'row':28} {'base':>10} {'this':>10} {'ratio':>7}")
    b, t = figures[key]["base"], figures[key]["this"]
    if not b or not t:
        continue
    mb, mt = statistics.median(b), statistics.median(t)
    print(f"{key[1]:28} {mb:10.2f} {mt:10.2f} {mt / mb if mb else float('nan'):7.3f}")
EOF
