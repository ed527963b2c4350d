#!/usr/bin/env bash
# A rank killed in the middle of the accuracy rounds (study/round_work.h; docs/cluster.md
# "Failures"), in two phases under `mpirun -np 2`, rank 1 and then rank 0 killed by SIGKILL:
#  - sky: a small side-lit room with `simulation.accuracy` at 1 % (the pilot reaches about
#    2.3 %, round 2 traces some 3 times the pilot's photons), killed as soon as rank 0's run.log
#    has the pilot's line (watched, not a fixed sleep): the ranks are then in round 2's tracing;
#  - sun: the annual study of that room in Oakland with `sun: bins` on Reinhart MF 1 at 1.5 %
#    (the sky's rounds end after 2 rounds, the sun bins' pilot reaches about 9 %, rounds 2 and 3
#    trace some 13 and 30 times its attempts), killed as soon as the sun bins' pilot line is in
#    run.log: the ranks are then in the sun rounds' round 2.
# Each time:
#  1. mpirun exits non-zero within 60 s (no rank waits forever for the dead one);
#  2. the results folder is marked incomplete: INCOMPLETE present, no summary.json;
#  3. a re-run under `mpirun -np 2` into the same folder and cache completes the folder with
#     every file byte-identical to an uninterrupted one-process run (run.log and timings.json
#     aside; summary.json apart from the folder name): the rounds are one cached step, so it
#     runs them again;
#  4. no rank's scratch folder is left once the re-run is over.
# Usage: kill_rank_in_accuracy_rounds.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
source_dir=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
tmp=$(mktemp -d)
job=
cleanup() {
  [ -n "$job" ] && kill -9 "$job" 2>/dev/null  # only mpirun started here, if a check failed early
  rm -rf "$tmp"
}
trap cleanup EXIT
mkdir -p "$tmp/scratch"
export TMPDIR=$tmp/scratch  # the ranks' scratch folders go here
fail() { echo "FAIL $*"; exit 1; }

cat > "$tmp/project.yaml" <<'YAML'
version: 1
study: daylight_factor
site: {latitude: 51.5, longitude: -0.12, time_zone: 0}
materials:
  walls: {type: lambertian, reflectance: 0.5}
  glass: {type: glass, transmittance: 0.6}
geometry:
  rooms:
    - name: office
      size: [4, 5, 3]
      materials: {floor: walls, ceiling: walls, walls: walls}
      windows: [{name: w, wall: south, width: 3, height: 1.5, sill: 0.9, material: glass}]
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5}
simulation:
  accuracy: {target_df_relative_stderr_percent: 1}
outputs:
  images: false
  report: false
YAML
mkdir -p "$tmp/sun"
cp "$source_dir/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw" "$tmp/sun/weather.epw" ||
  fail "no weather file in $source_dir/projects/office"
cat > "$tmp/sun/project.yaml" <<'YAML'
version: 1
site: {latitude: 37.72, longitude: -122.22, time_zone: -8}
weather: weather.epw
materials:
  walls: {type: lambertian, reflectance: 0.5}
  glass: {type: glass, transmittance: 0.6}
geometry:
  rooms:
    - name: office
      size: [4, 5, 3]
      materials: {floor: walls, ceiling: walls, walls: walls}
      windows: [{name: w, wall: south, width: 3, height: 1.5, sill: 0.9, material: glass}]
sensors:
  grids:
    - {name: workplane, room: office, height: 0.8, spacing: 0.5}
simulation:
  sun: bins
  sun_mf: 1
  accuracy: {target_df_relative_stderr_percent: 1.5}
outputs:
  images: false
  report: false
YAML

# The phase's project, the pilot's line that starts the kill, the stop line that must not be
# there yet, and round 2's line.
settings() {
  local words=accuracy
  [ $1 = sun ] && { project=$tmp/sun/project.yaml; words='sun accuracy'; } || project=$tmp/project.yaml
  watch="^$words round 1 (pilot): " ended="^$words: " next="^$words round 2: " reference=$tmp/reference-$1
}

