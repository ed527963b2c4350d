#!/usr/bin/env bash
# dayphoton started by mpirun (app/main.cpp): with 2 ranks, `check` prints exactly what an
# ordinary run prints on standard output, once, and exits 0; a missing project gives exit 1.
# `run` under 3 ranks of a project with input errors (two in the project file; then a damaged
# weather file, read inside the study) prints the located errors once, as one process does,
# with its exit code, and no rank calls MPI_Abort (the ranks agree on the failure,
# app/commands.h agree_on_failure).
# Usage: run_app_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
project=$3/projects/office/project.yaml
source "$(dirname "$0")/common.sh"
mpi_test_begin
fail=0
"$dayphoton" check "$project" > "$tmp/serial.out" || { echo "serial check failed"; exit 1; }
mpi_run 60 2 "$dayphoton" check "$project" > "$tmp/mpi.out" 2> "$tmp/mpi.err"
rc=$?
[ $rc -eq 0 ] || { echo "mpirun check: exit $rc"; cat "$tmp/mpi.err"; fail=1; }
cmp -s "$tmp/serial.out" "$tmp/mpi.out" || { echo "mpirun check printed other output:"; diff "$tmp/serial.out" "$tmp/mpi.out"; fail=1; }
grep -q "rank 0 runs this one alone" "$tmp/mpi.err" || { echo "no note that the work is not distributed"; fail=1; }
mpi_run 60 2 "$dayphoton" check "$tmp/missing.yaml" > /dev/null 2>&1
rc=$?
[ $rc -ne 0 ] && [ $rc -ne 124 ] || { echo "mpirun check of a missing project: exit $rc"; fail=1; }

# Input errors of `run`: each line one process prints, printed once under 3 ranks.
mkdir -p "$tmp/bad" "$tmp/badweather"
sed 's/^    reflectance: 0.2$/    reflectance: 1.7/; s/^    transmittance: 0.6 .*$/    transmittance: -0.6/' \
  "$project" > "$tmp/bad/project.yaml"
cp "$(dirname "$project")"/*.epw "$tmp/bad/"
cp "$project" "$tmp/badweather/project.yaml"
head -n 20 "$(dirname "$project")"/*.epw > "$tmp/badweather/$(basename "$(dirname "$project")"/*.epw)"
sed -i '20s/^\([^,]*\),\([^,]*\),/\1,13,/' "$tmp/badweather/"*.epw  # month 13 in a data line
for case in bad badweather; do
  "$dayphoton" run "$tmp/$case/project.yaml" --output "$tmp/$case/serial" --quiet > /dev/null 2> "$tmp/$case.serial.err"
  serial_rc=$?
  [ $serial_rc -eq 1 ] || { echo "$case: one process exited $serial_rc, not 1 (input error)"; cat "$tmp/$case.serial.err"; fail=1; continue; }
  lines=$(grep -c . "$tmp/$case.serial.err")
  [ "$case" != bad ] || [ "$lines" -ge 2 ] || { echo "bad: fewer than two error lines"; cat "$tmp/$case.serial.err"; fail=1; }
  mpi_run 120 3 "$dayphoton" run "$tmp/$case/project.yaml" \
    --output "$tmp/$case/mpi" --quiet > /dev/null 2> "$tmp/$case.mpi.err"
  rc=$?
  [ $rc -eq $serial_rc ] || { echo "$case: mpirun -np 3 exited $rc, one process $serial_rc"; fail=1; }
  while IFS= read -r line; do
    [ -n "$line" ] || continue
    n=$(grep -cxF -- "$line" "$tmp/$case.mpi.err")
    [ "$n" -eq 1 ] || { echo "$case: under 3 ranks printed $n times: $line"; fail=1; }
  done < "$tmp/$case.serial.err"
  if grep -q "MPI_ABORT" "$tmp/$case.mpi.err"; then echo "$case: a rank called MPI_Abort"; fail=1; fi
  [ ! -e "$tmp/$case/mpi" ] || { echo "$case: the failed run made its output folder"; fail=1; }
done
exit $fail
