#!/usr/bin/env bash
# `dayphoton annual` in the exact-sun mode reproduces `run` with `simulation.sun: bins`
# (tests/cli/cases/exact_sun: two grids, one with its own schedule, and a variant): from the
# exported coefficients_sky.mtx, coefficients_sun.mtx, sun_bins.csv and direct_sun.bin.gz,
# metrics.csv must be byte-identical to the run's, grid_metrics.json's sDA, ASE and EN 17037
# equal and its means within the 7 digits of the ascii coefficients, for one grid folder
# and for the whole results folder (every grid, the variant's too), without the project: the
# metric settings, each grid's own schedule and the site come from the run's results.json. Command-line thresholds override the run's. Then: --sun spread is the old sky-only result (no ASE, other numbers); another
# weather file of the same site (the Oakland irradiance shifted by a day) runs with every
# sun at an exported position; a site moved by 0.05 deg (in results.json) warns that the
# direct sun is interpolated; moved by 5 deg it is a located error; another station's file on
# the run's clock warns that it is far, one on another clock is a located error; a damaged
# direct_sun.bin.gz is a located error.
set -u
cd "$(dirname "$0")/../.."
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL $*"; exit 1; }
project=tests/cli/cases/exact_sun/project.yaml
run=$scratch/run

"$bin" run "$project" --output "$run" --quiet || fail "run exited $?"
for g in desks club variants/dark_glass/desks variants/dark_glass/club; do
  [ -s "$run/$g/direct_sun.bin.gz" ] || fail "run wrote no $g/direct_sun.bin.gz"
done

# One grid folder, no project: everything from the run's results.json.
for g in desks club variants/dark_glass/club; do
  "$bin" annual --coefficients "$run/$g" --weather projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw \
    -o "$scratch/one/$g" >"$scratch/one.out" 2>"$scratch/one.err" ||
    fail "annual $g without the project exited $?: $(cat "$scratch/one.out" "$scratch/one.err")"
  cmp -s "$run/$g/metrics.csv" "$scratch/one/$g/metrics.csv" || fail "$g: metrics.csv of annual without the project differs from run's"
  [ ! -s "$scratch/one.err" ] || fail "annual $g with the run's weather warns: $(cat "$scratch/one.err")"
  grep -q "metric settings: the run's, from .*results.json$" "$scratch/one.out" || fail "$g: settings not the run's: $(cat "$scratch/one.out")"
done
grep -q "sun: exact .* suns at exported positions; ASE1000,250 " "$scratch/one.out" || fail "no exact-sun line: $(cat "$scratch/one.out")"

# Command-line thresholds override the run's: DA500, ASE at 800 lx.
"$bin" annual --coefficients "$run/desks" --weather projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw \
  --da-threshold 500 --ase-threshold 800 --ase-hours 100 -o "$scratch/override" >"$scratch/override.out" ||
  fail "annual with overrides exited $?"
grep -q "metric settings: the run's, from .*results.json, with the command line's overrides$" "$scratch/override.out" ||
  fail "override line: $(cat "$scratch/override.out")"
python3 - "$run/desks/grid_metrics.json" "$scratch/override/grid_metrics.json" <<'PY' || exit 1
import json, sys
run, o = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert o["thresholds"]["da_lux"] == 500 and "da500_percent" in o["mean"], o["thresholds"]
assert o["thresholds"]["ase_threshold_lux"] == 800 and o["thresholds"]["ase_hours"] == 100, o["thresholds"]
assert o["occupancy"] == run["occupancy"] and o["occupied_hours"] == run["occupied_hours"]
assert o["ase_percent"] >= run["ase_percent"], (o["ase_percent"], run["ase_percent"])
PY

# The results folder without the project: every grid, into -o DIR/<its path below the results folder>.
"$bin" annual --coefficients "$run" --weather projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw -o "$scratch/all" --quiet ||
  fail "annual on the results folder exited $?"
for g in desks club variants/dark_glass/desks variants/dark_glass/club; do
  cmp -s "$run/$g/metrics.csv" "$scratch/all/$g/metrics.csv" || fail "$g: metrics.csv of annual on the results folder differs"
done
python3 - "$run" "$scratch/all" <<'PY' || exit 1
import json, sys
run, ann = sys.argv[1], sys.argv[2]
summary = json.load(open(run + "/summary.json"))
cases = [("", summary["grids"])] + [("variants/" + v["name"] + "/", v["grids"]) for v in summary.get("variants", [])]
checked = 0
for prefix, grids in cases:
    for g in grids:
        r, a = g["annual"], json.load(open(ann + "/" + prefix + g["name"] + "/grid_metrics.json"))
        for key in ("occupied_hours", "sda_percent", "sda_sensors", "ase_percent", "en17037", "thresholds", "occupancy"):
            assert r[key] == a[key], (prefix + g["name"], key, r[key], a[key])
        # The means in full double precision: the exported coefficients are ascii with 7
        # significant digits (%.7g), so sums over the year agree to that, not to the last bit.
        for key, value in r["mean"].items():
            assert abs(a["mean"][key] - value) <= 1e-7 * max(1.0, abs(value)), (prefix + g["name"], key, value, a["mean"][key])
        assert a["ase_percent"] is not None
        checked += 1
assert checked == 4, checked
PY

