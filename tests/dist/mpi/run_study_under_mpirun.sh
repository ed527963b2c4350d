#!/usr/bin/env bash
# `dayphoton run` distributed by mpirun (study/distributed_executor.h, docs/cluster.md): the
# office (at a fortieth of its photons, which changes nothing but the noise) run by one process
# and under `mpirun -np 1`, `-np 2` and `-np 3 --oversubscribe`, and the two-variant office
# likewise, every run with a cache of its own. Every file of the results folders must be byte-identical
# to the one-process run's, apart from run.log and timings.json (times) and the output folder's
# name in summary.json; every cache holds the one-process run's artefacts and list of used
# ones. The two-variant office (three cases) goes as whole cases over 2 and 3 ranks
# (study/case_units.h: its run.log says so; the office never). The ranks other than 0 write
# nothing (the writer flag, study_runner.h): each is started by a wrapper with a TMPDIR that is a file, not a folder, with a working
# folder of its own and with --output and --cache of its own, none of which may gain a file,
# so a rank that wrote anything anywhere it could (its results, run.log, the cache, a scratch
# folder) fails the test. No pictures and no
# report: report.html shows the run's times (its appendix), and it is made from results.json,
# which is compared.
# Usage: run_study_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
source_dir=$3
source "$(dirname "$0")/common.sh"
mpi_test_begin
fail=0

other_ranks_wrapper  # $tmp/rank.sh: the ranks other than 0 with folders of their own

office_copy "$source_dir" "$tmp/office" || exit 1
office_variants_copy "$source_dir" "$tmp/office_variants" || exit 1

for p in office office_variants; do
  project=$tmp/$p/project.yaml
  "$dayphoton" run "$project" --output "$tmp/out/$p-serial" --cache "$tmp/cache/$p-serial" --quiet \
    > /dev/null || { echo "$p: the one-process run failed"; fail=1; continue; }
  for np in 1 2 3; do
    out=$tmp/out/$p-np$np
    mpi_run 300 $np "$tmp/rank.sh" run "$project" --output "$out" \
      --cache "$tmp/cache/$p-np$np" --quiet > "$tmp/$p-np$np.log" 2>&1
    rc=$?
    [ $rc -eq 0 ] || { echo "$p: mpirun -np $np: exit $rc"; cat "$tmp/$p-np$np.log"; fail=1; continue; }
    # summary.json names the output folder; apart from it, the same bytes.
    if ! same_results "$tmp/out/$p-serial" "$out"; then
      echo "$p: mpirun -np $np wrote other results than the one-process run"
      fail=1
    fi
    # The cache: the same artefacts, and the same list of those the run used.
    if ! same_cache "$tmp/cache/$p-serial" "$tmp/cache/$p-np$np"; then
      echo "$p: mpirun -np $np cached other artefacts than the one-process run"
      fail=1
    fi
    # The variants (three cases) go as units from 2 ranks on (study/case_units.h); the office
    # (one case) never.
    units=$(grep -c "^cases as units over $np ranks: rank 0 case" "$out/run.log")
    if [ "$p" = office_variants ] && [ $np -ge 2 ]; then expected=1; else expected=0; fi
    [ "$units" -eq $expected ] || { echo "$p: mpirun -np $np: $units line(s) on cases as units, not $expected"; fail=1; }
  done
done
# What the ranks other than 0 wrote: nothing, anywhere.
other_ranks_wrote_nothing "$tmp/out" "$tmp/cache" || fail=1
exit $fail
