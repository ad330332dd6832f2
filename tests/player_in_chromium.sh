#!/usr/bin/env bash
# Opens acosim's HTML player in headless Chromium: the page must load from disk with no network,
# and opened with #final its script must show the last frame: the time label at the run's time
# and the robot where the trajectory ends. A PNG screenshot is written.
#   tests/player_in_chromium.sh ACOSIM SOURCE_DIR WORK_DIR
set -euo pipefail
acosim=$1 source=$2 work=$3
source "$(dirname "$0")/chromium.sh"
rm -rf "$work" && mkdir -p "$work"
"$acosim" "$source/data/scenarios/paper003_static.yaml" --html "$work/player.html" --json > "$work/run.json"
# What the last frame must show: the time (one decimal) and the robot's centre in pixels
# (24 per cell, 12 margin).
read -r time x y < <(python3 -c "
import json; j = json.load(open('$work/run.json')); f = j['trajectory'][-1]
print(round(f['t'] * 10) / 10, 12 + (f['x'] + 0.5) * 24, 12 + (f['y'] + 0.5) * 24)")
render "file://$work/player.html#final" 560,720 "$work/player.png" "$work"
shown=$(grep -oE '<span id="time">[^<]*</span>' "$work/dom.html" | sed -E 's/<[^>]*>//g')
cx=$(grep -oE '<circle id="robot-body"[^>]*>' "$work/dom.html" | grep -oE 'cx="[^"]*"' | cut -d'"' -f2)
cy=$(grep -oE '<circle id="robot-body"[^>]*>' "$work/dom.html" | grep -oE 'cy="[^"]*"' | cut -d'"' -f2)
echo "final frame: time '$shown' (run: $time s), robot at ($cx, $cy) (trajectory ends at ($x, $y))"
python3 -c "
import sys
shown, time, cx, cy, x, y = '$shown', float('$time'), float('${cx:-nan}'), float('${cy:-nan}'), float('$x'), float('$y')
ok = abs(float(shown.split()[0]) - time) < 1e-6 and abs(cx - x) < 1e-6 and abs(cy - y) < 1e-6
sys.exit(0 if ok else 1)" || { echo "the player does not show the final frame" >&2; exit 1; }
check_screenshot "$work/player.png"
echo "player: ok ($work/player.png)"
