#!/usr/bin/env bash
# distribute_jobs under Open MPI's mpirun (tests/dist/mpi/distribute_jobs_check.cpp):
#  1. the bytes delivered (to rank 0, and to every rank) are identical without mpirun and with
#     -np 1, 2 and 3 (3 oversubscribes a 2-core machine);
#  2. a job throwing on rank 1 of 3 ends every rank with "rank 1, job J (job J): deliberate failure
#     on rank 1" and mpirun exits non-zero;
#  3. a rank killed by SIGKILL makes mpirun exit non-zero promptly, not hang (time-out 60 s).
# Usage: run_mpi_test.sh PROGRAM MPIEXEC
set -uo pipefail
program=$1
mpiexec=$2
source "$(dirname "$0")/common.sh"
mpi_test_begin
fail=0

env -u OMPI_COMM_WORLD_SIZE "$program" results > "$tmp/serial.out" 2>&1 || { echo "serial run failed"; cat "$tmp/serial.out"; exit 1; }
root=$(grep '^root digest' "$tmp/serial.out")
every=$(grep '^every-rank digest' "$tmp/serial.out")
case "$root $every" in *"in_order 1"*"in_order 1") ;; *) echo "serial run out of order: $root / $every"; fail=1 ;; esac
for np in 1 2 3; do
  mpi_run 60 "$np" "$program" results > "$tmp/np$np.out" 2>&1
  rc=$?
  if [ $rc -ne 0 ]; then echo "np $np: exit $rc"; cat "$tmp/np$np.out"; fail=1; continue; fi
  [ "$(grep -c '^root digest' "$tmp/np$np.out")" = 1 ] && grep -qxF "$root" "$tmp/np$np.out" ||
    { echo "np $np: rank 0 got other bytes than the serial run ($root)"; cat "$tmp/np$np.out"; fail=1; }
  [ "$(grep -cxF "$every" "$tmp/np$np.out")" = "$np" ] ||
    { echo "np $np: not every rank got the serial run's bytes ($every)"; cat "$tmp/np$np.out"; fail=1; }
done

for np in 3; do
  mpi_run 60 "$np" "$program" throw > "$tmp/throw$np.out" 2>&1
  rc=$?
  if [ $rc -eq 0 ] || [ $rc -eq 124 ]; then echo "throw, np $np: exit $rc, expected a failure"; fail=1; fi
  n=$(grep -cE '^error: rank 1, job ([0-9]+) \(job \1\): deliberate failure on rank 1$' "$tmp/throw$np.out")
  [ "$n" = "$np" ] || { echo "throw, np $np: $n of $np ranks printed the agreed error"; cat "$tmp/throw$np.out"; fail=1; }
  ! grep -q 'digest' "$tmp/throw$np.out" || { echo "throw, np $np: something was delivered"; fail=1; }
done

start=$(date +%s)
mpi_run 60 3 "$program" kill > "$tmp/kill.out" 2>&1
rc=$?
elapsed=$(( $(date +%s) - start ))
if [ $rc -eq 0 ] || [ $rc -eq 124 ]; then echo "kill: exit $rc after ${elapsed}s, expected a prompt failure"; cat "$tmp/kill.out"; fail=1; fi
! grep -q 'digest' "$tmp/kill.out" || { echo "kill: something was delivered"; fail=1; }
echo "kill: mpirun exit $rc after ${elapsed}s"
exit $fail
