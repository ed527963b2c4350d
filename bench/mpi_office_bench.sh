#!/usr/bin/env bash
# The office (projects/office) run by one process with 1 and 2 threads and under
# `mpirun -np 1` and `-np 2 --bind-to none` with 1 thread per rank (docs/cluster.md
# "Measured"), each with a fresh cache and output folder. Prints per run the wall seconds,
# user + system CPU seconds of all processes (mpirun's children included; under mpirun also
# each rank's own), the peak RSS of the largest process and the load before it; then the step times of rank 0's run.log for
# the one-thread and the two-rank runs. Every results folder is compared with the first
# one's (all but run.log, summary.json and the report pages, which name times and folders).
# Usage: bench/mpi_office_bench.sh [BUILD_DIR] [PROJECT_DIR]
set -uo pipefail
build=${1:-build}
project_dir=${2:-projects/office}
dayphoton=$(realpath "$build/app/dayphoton")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/project"
cp "$project_dir"/project.yaml "$project_dir"/*.epw "$tmp/project/"
project=$tmp/project/project.yaml
run() {  # name threads command...
  local name=$1 threads=$2
  shift 2
  echo "== $name (load average $(cut -d' ' -f1-3 /proc/loadavg))"
  /usr/bin/time -f "   wall %e s, CPU %U user + %S system s, peak RSS %M kB" \
    "$@" run "$project" --output "$tmp/out-$name" --cache "$tmp/cache-$name" --quiet -j "$threads" 2>&1 | tail -3 |
    grep -v "^$"
  grep "time: " "$tmp/out-$name/run.log" | sed 's/^.*time: /   /' >"$tmp/$name.steps"
  if [ "$name" != serial-1 ] &&
    ! diff -r -q -x run.log -x summary.json -x report.html -x report.pdf "$tmp/out-serial-1" "$tmp/out-$name" >/dev/null; then
    echo "   results differ from serial-1's"
  fi
}
run serial-1 1 "$dayphoton"
run serial-2 2 "$dayphoton"
# Each rank under time(1) too: its own CPU seconds (printed before the job's line).
rank_time=(/usr/bin/time -f "   a rank: CPU %U user + %S system s, peak RSS %M kB")
run mpirun-np1 1 mpirun -np 1 --bind-to none "${rank_time[@]}" "$dayphoton"
run mpirun-np2 1 mpirun -np 2 --bind-to none --oversubscribe "${rank_time[@]}" "$dayphoton"
for n in serial-1 mpirun-np2; do
  echo "== step times of $n (rank 0's run.log)"
  cat "$tmp/$n.steps"
done
