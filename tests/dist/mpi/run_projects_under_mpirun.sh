#!/usr/bin/env bash
# Several projects of one command as units under mpirun (study/case_units.h, docs/cluster.md
# "Projects as units"): `dayphoton run office/project.yaml office_variants/project.yaml`
# (the office at a fortieth of its photons, the two-variant office at a quarter: 1 + 3 cases)
# by one process and under `mpirun -np 2` and `-np 3 --oversubscribe` (not `-np 1`: at one rank
# the app takes the one-process path, app/command_run.cpp, which the one-process run here
# covers, and dist_mpirun_run runs each project under `mpirun -np 1`). Each project
# writes to --output/<its folder's name> with its own cache beside it; every file of both
# results folders and both caches must be byte-identical to the one-process run's (apart from
# run.log, timings.json and the output folder's name in summary.json), and from 2 ranks on
# each project's run.log names the units. The ranks other than 0 write nothing: each gets
# --output of its own (so a cache of its own: the artefacts it computes must reach rank 0 as
# messages), a TMPDIR that is a file and a working folder of its own, none of which may gain
# a file. Then an input error of the second project (its time zone is not its weather
# file's) is reported once, located, under `mpirun -np 2`, and nothing is written.
# Usage: run_projects_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
source_dir=$3
source "$(dirname "$0")/common.sh"
mpi_test_begin
fail=0

other_ranks_wrapper  # $tmp/rank.sh: the ranks other than 0 with folders of their own

office_copy "$source_dir" "$tmp/p/office" || exit 1
office_variants_copy "$source_dir" "$tmp/p/office_variants" || exit 1
projects=("$tmp/p/office/project.yaml" "$tmp/p/office_variants/project.yaml")

"$dayphoton" run "${projects[@]}" --output "$tmp/out/serial" --quiet > /dev/null ||
  { echo "the one-process run failed"; exit 1; }
for p in office office_variants; do
  [ -f "$tmp/out/serial/$p/summary.json" ] && [ -d "$tmp/out/serial/.$p-cache" ] ||
    { echo "the one-process run wrote no $p/summary.json or .$p-cache"; fail=1; }
done
for np in 2 3; do
  out=$tmp/out/np$np
  mpi_run 300 $np "$tmp/rank.sh" run "${projects[@]}" --output "$out" \
    --quiet > "$tmp/np$np.log" 2>&1
  rc=$?
  [ $rc -eq 0 ] || { echo "mpirun -np $np: exit $rc"; cat "$tmp/np$np.log"; fail=1; continue; }
  # Both results folders and both caches (.office-cache, .office_variants-cache).
  if ! diff -r -q -x run.log -x timings.json -x summary.json "$tmp/out/serial" "$out"; then
    echo "mpirun -np $np wrote other results or cached other artefacts than the one-process run"
    fail=1
  fi
  for p in office office_variants; do
    if ! cmp -s <(sed "s|$tmp/out/serial|OUT|g" "$tmp/out/serial/$p/summary.json") \
                <(sed "s|$out|OUT|g" "$out/$p/summary.json"); then
      echo "$p: mpirun -np $np wrote another summary.json than the one-process run"
      fail=1
    fi
    # Four cases in all: units, named in each project's run.log.
    units=$(grep -c "^cases of 2 projects as units over $np ranks: rank 0 project" "$out/$p/run.log")
    [ "$units" -eq 1 ] || { echo "$p: mpirun -np $np: $units line(s) on units, not 1"; fail=1; }
    # The project's own units are not made again.
    grep -q "^cases as units" "$out/$p/run.log" && { echo "$p: mpirun -np $np: the project's cases as units again"; fail=1; }
  done
done
other_ranks_wrote_nothing "$tmp/out" || fail=1

# An input error of the second project: its site on another clock than its weather file.
mkdir -p "$tmp/p/bad"
cp "$tmp/p/office/project.yaml" "$tmp/p/office/"*.epw "$tmp/p/bad/"
sed -i 's/^  time_zone: -8 /  time_zone: -5 /' "$tmp/p/bad/project.yaml"
line=$(grep -n '^  time_zone: -5 ' "$tmp/p/bad/project.yaml" | cut -d: -f1)
[ -n "$line" ] || { echo "bad: time_zone not found"; exit 1; }
mpi_run 120 2 "$tmp/rank.sh" run "$tmp/p/office/project.yaml" \
  "$tmp/p/bad/project.yaml" --output "$tmp/out/bad" > "$tmp/bad.out" 2> "$tmp/bad.err"
rc=$?
[ $rc -eq 1 ] || { echo "input error of the second project: exit $rc, not 1"; cat "$tmp/bad.err"; fail=1; }
located=$(grep -c "bad/project.yaml:$line:" "$tmp/bad.err")
[ "$located" -eq 1 ] || { echo "input error printed $located times located at line $line, not once:"; cat "$tmp/bad.err"; fail=1; }
grep -q "MPI_Abort\|MPI_ABORT" "$tmp/bad.err" && { echo "input error ended by MPI_Abort"; fail=1; }
[ ! -e "$tmp/out/bad" ] || { echo "input error of the second project, but something was written:"; find "$tmp/out/bad" | head; fail=1; }
exit $fail
