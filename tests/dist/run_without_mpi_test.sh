#!/usr/bin/env bash
# A dayphoton built without MPI (DAYPHOTON_MPI=OFF) that finds itself started by a launcher
# (app/main.cpp): with 2 processes announced it refuses (exit 2, saying why), since two copies
# of one serial run would write one output folder; with 1 it runs as usual. The launcher is
# imitated by its environment variable, so no mpirun is needed.
# Usage: run_without_mpi_test.sh DAYPHOTON SOURCE_DIR
set -uo pipefail
dayphoton=$1
project=$2/projects/office/project.yaml
fail=0
err=$(OMPI_COMM_WORLD_SIZE=2 "$dayphoton" check "$project" 2>&1 >/dev/null)
rc=$?
[ $rc -eq 2 ] || { echo "2 processes announced: exit $rc, expected 2"; fail=1; }
case "$err" in *"built without MPI"*"OMPI_COMM_WORLD_SIZE is set"*) ;; *) echo "unexpected message: $err"; fail=1 ;; esac
OMPI_COMM_WORLD_SIZE=1 "$dayphoton" check "$project" > /dev/null || { echo "1 process announced: failed"; fail=1; }
exit $fail