# --sun spread: the sky coefficients alone, no ASE.
"$bin" annual --coefficients "$run/desks" --project "$project" --sun spread -o "$scratch/spread" --quiet || fail "--sun spread exited $?"
cmp -s "$run/desks/metrics.csv" "$scratch/spread/metrics.csv" && fail "--sun spread gives the exact-sun metrics"
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['ase_percent'] is None" "$scratch/spread/grid_metrics.json" ||
  fail "--sun spread computed ASE"

# Another weather file of the site: every record's irradiance from the next day.
python3 - "$scratch/shifted.epw" <<'PY'
import sys
lines = open("projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw", newline="").read().split("\n")
head, data = lines[:8], [l for l in lines[8:] if l]
f = [l.split(",") for l in data]
out = [",".join(f[i][:6] + f[(i + 24) % len(f)][6:]) for i in range(len(f))]
open(sys.argv[1], "w", newline="").write("\n".join(head + out) + "\n")
PY
"$bin" annual --coefficients "$run/desks" --project "$project" --weather "$scratch/shifted.epw" -o "$scratch/shifted" \
  >"$scratch/shifted.out" 2>"$scratch/shifted.err" || fail "annual with another weather file exited $?: $(cat "$scratch/shifted.err")"
grep -q "interpolated" "$scratch/shifted.err" && fail "the same site's suns were not all exported: $(cat "$scratch/shifted.err")"
cmp -s "$run/desks/metrics.csv" "$scratch/shifted/metrics.csv" && fail "another weather file gives the same metrics"

# A weather file of another station on the run's clock (the shifted file under a Seattle
# header, 1082 km away): the sun is still the run's site's, as `run` would compute it with this
# file, and annual warns that the station is far, as run does. Another clock (the header's
# time zone UTC+1): a located error naming both clocks, never a silent shift of the sun.
sed '1s/.*/LOCATION,Seattle Tacoma Intl Arpt,WA,USA,TMY3,727930,47.45,-122.31,-8.0,122.0/' "$scratch/shifted.epw" \
  >"$scratch/seattle.epw"
"$bin" annual --coefficients "$run/desks" --weather "$scratch/seattle.epw" -o "$scratch/seattle" --quiet \
  2>"$scratch/seattle.err" || fail "annual with another station's file exited $?: $(cat "$scratch/seattle.err")"
grep -q "^warning: .*desks: the weather station Seattle Tacoma Intl Arpt, WA, USA (WMO 727930) is 1082 km from the site" \
  "$scratch/seattle.err" || fail "no distant-station warning: $(cat "$scratch/seattle.err")"
cmp -s "$scratch/shifted/metrics.csv" "$scratch/seattle/metrics.csv" ||
  fail "the same irradiance under another station's header gives other metrics (the sun must stay the run's site's)"
sed '1s/.*/LOCATION,Mannheim,BW,DEU,BBSR,107290,49.52000,8.55000,1.0,96.0/' "$scratch/shifted.epw" >"$scratch/mannheim.epw"
"$bin" annual --coefficients "$run/desks" --weather "$scratch/mannheim.epw" -o "$scratch/mannheim" --quiet \
  >/dev/null 2>"$scratch/mannheim.err"
[ $? -eq 1 ] || fail "a weather file on another clock is not an input error: $(cat "$scratch/mannheim.err")"
grep -q "results.json: error: the run computed the sun on the clock of UTC-8, but the records of .*mannheim.epw are local standard time of UTC+1" \
  "$scratch/mannheim.err" || fail "another clock: $(cat "$scratch/mannheim.err")"
[ ! -e "$scratch/mannheim/metrics.csv" ] || fail "another clock wrote metrics"

# A site 0.05 deg north of the run's: suns near exported ones, a warning; 5 deg: an error.
for dlat in 0.05 5; do
  mkdir -p "$scratch/moved$dlat"
  cp -r "$run/desks" "$scratch/moved$dlat/desks"
  python3 - "$run/results.json" "$scratch/moved$dlat/results.json" "$dlat" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["site"]["sun_site"]["latitude_deg"] += float(sys.argv[3])
json.dump(s, open(sys.argv[2], "w"))
PY
done
"$bin" annual --coefficients "$scratch/moved0.05/desks" --project "$project" --quiet 2>"$scratch/moved.err" ||
  fail "a site 0.05 deg away exited $?: $(cat "$scratch/moved.err")"
grep -q "^warning: .*suns of the weather file are not at a sun position the run exported.*interpolated" "$scratch/moved.err" ||
  fail "no interpolation warning: $(cat "$scratch/moved.err")"
"$bin" annual --coefficients "$scratch/moved5/desks" --project "$project" --quiet >/dev/null 2>"$scratch/far.err"
[ $? -eq 1 ] || fail "a site 5 deg away is not an input error"
grep -q "direct_sun.bin.gz: .*farther than 1 deg" "$scratch/far.err" || fail "far site: $(cat "$scratch/far.err")"

# A damaged export is a located error.
head -c 300 "$run/desks/direct_sun.bin.gz" >"$scratch/moved0.05/desks/direct_sun.bin.gz"
"$bin" annual --coefficients "$scratch/moved0.05/desks" --project "$project" --quiet >/dev/null 2>"$scratch/bad.err"
[ $? -eq 1 ] || fail "a truncated direct_sun.bin.gz is not an input error: $(cat "$scratch/bad.err")"
grep -q "direct_sun.bin.gz" "$scratch/bad.err" || fail "the error does not name the file: $(cat "$scratch/bad.err")"
echo "ok   annual in the exact-sun mode reproduces run's metrics and ASE (grid and results folder)"
