#!/usr/bin/env bash
# The accuracy rounds over the ranks (study/round_work.h, docs/cluster.md "Accuracy rounds"),
# on two projects, each run by one process and under `mpirun -np 1`, `-np 2` and `-np 3
# --oversubscribe` (and `-np 2` with one thread per rank, `--threads 1`), each with a cache of
# its own:
#  - the sky's rounds: a daylight-factor study of a small side-lit room with
#    `simulation.accuracy` (target 2 %: the pilot reaches about 2.3 %, so a second round is
#    traced);
#  - the sun bins' rounds: the annual study of the same room in Oakland with `sun: bins` on
#    Reinhart MF 1 (85 bins, 63 lit) and target 3 %: the sky's pilot meets it (2.3 %), the sun
#    bins' pilot does not (about 9 %), so the sun rounds trace a second round;
#  - a gathered grid in the sun bins' rounds: tests/cli/cases/gathered_sun_accuracy.yaml (a
#    back-wall grid of 18 sensors at 16 gather rays, sun bins on MF 1, draft target 5 %): after
#    the sun's pilot its gather rounds raise its rays (by sensor blocks over the ranks);
#  - a work plane with sensors next to a column (engine/plane_cuts.h, "Sensors next to a cut"):
#    the sun bins' room with a 0.4 m column at x 1.55-1.95, y 2.05-2.45, whose 4 nearest sensors
#    (0.07 m from its corners) are gathered inside the plane's grid in the sky's and the sun's
#    rounds (by sensor blocks over the ranks, their rays seeded by their index in the grid), at
#    4 gather rays, so that after the photon rounds their own gather rounds raise the rays (to 64
#    in the sky's, 64 then 1024 in the sun's: sensor blocks of those rows over the ranks).
# Every rank runs the rounds: the pilot's doublings and round 2's extension traced in attempt
# ranges over the ranks, the estimates by sensor blocks (80 sensors, blocks of 16). Every file
# of the results folders must be byte-identical to the one-process run's, apart from run.log
# and timings.json (times) and the output folder's name in summary.json, and so must the cached
# artefacts (the rounds' coefficients, variances and outcome); each run's log must show the
# two rounds.
# With a fourth argument `points_in_time`, instead: the sun bins' room with two point-in-time
# cases with a sun (a weather hour, a CIE clear sky), whose own sun rounds measure each case's
# illuminance (study/sun_accuracy_rounds.h, SunRoundCase) and trace a second round, and each
# case stated against the target (summary.json `status`).
# Usage: run_accuracy_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR [points_in_time]
set -uo pipefail
dayphoton=$1
mpiexec=$2
source_dir=$3
only=${4:-}
source "$(dirname "$0")/common.sh"
mpi_test_begin
export TMPDIR=$tmp  # the other ranks' scratch folders go here
fail=0

side_lit_room "$tmp/project.yaml" "accuracy: {target_df_relative_stderr_percent: 2}"

sun_room "$tmp/sun" "$source_dir" 3 || exit 1

two_rounds() { grep -q '^accuracy round 2: ' "$1/run.log" && grep -q '^accuracy: target met after 2 round(s)$' "$1/run.log"; }

two_sun_rounds() {
  grep -q '^accuracy: target met after 1 round(s)$' "$1/run.log" && grep -q '^sun accuracy round 2: ' "$1/run.log" &&
    grep -q '^sun accuracy: target met after 2 round(s)$' "$1/run.log"
}

