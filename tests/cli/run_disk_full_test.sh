#!/bin/bash
# A full disk during `dayphoton run` (docs/outputs.md, "Complete or marked incomplete"): on a
# 64 MB tmpfs, a first run completes; a re-run with a new sensor spacing (photons from the
# cache, new coefficients and outputs) on the disk filled to 100 KB of free space must end with
# a clean error (exit 4, "No space left on device", no signal) and leave the folder marked
# INCOMPLETE without summary.json or lock; with space again the run resumes from the cache,
# completes, and gives the same results as a fresh run. Mounting needs root: otherwise the test
# is skipped (exit 77). The disk fills after the photon pass (its photons are cached).
# Usage: DAYPHOTON=path/to/dayphoton bash run_disk_full_test.sh  (from the repository root)
set -u
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
mounted=""
cleanup() {
  [ -n "$mounted" ] && umount "$mounted" 2>/dev/null
  rm -rf "$scratch"
}
trap cleanup EXIT
fail() { echo "FAIL $*"; exit 1; }
. "$(dirname "$0")/output_folder_checks.sh"

if [ "$(id -u)" != 0 ] || ! mkdir -p "$scratch/tmpfs" || ! mount -t tmpfs -o size=64m tmpfs "$scratch/tmpfs" 2>/dev/null; then
  echo "skipped: needs root and a tmpfs mount"
  exit 77
fi
mounted="$scratch/tmpfs"
disk="$mounted/out"
"$bin" run "$scratch/office/first.yaml" --output "$disk" --quiet || fail "the run on the tmpfs failed"
# A new sensor spacing: photons come from the cache, coefficients and every output are new.
# Fill the disk but 100 KB, far less than the run writes (coefficients ~870 KB, tables MBs).
sed 's/spacing: 0.5/spacing: 0.4/' "$scratch/office/first.yaml" >"$scratch/office/spacing.yaml"
dd if=/dev/zero of="$mounted/filler" bs=1k count=$(( $(df -k --output=avail "$mounted" | tail -1) - 100 )) 2>/dev/null
"$bin" run "$scratch/office/spacing.yaml" --output "$disk" --quiet 2>"$scratch/full.err"
status=$?
[ $status -eq 4 ] || fail "on a full disk: exit $status (expected 4): $(cat "$scratch/full.err")"
grep -q "No space left on device" "$scratch/full.err" || fail "on a full disk: $(cat "$scratch/full.err")"
[ -e "$disk/summary.json" ] && fail "on a full disk: summary.json present"
[ -e "$disk/INCOMPLETE" ] || fail "on a full disk: no INCOMPLETE marker"
[ -e "$disk/.dayphoton.lock" ] && fail "on a full disk: the lock file was left behind"
echo "ok   full disk: exit 4, $(head -1 "$scratch/full.err" | cut -c1-150)"
rm -f "$mounted/filler"
"$bin" run "$scratch/office/spacing.yaml" --output "$disk" --quiet || fail "the run after freeing space failed"
grep -q "photons: traced 0 of 146 sources" "$disk/run.log" || fail "resumed: $(grep photons "$disk/run.log")"
problems=$(check_complete "$disk") || fail "after the full disk: $problems"
"$bin" run "$scratch/office/spacing.yaml" --output "$scratch/reference" --quiet || fail "the reference run failed"
for f in workplane/daylight_factor.csv workplane/coefficients_sky.mtx workplane/metrics.csv; do
  cmp -s "$disk/$f" "$scratch/reference/$f" || fail "$f differs between the resumed run and a fresh one"
done
echo "ok   with space again: resumed from the cache (photons not traced), complete, same results as a fresh run"
echo "run_disk_full: all passed"
