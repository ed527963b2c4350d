#!/usr/bin/env bash
# A rank killed in the middle of a distributed `dayphoton run` (docs/cluster.md, "Failures"):
# the office (at a fortieth of its photons, the sun spread over the sky patches, float matrices,
# no pictures: 1.4 s of CPU alone) under
# `mpirun -np 2`, with rank 1 and then rank 0 killed by SIGKILL as soon as rank 0 has stored
# the first photon artefact in the cache (watched, not a fixed sleep). Each time:
#  1. mpirun exits non-zero within 60 s (not the time-out's 124);
#  2. the results folder is marked incomplete: INCOMPLETE present, no summary.json
#     (docs/outputs.md, "Complete or marked incomplete");
#  3. a re-run under `mpirun -np 2` into the same folder and cache takes the stored photons
#     from the cache (run.log: "photons: traced T of 146 sources (C cached)" with C >= 1, or
#     none needed), completes the folder, and writes every file byte-identical to an
#     uninterrupted one-process run (run.log and timings.json aside; summary.json apart from the folder name).
# Usage: kill_rank_under_mpirun.sh DAYPHOTON MPIEXEC SOURCE_DIR
set -uo pipefail
dayphoton=$1
mpiexec=$2
source_dir=$3
source "$(dirname "$0")/common.sh"
mpi_test_begin
fail() { echo "FAIL $*"; exit 1; }

office_copy "$source_dir" "$tmp/office" || fail "office: a line to change was not found"
sed -i 's/^  sun: bins$/  sun: spread/' "$tmp/office/project.yaml"
grep -q '^  sun: spread$' "$tmp/office/project.yaml" || fail "office: sun not found"
project=$tmp/office/project.yaml

"$dayphoton" run "$project" --output "$tmp/reference" --cache "$tmp/reference-cache" --quiet >/dev/null ||
  fail "the uninterrupted one-process run failed"

# Whether rank 0 has stored a photon artefact in the cache $cache.
photon_stored() { [ -n "$(find "$cache" -name 'photons-*.bin' 2>/dev/null | head -1)" ]; }

for victim in 1 0; do
  out=$tmp/out-kill$victim
  cache=$tmp/cache-kill$victim
  start_run_to_kill "$project" "$out" "$cache" "$tmp/kill$victim.log"
  # Wait (up to 120 s) for rank 0 to store a first photon artefact: the photon batch is done
  # and being delivered; the coefficients (a final gather), the sky matrix and the annual
  # multiply, 0.9 s of CPU, are still to come.
  await_in_job "$victim" "$tmp/kill$victim.log" "a photon artefact was stored" photon_stored
  stored=$(find "$cache" -name 'photons-*.bin' | wc -l)
  kill_rank_expect_incomplete "$victim" "$out"
  echo "ok   rank $victim killed with $stored photon artefacts stored: mpirun exit $rc after ${elapsed}s, folder marked incomplete"

  rerun_completes "$victim" "$project" "$out" "$cache" "$tmp/reference"
  line=$(grep -m1 '^photons: traced' "$out/run.log")
  if [[ $line =~ ^photons:\ traced\ ([0-9]+)\ of\ 146\ sources\ \(([0-9]+)\ cached\)$ ]]; then
    [ "${BASH_REMATCH[2]}" -ge 1 ] || fail "rank $victim: the re-run took no photons from the cache: $line"
  elif [[ $line != "photons: traced 0 of 146 sources (not needed: every grid's coefficients are cached)" ]]; then
    fail "rank $victim: the re-run's photon line is unexpected: $line"
  fi
  echo "ok   re-run: $line; results byte-identical to the uninterrupted run"
done
echo "kill_rank_under_mpirun: all passed"
