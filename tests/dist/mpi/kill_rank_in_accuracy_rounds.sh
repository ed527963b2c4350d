#!/usr/bin/env bash
# A rank killed in the middle of the accuracy rounds (study/round_work.h; docs/cluster.md
# "Failures"): a small side-lit room with `simulation.accuracy` at 1 % (the pilot reaches
# about 2.3 %, round 2 traces some 3 times the pilot's photons) under `mpirun -np 2`, with
# rank 1 and then rank 0 killed by SIGKILL as soon as rank 0's run.log has the pilot's line
# (watched, not a fixed sleep): the ranks are then in round 2's tracing. Each time:
#  1. mpirun exits non-zero within 60 s (no rank waits forever for the dead one);
#  2. the results folder is marked incomplete: INCOMPLETE present, no summary.json;
#  3. a re-run under `mpirun -np 2` into the same folder and cache completes the folder with
#     every file byte-identical to an uninterrupted one-process run (run.log and timings.json
#     aside; summary.json apart from the folder name): the rounds are one cached step, so it
#     runs them again;
#  4. no rank's scratch folder is left once the re-run is over.
# Usage: kill_rank_in_accuracy_rounds.sh DAYPHOTON MPIEXEC
set -uo pipefail
dayphoton=$1
mpiexec=$2
source "$(dirname "$0")/common.sh"
mpi_test_begin
mkdir -p "$tmp/scratch"
export TMPDIR=$tmp/scratch  # the ranks' scratch folders go here
fail() { echo "FAIL $*"; exit 1; }

side_lit_room "$tmp/project.yaml" "accuracy: {target_df_relative_stderr_percent: 1}"
project=$tmp/project.yaml

"$dayphoton" run "$project" --output "$tmp/reference" --cache "$tmp/reference-cache" --quiet >/dev/null ||
  fail "the uninterrupted one-process run failed"
grep -q '^accuracy round 2: ' "$tmp/reference/run.log" || fail "the uninterrupted run took no second round"

for victim in 1 0; do
  out=$tmp/out-kill$victim
  cache=$tmp/cache-kill$victim
  start_run_to_kill "$project" "$out" "$cache" "$tmp/kill$victim.log"
  await_in_job "$victim" "$tmp/kill$victim.log" "the pilot's line" grep -q '^accuracy round 1 (pilot): ' "$out/run.log"
  kill_rank_expect_incomplete "$victim" "$out"
  grep -q '^accuracy: ' "$out/run.log" && fail "rank $victim killed: the rounds ended before the kill (the test killed nothing mid-round)"
  echo "ok   rank $victim killed in round 2: mpirun exit $rc after ${elapsed}s, folder marked incomplete"

  rerun_completes "$victim" "$project" "$out" "$cache" "$tmp/reference"
  left=$(find "$TMPDIR" -maxdepth 1 -name 'dayphoton-rank-*')
  [ -z "$left" ] || fail "rank $victim: scratch folders left after the re-run: $left"
  echo "ok   re-run: results byte-identical to the uninterrupted run; no scratch folder left"
done
echo "kill_rank_in_accuracy_rounds: all passed"
