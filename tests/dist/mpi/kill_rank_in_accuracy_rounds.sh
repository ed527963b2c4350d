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
source "$(dirname "$0")/common.sh"
mpi_test_begin
mkdir -p "$tmp/scratch"
export TMPDIR=$tmp/scratch  # the ranks' scratch folders go here
fail() { echo "FAIL ${phase:-}: $*"; exit 1; }

side_lit_room "$tmp/project.yaml" "accuracy: {target_df_relative_stderr_percent: 1}"
sun_room "$tmp/sun" "$source_dir" 1.5 || exit 1

# The phase's project, the pilot's line that starts the kill, the stop line that must not be
# there yet, and round 2's line.
settings() {
  local words=accuracy
  [ $1 = sun ] && { project=$tmp/sun/project.yaml; words='sun accuracy'; } || project=$tmp/project.yaml
  watch="^$words round 1 (pilot): " ended="^$words: " next="^$words round 2: " reference=$tmp/reference-$1
}

for phase in sky sun; do
  settings $phase
  "$dayphoton" run "$project" --output "$reference" --cache "$tmp/reference-cache-$phase" --quiet >/dev/null ||
    fail "the uninterrupted one-process run failed"
  grep -q "$next" "$reference/run.log" || fail "the uninterrupted run took no second round"
done

for phase in sky sun; do
  settings $phase
  for victim in 1 0; do
    out=$tmp/out-$phase-kill$victim
    cache=$tmp/cache-$phase-kill$victim
    start_run_to_kill "$project" "$out" "$cache" "$tmp/$phase-kill$victim.log"
    await_in_job "$victim" "$tmp/$phase-kill$victim.log" "the pilot's line" grep -q "$watch" "$out/run.log"
    kill_rank_expect_incomplete "$victim" "$out"
    grep -q "$ended" "$out/run.log" && fail "rank $victim killed: the rounds ended before the kill (the test killed nothing mid-round)"
    echo "ok   $phase: rank $victim killed in round 2: mpirun exit $rc after ${elapsed}s, folder marked incomplete"

    rerun_completes "$victim" "$project" "$out" "$cache" "$reference"
    left=$(find "$TMPDIR" -maxdepth 1 -name 'dayphoton-rank-*')
    [ -z "$left" ] || fail "rank $victim: scratch folders left after the re-run: $left"
    echo "ok   $phase: re-run: results byte-identical to the uninterrupted run; no scratch folder left"
  done
done
echo "kill_rank_in_accuracy_rounds: all passed"
