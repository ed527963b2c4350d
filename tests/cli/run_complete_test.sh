#!/bin/bash
# An output folder is complete or marked incomplete (docs/outputs.md, "Complete or marked
# incomplete"), checked on the real binary:
#  1. a complete run: summary.json lists every output with its size and SHA-256, which match
#     the files; no INCOMPLETE marker, no lock file left;
#  2. a re-run with changed inputs (other photon count, no annual illuminance table) killed
#     with SIGKILL during its photon pass and again after its first new output: each time the
#     folder has no summary.json, has INCOMPLETE, and holds no output of the earlier run;
#  3. the re-run completed: only its own outputs (the earlier illuminance.bin is gone), the
#     temporaries of killed writes removed, the manifest matches;
#  4. a fully cached re-run writes byte-identical results (the run's history is in run.log and
#     timings.json, and in report.html's appendix, which shows the times: summary.json differs
#     only in report.html's hash), its timings.json marks every step "from cache";
#  5. a second run into a folder that a running run holds fails with exit 5, naming the
#     holder's pid and start time; after the holder is killed, the next run takes the lock over
#     and says so in run.log.
# The full disk is run_disk_full_test.sh (root only).
# Usage: DAYPHOTON=path/to/dayphoton bash run_complete_test.sh  (from the repository root)
set -u
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL $*"; exit 1; }
. "$(dirname "$0")/output_folder_checks.sh"

out="$scratch/out"
cache="$scratch/.out-cache"   # the cache beside the output folder (docs/cache.md)

# Starts `run second.yaml` and kills it with SIGKILL once the file test "$1" succeeds.
kill_when() {
  local condition=$1 what=$2
  touch "$scratch/started"
  sleep 0.05  # file times: everything the run writes is strictly newer than the reference
  "$bin" run "$scratch/office/second.yaml" --output "$out" --quiet &
  local pid=$! waited=0
  while ! eval "$condition"; do
    kill -0 "$pid" 2>/dev/null || fail "the run ended before it could be killed $what"
    sleep 0.02
    waited=$((waited + 1))
    [ $waited -gt 6000 ] && fail "timed out waiting to kill $what"
  done
  kill -9 "$pid"
  wait "$pid" 2>/dev/null
  problems=$(check_incomplete "$out" "$scratch/started") || fail "killed $what: $problems"
  echo "ok   killed $what: no summary.json, INCOMPLETE present, no output of the earlier run"
}

# 1. A complete run.
"$bin" run "$scratch/office/first.yaml" --output "$out" --quiet || fail "the first run failed"
problems=$(check_complete "$out") || fail "first run: $problems"
[ -f "$out/workplane/illuminance.bin" ] || fail "first run: no illuminance.bin"
echo "ok   complete run: summary.json lists $(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['files']))" "$out/summary.json") outputs, sizes and hashes match"

# 2. The changed re-run killed twice: in its photon pass, and after its first new output.
new_photons() { [ -n "$(find "$cache" -name 'photons-*.bin' -newer "$scratch/started" 2>/dev/null | head -1)" ]; }
kill_when new_photons "in the photon pass"
new_output() { [ -n "$(find "$out/workplane" -name 'daylight_factor.csv' -newer "$scratch/started" 2>/dev/null)" ]; }
kill_when new_output "after writing daylight_factor.csv"

# 3. Completed, with a temporary of a dead writer planted: only the re-run's outputs remain.
sleep 30 & dead=$!; kill -9 $dead; wait $dead 2>/dev/null  # a pid that no longer runs
echo partial >"$out/summary.json.tmp.$dead"
echo partial >"$cache/photons-0.bin.tmp.$dead"
"$bin" run "$scratch/office/second.yaml" --output "$out" --quiet || fail "the completing run failed"
problems=$(check_complete "$out") || fail "completed re-run: $problems"
[ -e "$out/workplane/illuminance.bin" ] && fail "the earlier run's illuminance.bin is still there"
[ -e "$out/summary.json.tmp.$dead" ] || [ -e "$cache/photons-0.bin.tmp.$dead" ] &&
  fail "temporaries of a dead writer were not removed"
grep -q "removed 2 temporary file" "$out/run.log" || fail "run.log does not report the removed temporaries"
echo "ok   completed re-run: only its own outputs, manifest matches, dead temporaries removed"

# 4. Nothing changed: every result byte-identical, run.log aside.
cp -r "$out" "$scratch/before"
"$bin" run "$scratch/office/second.yaml" --output "$out" --quiet || fail "the cached run failed"
grep -q "photons: traced 0 of 146" "$out/run.log" || fail "cached run: $(grep photons "$out/run.log")"
history=(-x run.log -x timings.json -x report.html -x summary.json)
diff -r "${history[@]}" "$scratch/before" "$out" >/dev/null ||
  fail "a fully cached run changed: $(diff -rq "${history[@]}" "$scratch/before" "$out")"
python3 - "$scratch/before/summary.json" "$out/summary.json" <<'PY' || fail "summary.json of the cached run differs"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
for s in (a, b):
    s["files"] = [f for f in s["files"] if f["path"] != "report.html"]
sys.exit(0 if a == b else 1)
PY
python3 - "$out/timings.json" <<'PY' || fail "timings.json of the cached run: $(head -c 600 "$out/timings.json")"
import json, sys
t = json.load(open(sys.argv[1]))
steps = {s["name"]: s for s in t["steps"]}
need = ["photons", "coefficients workplane", "sky matrix"]
sys.exit(0 if all(steps[n]["cached"] and steps[n]["wall_s"] == 0 for n in need) else 1)
PY
grep -q '<td>photons</td><td class="cached" colspan="3">from cache</td>' "$out/report.html" ||
  fail "the report's appendix does not show the cached photons as from cache"
echo "ok   fully cached re-run: every output byte-identical (summary.json but report.html's hash, and grid_metrics.json);"
echo "     timings.json and the report's appendix show the cached steps as from cache"

# 5. The lock: a second run into a folder in use fails clearly; a dead holder's lock is taken over.
"$bin" run "$scratch/office/first.yaml" --output "$out" --quiet --force &
holder=$!
for _ in $(seq 1 500); do grep -q '^started ' "$out/.dayphoton.lock" 2>/dev/null && break; sleep 0.02; done
"$bin" run "$scratch/office/second.yaml" --output "$out" --quiet 2>"$scratch/busy.err"
status=$?
kill -0 "$holder" 2>/dev/null || fail "the holding run ended before the second run was tried"
[ $status -eq 5 ] || fail "a run into a locked folder exited $status, not 5: $(cat "$scratch/busy.err")"
grep -q "in use by another dayphoton run: pid $holder .*started 20" "$scratch/busy.err" ||
  fail "the lock error does not name the holder: $(cat "$scratch/busy.err")"
echo "ok   locked folder: exit 5, $(sed 's/.*in use/in use/; s/; wait.*//' "$scratch/busy.err")"
kill -9 "$holder"
wait "$holder" 2>/dev/null
[ -e "$out/.dayphoton.lock" ] || fail "the killed holder left no lock file (the test needs one)"
"$bin" run "$scratch/office/second.yaml" --output "$out" --quiet || fail "the run after the killed holder failed"
grep -q "took over the lock of a run that no longer exists: pid $holder" "$out/run.log" ||
  fail "run.log does not mention the stale lock: $(head -5 "$out/run.log")"
problems=$(check_complete "$out") || fail "after taking over the lock: $problems"
echo "ok   stale lock of a killed run taken over, with a note in run.log"
echo "run_complete: all passed"
