#!/usr/bin/env bash
# Opens an acobench HTML report in headless Chromium: the page must load from disk with no
# network, its DOM (after parsing) must hold the plots, and a PNG screenshot is written.
#   tests/report_in_chromium.sh ACOBENCH SOURCE_DIR WORK_DIR
set -euo pipefail
acobench=$1 source=$2 work=$3
source "$(dirname "$0")/chromium.sh"
rm -rf "$work" && mkdir -p "$work"
sed "s|{DATA}|$source/data|g" > "$work/experiment.yaml" <<'YAML'
name: chromium-check
repetitions: 5
problems:
  - map: {DATA}/maps/classic20/map1.txt
    start: [0, 0]
    goal: [19, 19]
settings: {ants: 20, iterations: 40, corner-cutting: true}
baseline: {name: AS}
configurations:
  - {name: ACS, update: {plugin: acs}}
  - {name: MMAS, update: {plugin: max_min}}
  - {name: "003 obstacle-density init + wolf-pack update (a long legend entry)", init: obstacle_density, update: wolf_pack}
ablation: {target: ACS}
YAML
"$acobench" run "$work/experiment.yaml" --db "$work/results.db" >/dev/null
"$acobench" report "$work/results.db" --out "$work/report" >/dev/null
render "file://$work/report/report.html" 1400,3200 "$work/report.png" "$work"
count() { grep -oE "<svg[^>]*class=\"$1\"" "$work/dom.html" | wc -l; }
boxes=$(count boxplot) curves=$(count convergence) maps=$(count paths) anytime=$(count anytime) ecdf=$(count ecdf)
echo "DOM: $boxes box plots, $curves line charts, $anytime gap-against-time/walks charts, $ecdf ECDF charts, $maps path maps; screenshot $work/report.png"
[ "$boxes" -ge 1 ] && [ "$curves" -ge 2 ] && [ "$maps" -ge 1 ] || { echo "plots missing from the DOM" >&2; exit 1; }
[ "$anytime" -eq 2 ] && [ "$ecdf" -eq 2 ] || { echo "anytime charts missing from the DOM" >&2; exit 1; }
grep -q "Ablation path" "$work/dom.html" || { echo "ablation section missing" >&2; exit 1; }
check_screenshot "$work/report.png"
