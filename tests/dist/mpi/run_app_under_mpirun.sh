#!/usr/bin/env bash
# dayphoton started by mpirun (app/main.cpp): with 2 ranks, `check` prints exactly what an
# ordinary run prints on standard output, once, and exits 0; a missing project gives exit 1.
# Usage: run_app_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
project=$3/projects/office/project.yaml
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
"$dayphoton" check "$project" > "$tmp/serial.out" || { echo "serial check failed"; exit 1; }
timeout 60 "$mpiexec" -np 2 --oversubscribe --bind-to none "$dayphoton" check "$project" > "$tmp/mpi.out" 2> "$tmp/mpi.err"
rc=$?
[ $rc -eq 0 ] || { echo "mpirun check: exit $rc"; cat "$tmp/mpi.err"; fail=1; }
cmp -s "$tmp/serial.out" "$tmp/mpi.out" || { echo "mpirun check printed other output:"; diff "$tmp/serial.out" "$tmp/mpi.out"; fail=1; }
grep -q "rank 0 runs this one alone" "$tmp/mpi.err" || { echo "no note that the work is not distributed"; fail=1; }
timeout 60 "$mpiexec" -np 2 --oversubscribe --bind-to none "$dayphoton" check "$tmp/missing.yaml" > /dev/null 2>&1
rc=$?
[ $rc -ne 0 ] && [ $rc -ne 124 ] || { echo "mpirun check of a missing project: exit $rc"; fail=1; }
exit $fail
