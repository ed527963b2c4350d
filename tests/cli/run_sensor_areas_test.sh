#!/usr/bin/env bash
# A Honeybee grid whose mesh faces differ (tests/cli/cases/sensor_areas: 24 sensors on 1 m
# cells and a column of 0.2 m cells along the window wall): `check` and `run` note at the mesh
# that the shares are weighted by the faces' areas; sensors.csv and results.json carry the
# areas; the run's sDA, ASE, EN 17037 target areas and mean DA are the area-weighted shares of
# its own metrics.csv (recomputed here), not the sensor counts; and `dayphoton annual` on the
# results folder, without the project, gives the same shares and metrics.csv.
set -u
cd "$(dirname "$0")/../.."
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL $*"; exit 1; }
epw=projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw
cp tests/cli/cases/sensor_areas/project.yaml "$epw" "$scratch/"
python3 tests/cli/cases/sensor_areas/make_model.py "$scratch/model.hbjson" || fail "make_model.py exited $?"

"$bin" check "$scratch/project.yaml" >"$scratch/check.out" 2>&1 || fail "check exited $?: $(cat "$scratch/check.out")"
grep -q "^note .*model.hbjson:[0-9]*:[0-9]*: sensor grid 'floor_grid': the faces of its mesh differ in area (0.2 to 1 m^2, 20.8 m^2 in all): each sensor's share of the area .* is weighted by its face's area, as Honeybee does" \
  "$scratch/check.out" || fail "check does not note the weighting: $(cat "$scratch/check.out")"
"$bin" run "$scratch/project.yaml" --output "$scratch/run" --quiet || fail "run exited $?"
head -1 "$scratch/run/floor_grid/sensors.csv" | grep -qx "index,x,y,z,nx,ny,nz,area_m2" ||
  fail "sensors.csv has no area_m2: $(head -1 "$scratch/run/floor_grid/sensors.csv")"
grep -q "note: .*sensor grid 'floor_grid': the faces of its mesh differ" "$scratch/run/run.log" || fail "run.log has no note"

"$bin" annual --coefficients "$scratch/run" --weather "$epw" -o "$scratch/annual" >"$scratch/annual.out" 2>&1 ||
  fail "annual exited $?: $(cat "$scratch/annual.out")"
cmp -s "$scratch/run/floor_grid/metrics.csv" "$scratch/annual/floor_grid/metrics.csv" || fail "annual's metrics.csv differs from run's"

python3 - "$scratch" <<'PY' || exit 1
import csv, json, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/run/floor_grid/metrics.csv")))
areas = [float(r["area_m2"]) for r in csv.DictReader(open(d + "/run/floor_grid/sensors.csv"))]
assert len(areas) == len(rows) == 24 and sorted(set(round(a, 9) for a in areas)) == [0.2, 1.0], sorted(set(areas))
total = sum(areas)
def share(passes): return 100 * sum(a for a, p in zip(areas, passes) if p) / total
def counted(passes): return 100 * sum(passes) / len(passes)
da = [float(r["da1500_percent"]) for r in rows]
ase = [int(r["ase_hours"]) > 250 for r in rows]
run = next(g for g in json.load(open(d + "/run/summary.json"))["grids"] if g["name"] == "floor_grid")["annual"]
ann = json.load(open(d + "/annual/floor_grid/grid_metrics.json"))
# The run's shares are the area-weighted ones (metrics.csv prints DA to 3 decimals: the sDA
# verdicts at exactly 50 % are not in doubt here), and annual gives them again.
for g in (run, ann):
    assert abs(g["sda_percent"] - share([v >= 50 for v in da])) < 1e-9, (g["sda_percent"], share([v >= 50 for v in da]))
    assert abs(g["ase_percent"] - share(ase)) < 1e-9, (g["ase_percent"], share(ase))
    assert abs(g["mean"]["da1500_percent"] - sum(a * v for a, v in zip(areas, da)) / total) < 1e-3
assert abs(share(ase) - counted(ase)) > 1 and abs(share([v >= 50 for v in da]) - counted([v >= 50 for v in da])) > 1, \
    "the weighted shares equal the counted ones: the case tests nothing"
for key in ("sda_percent", "ase_percent"):
    assert run[key] == ann[key], (key, run[key], ann[key])
# The means within the 7 digits of the exported coefficients (as cli_annual_exact_sun).
for k, v in run["mean"].items():
    assert abs(v - ann["mean"][k]) <= 1e-6 * max(1.0, abs(v)), (k, v, ann["mean"][k])
assert [l["target_area_percent"] for l in run["en17037"]["levels"]] == [l["target_area_percent"] for l in ann["en17037"]["levels"]]
results = json.load(open(d + "/run/results.json"))
grid = next(g for g in results["cases"][0]["grids"] if g["name"] == "floor_grid")
assert [s["area_m2"] for s in grid["sensors"]] == areas
print("sDA1500 %.2f %% (counted %.2f %%), ASE %.2f %% (counted %.2f %%), mean DA1500 %.2f %% (counted %.2f %%)" % (
    run["sda_percent"], counted([v >= 50 for v in da]), run["ase_percent"], counted(ase),
    run["mean"]["da1500_percent"], sum(da) / len(da)))
print("EN 17037 target areas", [l["target_area_percent"] for l in run["en17037"]["levels"]])
PY
echo "PASS sensor areas"
