#!/usr/bin/env bash
# Big photon sources traced in attempt ranges over the ranks (study/split_photon_steps.h,
# docs/cluster.md "Big sources in attempt ranges"): a daylight-factor study of a small
# side-lit room under the CIE overcast sky, run by one process and under `mpirun -np 2` and
# `-np 3 --oversubscribe`, each with a cache of its own. Its ground bin (16 sky bins' photons,
# GroundPhotonFactor) is more than 1/8 of a rank's share of the 146 sources from 2 ranks on
# (SplitSourceFactor, plan_policy.h), so its passes are traced in ranges of at least 4,096
# attempts on every rank (at 4,000 photons per bin about 40,000 attempts in 2 passes; at 1,000,
# 10,046 attempts, no pass was long enough to be cut). Every file of the results folders must be
# byte-identical to the one-process run's, apart from run.log and timings.json (times) and the output folder's
# name in summary.json. The run log names the split source (the ground, source 0) and its
# ranges: "photons: 1 source split into attempt ranges over N ranks: source photons 0 (R
# ranges in P passes, A attempts)", with more ranges than passes (a pass was cut); the
# one-process log has no such line.
# Usage: run_split_sources_under_mpirun.sh DAYPHOTON MPIEXEC
set -uo pipefail
dayphoton=$1
mpiexec=$2
source "$(dirname "$0")/common.sh"
mpi_test_begin
export TMPDIR=$tmp  # the other ranks' scratch folders go here
fail=0

side_lit_room "$tmp/project.yaml" "photons_per_bin: 4000"

"$dayphoton" run "$tmp/project.yaml" --output "$tmp/out/serial" --cache "$tmp/cache/serial" --quiet > /dev/null ||
  { echo "the one-process run failed"; exit 1; }
! grep -q 'split into attempt ranges' "$tmp/out/serial/run.log" || { echo "one process split a source"; fail=1; }
for np in 2 3; do
  out=$tmp/out/np$np
  mpi_run 120 $np "$dayphoton" run "$tmp/project.yaml" --output "$out" \
    --cache "$tmp/cache/np$np" --quiet > "$tmp/np$np.log" 2>&1
  rc=$?
  [ $rc -eq 0 ] || { echo "mpirun -np $np: exit $rc"; cat "$tmp/np$np.log"; fail=1; continue; }
  split_line=$(grep '^photons: .* split into attempt ranges' "$out/run.log")
  if [[ $split_line =~ ^photons:\ 1\ source\ split\ into\ attempt\ ranges\ over\ $np\ ranks:\ source\ photons\ 0\ \(([0-9]+)\ ranges\ in\ ([0-9]+)\ passes,\ [0-9]+\ attempts\)$ ]]; then
    [ "${BASH_REMATCH[1]}" -gt "${BASH_REMATCH[2]}" ] || { echo "mpirun -np $np: no pass cut into ranges: $split_line"; fail=1; }
    echo "mpirun -np $np: $split_line"
  else
    echo "mpirun -np $np: run.log does not name the split source: '$split_line'"
    fail=1
  fi
  if ! same_results "$tmp/out/serial" "$out"; then
    echo "mpirun -np $np wrote other results than the one-process run"
    fail=1
  fi
  # The photons' cache artefacts themselves: the same bytes (file names are content keys).
  if ! same_cache "$tmp/cache/serial" "$tmp/cache/np$np"; then
    echo "mpirun -np $np cached other artefacts than the one-process run"
    fail=1
  fi
done
exit $fail
