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
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
tmp=$(mktemp -d)
job=
cleanup() {
  [ -n "$job" ] && kill -9 "$job" 2>/dev/null  # only mpirun started here, if a check failed early
  rm -rf "$tmp"
}
trap cleanup EXIT
fail() { echo "FAIL $*"; exit 1; }

mkdir -p "$tmp/office"
cp "$source_dir/projects/office/project.yaml" "$source_dir/projects/office/"*.epw "$tmp/office/"
sed -i 's/^  photons_per_bin: 40000$/  photons_per_bin: 1000/; s/^  matrix_format: ascii$/  matrix_format: float/;
        s/^  images: true$/  images: false/; s/^  report: true$/  report: false/; s/^  sun: bins$/  sun: spread/' \
  "$tmp/office/project.yaml"
grep -q '^  photons_per_bin: 1000$' "$tmp/office/project.yaml" && grep -q '^  sun: spread$' "$tmp/office/project.yaml" ||
  fail "office: photons_per_bin or sun not found"
project=$tmp/office/project.yaml

"$dayphoton" run "$project" --output "$tmp/reference" --cache "$tmp/reference-cache" --quiet >/dev/null ||
  fail "the uninterrupted one-process run failed"

# The pid of rank $2 of the mpirun $1: its child whose environment says so.
rank_pid() {
  local child
  for child in $(ps -o pid= --ppid "$1"); do
    if tr '\0' '\n' <"/proc/$child/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
      echo "$child"
      return 0
    fi
  done
  return 1
}

for victim in 1 0; do
  out=$tmp/out-kill$victim
  cache=$tmp/cache-kill$victim
  "$mpiexec" -np 2 --oversubscribe --bind-to none "$dayphoton" run "$project" --output "$out" --cache "$cache" \
    --quiet >"$tmp/kill$victim.log" 2>&1 &
  job=$!
  # Wait (up to 120 s) for rank 0 to store a first photon artefact: the photon batch is done
  # and being delivered; the coefficients (a final gather), the sky matrix and the annual
  # multiply, 0.9 s of CPU, are still to come.
  for ((i = 0; i < 6000; ++i)); do
    [ -n "$(find "$cache" -name 'photons-*.bin' 2>/dev/null | head -1)" ] && break
    kill -0 "$job" 2>/dev/null || fail "rank $victim: the run ended before a photon artefact was stored: $(cat "$tmp/kill$victim.log")"
    sleep 0.02
  done
  [ $i -lt 6000 ] || fail "rank $victim: no photon artefact stored after 120 s"
  pid=$(rank_pid "$job" "$victim") || fail "rank $victim: its process was not found among mpirun's children"
  stored=$(find "$cache" -name 'photons-*.bin' | wc -l)
  kill -9 "$pid"
  start=$(date +%s)
  while kill -0 "$job" 2>/dev/null && [ $(($(date +%s) - start)) -lt 60 ]; do sleep 0.05; done
  kill -0 "$job" 2>/dev/null && fail "rank $victim killed: mpirun still runs after 60 s"
  wait "$job"
  rc=$?
  job=
  elapsed=$(($(date +%s) - start))
  [ $rc -ne 0 ] || fail "rank $victim killed: mpirun exited 0"
  [ -e "$out/summary.json" ] && fail "rank $victim killed: the results folder has a summary.json (marked complete)"
  [ -e "$out/INCOMPLETE" ] || fail "rank $victim killed: the results folder has no INCOMPLETE marker"
  echo "ok   rank $victim killed with $stored photon artefacts stored: mpirun exit $rc after ${elapsed}s, folder marked incomplete"

  timeout 300 "$mpiexec" -np 2 --oversubscribe --bind-to none "$dayphoton" run "$project" --output "$out" \
    --cache "$cache" --quiet >"$tmp/rerun$victim.log" 2>&1 || fail "rank $victim: the re-run failed: $(cat "$tmp/rerun$victim.log")"
  line=$(grep -m1 '^photons: traced' "$out/run.log")
  if [[ $line =~ ^photons:\ traced\ ([0-9]+)\ of\ 146\ sources\ \(([0-9]+)\ cached\)$ ]]; then
    [ "${BASH_REMATCH[2]}" -ge 1 ] || fail "rank $victim: the re-run took no photons from the cache: $line"
  elif [[ $line != "photons: traced 0 of 146 sources (not needed: every grid's coefficients are cached)" ]]; then
    fail "rank $victim: the re-run's photon line is unexpected: $line"
  fi
  [ -e "$out/INCOMPLETE" ] && fail "rank $victim: the re-run left INCOMPLETE"
  diff -r -q -x run.log -x timings.json -x summary.json "$tmp/reference" "$out" ||
    fail "rank $victim: the re-run wrote other results than the uninterrupted run"
  cmp -s <(sed "s|$tmp/reference|OUT|g" "$tmp/reference/summary.json") <(sed "s|$out|OUT|g" "$out/summary.json") ||
    fail "rank $victim: the re-run wrote another summary.json than the uninterrupted run"
  echo "ok   re-run: $line; results byte-identical to the uninterrupted run"
done
echo "kill_rank_under_mpirun: all passed"
