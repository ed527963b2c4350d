#!/bin/bash
# `dayphoton run` cache and resume (issue 5 acceptance), checked from the run log:
#  1. a run killed with SIGKILL in the middle of the photon pass, run again, finishes from
#     what it cached and its results are byte-identical to an uninterrupted run;
#  2. a second run with nothing changed traces nothing, and its results, all from the cache,
#     are byte-identical to the first (summary.json and grid_metrics.json included);
#  3. a changed sensor spacing re-estimates without re-tracing photons;
#  4. a changed weather file re-multiplies only.
# Usage: DAYPHOTON=path/to/dayphoton bash run_resume_test.sh  (from the repository root)
set -u
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL $*"; exit 1; }

# The office at 20000 photons per bin: a photon pass of a few seconds to interrupt.
mkdir -p "$scratch/office"
cp projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw "$scratch/office/"
sed -e 's/photons_per_bin: .*/photons_per_bin: 20000/' -e 's/images: true/images: false/' \
    -e 's/report: true/report: false/' projects/office/project.yaml >"$scratch/office/project.yaml"
project="$scratch/office/project.yaml"

# 1. Interrupt: wait until some sources are cached, then SIGKILL. Only finished artefacts
#    count: the kill may leave a write's temporary "<artefact>.tmp.<pid>" behind.
finished='^photons-[0-9a-f]*\.bin$'
"$bin" run "$project" --output "$scratch/a" --quiet &
pid=$!
for _ in $(seq 1 600); do
  n=$(ls "$scratch/.a-cache" 2>/dev/null | grep -c "$finished" || true)
  [ "$n" -ge 20 ] && break
  sleep 0.05
done
kill -9 "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
cached=$(ls "$scratch/.a-cache" | grep -c "$finished")
[ -e "$scratch/a/summary.json" ] && fail "the run finished before it could be interrupted ($cached sources cached)"
[ "$cached" -ge 1 ] || fail "nothing was cached before the kill"
"$bin" run "$project" --output "$scratch/a" --quiet || fail "the resumed run failed"
grep -q "photons: traced .* of 146 sources ($cached cached)" "$scratch/a/run.log" ||
  fail "resumed run log: $(grep photons "$scratch/a/run.log")"
echo "ok   resume after SIGKILL with $cached of 146 sources cached: $(grep photons "$scratch/a/run.log")"

"$bin" run "$project" --output "$scratch/b" --quiet || fail "the uninterrupted run failed"
for f in workplane/daylight_factor.csv workplane/coefficients_sky.mtx workplane/illuminance.bin workplane/metrics.csv; do
  cmp -s "$scratch/a/$f" "$scratch/b/$f" || fail "$f differs between the resumed and the uninterrupted run"
done
echo "ok   resumed results are byte-identical to an uninterrupted run"

# 2. Nothing changed: no tracing, no estimating, sky matrix from the cache; same bytes.
# summary.json and grid_metrics.json included: the run's history (cache counts, timings, "from
# the cache") is in run.log only.
outputs="workplane/daylight_factor.csv workplane/coefficients_sky.mtx workplane/coefficients_sun.mtx workplane/direct_sun.bin.gz
         workplane/illuminance.bin workplane/metrics.csv workplane/grid_metrics.json summary.json"
mkdir -p "$scratch/first"
for f in $outputs; do cp "$scratch/b/$f" "$scratch/first/$(basename "$f")"; done  # basenames are unique
"$bin" run "$project" --output "$scratch/b" --quiet || fail "the repeated run failed"
for f in $outputs; do
  cmp -s "$scratch/b/$f" "$scratch/first/$(basename "$f")" || fail "$f differs between a fresh and a cached run"
done
grep -q "photons: traced 0 of 146" "$scratch/b/run.log" || fail "repeat: $(grep photons "$scratch/b/run.log")"
grep -q "coefficients workplane: cached" "$scratch/b/run.log" || fail "repeat: coefficients not cached"
grep -q "sky matrix: cached" "$scratch/b/run.log" || fail "repeat: sky matrix not cached"
echo "ok   unchanged project: nothing traced, estimated or built; results byte-identical"

# 3. A new sensor spacing: the plane is the same, so photons come from the cache.
sed -i 's/spacing: 0.5/spacing: 0.25/' "$project"
"$bin" run "$project" --output "$scratch/b" --quiet || fail "the re-gridded run failed"
grep -q "photons: traced 0 of 146 sources (146 cached)" "$scratch/b/run.log" ||
  fail "new spacing: $(grep photons "$scratch/b/run.log")"
grep -q "coefficients workplane: estimated" "$scratch/b/run.log" || fail "new spacing: not re-estimated"
echo "ok   new sensor spacing: re-estimated without re-tracing"

# 4. Another weather file (same site, one value changed): only the sky and the annual steps.
python3 - "$scratch/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw" <<'PY'
import sys
path = sys.argv[1]
lines = open(path).read().split("\n")
f = lines[4000].split(",")
f[15] = str(int(f[15]) + 50)  # diffuse horizontal irradiance of a daytime record
lines[4000] = ",".join(f)
open(path, "w").write("\n".join(lines))
PY
"$bin" run "$project" --output "$scratch/b" --quiet || fail "the re-weathered run failed"
grep -q "photons: traced 0 of 146 sources (not needed" "$scratch/b/run.log" ||
  fail "new weather: $(grep photons "$scratch/b/run.log")"
grep -q "coefficients workplane: cached" "$scratch/b/run.log" || fail "new weather: coefficients not cached"
grep -q "sky matrix: built" "$scratch/b/run.log" || fail "new weather: sky matrix not rebuilt"
echo "ok   new weather file: sky matrix rebuilt, coefficients and photons from the cache"
echo "run_resume: all passed"
