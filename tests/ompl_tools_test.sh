#!/usr/bin/env bash
# OMPL's own tools on a fresh acobench study (docs/studies.md, "OMPL's tools"): the script of
# Debian's ompl-demos plots a copy (-p) and computes its views (-v); Planner Arena's join of runs
# with plannerConfigs and experiments (its load_database(), as SQL) has no clashing column and
# offers numeric attributes only; an OMPL log appended with -a leaves a database acobench reports
# with OMPL's planners beside ours.
#   tests/ompl_tools_test.sh ACOBENCH OMPL_BENCHMARK_LOG SOURCE_DIR WORK_DIR
set -euo pipefail
acobench=$1 log_writer=$2 source=$3 work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work"
fail() { echo "ompl_tools_test: $*" >&2; exit 1; }
sed "s|{DATA}|$source/data|g" > experiment.yaml <<'YAML'
name: ompl-tools
repetitions: 5
problems:
  - {map: {DATA}/maps/classic20/map1.txt, start: [0, 0], goal: [19, 19]}
  - {scen: {DATA}/maps/classic20/map2.txt.scen}
settings: {ants: 10, iterations: 20}
baseline: {name: AS}
configurations:
  - {name: MMAS, update: max_min}
  - {name: A*, planner: astar}
YAML
"$acobench" run experiment.yaml --db study.db --threads 2 --trial-timeout 60 >/dev/null

# Plots, on a copy: in OMPL 1.5.2, -p FILE would take FILE for a log and delete the database.
cp study.db plots.db
ompl_benchmark_statistics -d plots.db -p > plots.out 2>&1 || { cat plots.out; fail "-p failed"; }
[ -s plots.pdf ] || fail "-p wrote no plots.pdf"
pages=$(/usr/bin/python3 -c "import re,sys; print(len(re.findall(rb'/Type\s*/Page\b', open(sys.argv[1],'rb').read())))" plots.pdf)
# A page per numeric runs column after the ids and the two identities, one per progress column
# after runid and time, and the experiments page.
expected=$(sqlite3 plots.db "SELECT (SELECT count(*) FROM pragma_table_info('runs') WHERE cid >= 3 AND type IN
  ('BOOLEAN', 'ENUM', 'INTEGER', 'REAL')) + (SELECT count(*) FROM pragma_table_info('progress')) - 2 + 1")
echo "ompl_benchmark_statistics -p: plots.pdf, $pages pages (expected $expected)"
[ "$pages" -eq "$expected" ] || fail "plots.pdf has $pages pages, expected $expected"
! grep -q "no available measurements" plots.out || { grep "no available" plots.out; fail "an empty column was plotted"; }
[ "$(sqlite3 plots.db "SELECT count(*) FROM experiments WHERE timelimit = 60 AND runcount = 5")" = 2 ] ||
  fail "experiments' limits not recorded"

ompl_benchmark_statistics -d plots.db -v || fail "-v failed"
best=$(sqlite3 plots.db "SELECT count(*) FROM bestPlannerConfigs")
echo "ompl_benchmark_statistics -v: bestPlannerConfigs has $best rows"
[ "$best" -eq 3 ] || fail "bestPlannerConfigs has $best rows, expected 3"

# Planner Arena's load_database(): runs joined with plannerConfigs (name as planner) and the
# experiments' columns but totaltime..runcount and hostname..setup (id, name renamed).
kept=$(sqlite3 study.db "SELECT group_concat(name, ',') FROM pragma_table_info('experiments') WHERE name NOT IN
  ('totaltime', 'timelimit', 'memorylimit', 'runcount', 'hostname', 'cpuinfo', 'date', 'seed', 'setup')")
clashes=$(sqlite3 study.db "SELECT group_concat(name) FROM pragma_table_info('runs') WHERE name IN ('planner',
  'experiment', 'run.id', 'experiment.id', 'planner.id') OR name IN (SELECT name FROM pragma_table_info('experiments')
  WHERE name NOT IN ('id', 'name', 'totaltime', 'timelimit', 'memorylimit', 'runcount', 'hostname', 'cpuinfo', 'date',
  'seed', 'setup'))")
[ -z "$clashes" ] || fail "runs columns clash in Planner Arena's join: $clashes"
sqlite3 -header study.db "SELECT runs.*, plannerConfigs.name AS planner, experiments.id AS \"experiment.id\",
  experiments.name AS experiment, experiments.version, experiments.optimal_length FROM runs
  JOIN plannerConfigs ON plannerConfigs.id = runs.plannerid JOIN experiments ON experiments.id = runs.experimentid
  LIMIT 1" > arena.txt
attributes=$(head -1 arena.txt | tr '|' '\n' | sed -n '4,$p')
duplicates=$(head -1 arena.txt | tr '|' '\n' | sort | uniq -d)
[ -z "$duplicates" ] || fail "Planner Arena's join repeats columns: $duplicates"
text=$(sqlite3 study.db "SELECT group_concat(name) FROM pragma_table_info('runs') WHERE cid >= 3 AND type NOT IN
  ('BOOLEAN', 'ENUM', 'INTEGER', 'INT', 'REAL')")
[ -z "$text" ] || fail "runs has text attributes: $text"
enums_missing=$(sqlite3 study.db "SELECT group_concat(name) FROM pragma_table_info('runs') WHERE type = 'ENUM' AND
  name NOT IN (SELECT name FROM enums)")
[ -z "$enums_missing" ] || fail "ENUM columns without enums rows: $enums_missing"
echo "Planner Arena's join: $(echo "$attributes" | wc -l) attributes, no clash (experiments columns kept: $kept)"

# An OMPL log of OMPL's own benchmark, appended with OMPL's own -a.
"$log_writer" "$source/data/maps/classic20/map1.txt" 0 0 19 19 ompl.log
cp study.db appended.db
ompl_benchmark_statistics -a -d appended.db ompl.log > append.out 2>&1 || { cat append.out; fail "-a failed"; }
"$acobench" report appended.db --out report >/dev/null || fail "acobench report failed on the appended database"
for planner in geometric_RRTConnect geometric_PRMstar MMAS; do
  grep -q "$planner" report/report.md || fail "the report does not show $planner"
done
grep -q "Planners of appended OMPL logs" report/report.md || fail "no table of the appended planners"
[ "$(sqlite3 appended.db "SELECT count(*) FROM runs")" -eq $((3 * 2 * 5 + 2 * 3)) ] || fail "runs were lost"
echo "ompl_benchmark_statistics -a: acobench report shows geometric_RRTConnect and geometric_PRMstar beside ours"