# check NAME PROJECT ROUNDS_CHECK: the project by one process, then under mpirun.
check() {
  local name=$1 project=$2 rounds=$3 base=$tmp/out/$1 np out rc
  "$dayphoton" run "$project" --output "$base/serial" --cache "$tmp/cache/$name/serial" --quiet > /dev/null ||
    { echo "$name: the one-process run failed"; fail=1; return; }
  $rounds "$base/serial" || { echo "$name: the one-process run did not take the expected rounds:"; grep accuracy "$base/serial/run.log"; fail=1; return; }
  for np in 1 2 3 2t1; do
    out=$base/np$np
    local threads=()
    [ $np = 2t1 ] && threads=(--threads 1)
    mpi_run 120 ${np%t1} "$dayphoton" run "$project" --output "$out" \
      --cache "$tmp/cache/$name/np$np" --quiet "${threads[@]}" > "$tmp/$name-np$np.log" 2>&1
    rc=$?
    [ $rc -eq 0 ] || { echo "$name: mpirun -np $np: exit $rc"; cat "$tmp/$name-np$np.log"; fail=1; continue; }
    local ok=1
    $rounds "$out" || { echo "$name: mpirun -np $np: not the expected rounds"; ok=0; }
    same_results "$base/serial" "$out" || { echo "$name: mpirun -np $np wrote other results than the one-process run"; ok=0; }
    same_cache "$tmp/cache/$name/serial" "$tmp/cache/$name/np$np" ||
      { echo "$name: mpirun -np $np cached other artefacts than the one-process run"; ok=0; }
    [ $ok -eq 1 ] && echo "ok   $name: mpirun -np $np: the expected rounds, results and cache byte-identical to the one-process run"
    [ $ok -eq 1 ] || fail=1
  done
}

if [ "$only" = points_in_time ]; then
  sun_room "$tmp/cases" "$source_dir" 3 || exit 1
  cat >> "$tmp/cases/project.yaml" <<'YAML'
points_in_time:
  - {name: weather_sun, date: 12-21, time: "12:00", sky: weather}
  - {name: clear, date: 12-21, time: "10:30", sky: cie, cie_type: 12, direct_normal_illuminance: 80000}
YAML
  case_rounds() {
    grep -q '^point in time sun accuracy round 2: .*point-in-time illuminance relative standard error' "$1/run.log" &&
      grep -q '^point in time workplane weather_sun: relative standard error (95th percentile) ' "$1/run.log" &&
      grep -q '"status": "' "$1/summary.json"
  }
  check points_in_time "$tmp/cases/project.yaml" case_rounds
  exit $fail
fi

check sky "$tmp/project.yaml" two_rounds
check sun "$tmp/sun/project.yaml" two_sun_rounds

gathered_sun_rounds() {
  grep -q '^sun accuracy gather round 1, grid back_wall: ' "$1/run.log" &&
    grep -q '^sun accuracy: target met after 1 round(s)$' "$1/run.log"
}
check gathered_sun "$source_dir/tests/cli/cases/gathered_sun_accuracy.yaml" gathered_sun_rounds

sun_room "$tmp/column" "$source_dir" 3 || exit 1
sed -i 's/^      windows: \[{name: w, .*$/&\n  boxes:\n    - {name: column, origin: [1.55, 2.05, 0], size: [0.4, 0.4, 3], material: walls}/' "$tmp/column/project.yaml"
sed -i 's/^  accuracy: {target_df_relative_stderr_percent: 3}$/&\n  gather_rays: 4/' "$tmp/column/project.yaml"
grep -q '^    - {name: column, ' "$tmp/column/project.yaml" || { echo "column: the box was not added"; exit 1; }
grep -q '^  gather_rays: 4$' "$tmp/column/project.yaml" || { echo "column: the gather rays were not set"; exit 1; }
near_cut_rounds() {
  grep -q '^accuracy round 1 (pilot): .*; 4 sensors next to a cut, gathered after the photon rounds' "$1/run.log" &&
    grep -q '^sun accuracy round 1 (pilot): .*; 4 sensors next to a cut, gathered after the photon rounds' "$1/run.log" &&
    grep -q "^accuracy workplane: .*; 4 sensors next to a cut gathered, largest .* at 64 gather rays" "$1/run.log" &&
    grep -q "^accuracy gather round 1, grid workplane's 4 sensors next to a cut: " "$1/run.log" &&
    grep -q "^sun accuracy gather round 2, grid workplane's 4 sensors next to a cut: " "$1/run.log"
}
check near_cut "$tmp/column/project.yaml" near_cut_rounds
exit $fail