for phase in sky sun; do
  settings $phase
  "$dayphoton" run "$project" --output "$tmp/reference-$phase" --cache "$tmp/reference-cache-$phase" --quiet >/dev/null ||
    fail "$phase: the uninterrupted one-process run failed"
  grep -q "$next" "$tmp/reference-$phase/run.log" || fail "$phase: the uninterrupted run took no second round"
done

# The pid of rank $2 of the mpirun $1: its child whose environment says so.
rank_pid() {
  local child
  for child in $(ps -o pid= --ppid "$1"); do
    if tr '\0' '\n' <"/proc/$child/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
      echo "$child"
      return 0
    fi
  done
  return 1
}

for phase in sky sun; do
settings $phase
for victim in 1 0; do
  out=$tmp/out-$phase-kill$victim
  cache=$tmp/cache-$phase-kill$victim
  "$mpiexec" -np 2 --oversubscribe --bind-to none "$dayphoton" run "$project" --output "$out" --cache "$cache" \
    --quiet >"$tmp/$phase-kill$victim.log" 2>&1 &
  job=$!
  for ((i = 0; i < 6000; ++i)); do
    grep -q "$watch" "$out/run.log" 2>/dev/null && break
    kill -0 "$job" 2>/dev/null || fail "$phase: rank $victim: the run ended before the pilot's line: $(cat "$tmp/$phase-kill$victim.log")"
    sleep 0.02
  done
  [ $i -lt 6000 ] || fail "$phase: rank $victim: no pilot line after 120 s"
  pid=$(rank_pid "$job" "$victim") || fail "$phase: rank $victim: its process was not found among mpirun's children"
  kill -9 "$pid"
  start=$(date +%s)
  while kill -0 "$job" 2>/dev/null && [ $(($(date +%s) - start)) -lt 60 ]; do sleep 0.05; done
  kill -0 "$job" 2>/dev/null && fail "$phase: rank $victim killed: mpirun still runs after 60 s"
  wait "$job"
  rc=$?
  job=
  elapsed=$(($(date +%s) - start))
  [ $rc -ne 0 ] || fail "$phase: rank $victim killed: mpirun exited 0"
  grep -q "$ended" "$out/run.log" && fail "$phase: rank $victim killed: the rounds ended before the kill (the test killed nothing mid-round)"
  [ -e "$out/summary.json" ] && fail "$phase: rank $victim killed: the results folder has a summary.json (marked complete)"
  [ -e "$out/INCOMPLETE" ] || fail "$phase: rank $victim killed: the results folder has no INCOMPLETE marker"
  echo "ok   $phase: rank $victim killed in round 2: mpirun exit $rc after ${elapsed}s, folder marked incomplete"

  timeout 300 "$mpiexec" -np 2 --oversubscribe --bind-to none "$dayphoton" run "$project" --output "$out" \
    --cache "$cache" --quiet >"$tmp/$phase-rerun$victim.log" 2>&1 || fail "$phase: rank $victim: the re-run failed: $(cat "$tmp/$phase-rerun$victim.log")"
  [ -e "$out/INCOMPLETE" ] && fail "$phase: rank $victim: the re-run left INCOMPLETE"
  diff -r -q -x run.log -x timings.json -x summary.json "$reference" "$out" ||
    fail "$phase: rank $victim: the re-run wrote other results than the uninterrupted run"
  cmp -s <(sed "s|$reference|OUT|g" "$reference/summary.json") <(sed "s|$out|OUT|g" "$out/summary.json") ||
    fail "$phase: rank $victim: the re-run wrote another summary.json than the uninterrupted run"
  left=$(find "$TMPDIR" -maxdepth 1 -name 'dayphoton-rank-*')
  [ -z "$left" ] || fail "$phase: rank $victim: scratch folders left after the re-run: $left"
  echo "ok   re-run: results byte-identical to the uninterrupted run; no scratch folder left"
done
done
echo "kill_rank_in_accuracy_rounds: all passed"
