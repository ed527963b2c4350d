#!/usr/bin/env bash
# The accuracy rounds over the ranks (study/round_work.h, docs/cluster.md "Accuracy rounds"):
# a daylight-factor study of a small side-lit room with `simulation.accuracy` (target 2 %: the
# pilot reaches about 2.3 %, so a second round is traced), run by one process and under
# `mpirun -np 1`, `-np 2` and `-np 3 --oversubscribe` (and `-np 2` with one thread per rank,
# `--threads 1`), each with a cache of its own. Every
# rank runs the rounds: the pilot's doublings and round 2's extension traced in attempt ranges
# over the ranks, the estimates by sensor blocks (80 sensors, blocks of 16). Every file of the
# results folders must be byte-identical to the one-process run's, apart from run.log and
# timings.json (times) and the output folder's name in summary.json, and so must the cached
# artefacts (the rounds' coefficients and outcome); each run's log must show two rounds.
# Usage: run_accuracy_under_mpirun.sh DAYPHOTON MPIEXEC
set -uo pipefail
dayphoton=$1
mpiexec=$2
source "$(dirname "$0")/common.sh"
mpi_test_begin
export TMPDIR=$tmp  # the other ranks' scratch folders go here
fail=0

side_lit_room "$tmp/project.yaml" "accuracy: {target_df_relative_stderr_percent: 2}"

two_rounds() { grep -q '^accuracy round 2: ' "$1/run.log" && grep -q '^accuracy: target met after 2 round(s)$' "$1/run.log"; }

"$dayphoton" run "$tmp/project.yaml" --output "$tmp/out/serial" --cache "$tmp/cache/serial" --quiet > /dev/null ||
  { echo "the one-process run failed"; exit 1; }
two_rounds "$tmp/out/serial" || { echo "the one-process run did not take two rounds:"; grep accuracy "$tmp/out/serial/run.log"; exit 1; }
for np in 1 2 3 2t1; do
  out=$tmp/out/np$np
  threads=()
  [ $np = 2t1 ] && threads=(--threads 1)
  mpi_run 120 ${np%t1} "$dayphoton" run "$tmp/project.yaml" --output "$out" \
    --cache "$tmp/cache/np$np" --quiet "${threads[@]}" > "$tmp/np$np.log" 2>&1
  rc=$?
  [ $rc -eq 0 ] || { echo "mpirun -np $np: exit $rc"; cat "$tmp/np$np.log"; fail=1; continue; }
  two_rounds "$out" || { echo "mpirun -np $np: not two rounds"; fail=1; }
  if ! same_results "$tmp/out/serial" "$out"; then
    echo "mpirun -np $np wrote other results than the one-process run"
    fail=1
  fi
  if ! same_cache "$tmp/cache/serial" "$tmp/cache/np$np"; then
    echo "mpirun -np $np cached other artefacts than the one-process run"
    fail=1
  fi
  [ $fail -eq 0 ] && echo "ok   mpirun -np $np: two rounds, results and cache byte-identical to the one-process run"
done
exit $fail
