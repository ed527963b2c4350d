#!/usr/bin/env bash
# Every sensor against an independent reference (docs/validation.md, "Every kind of sensor"):
# runs projects/wall_sensors (the reference office with a work-plane grid, the same 165
# positions as a mid-air .pts point set, and grids on the back and west walls) and compares
#   - the wall grids' daylight_factor.csv with the backward Monte Carlo references
#     (tests/data/reference/office_*_backward.csv, column df_cie_continuous_percent: the same
#     CIE sky, continuous, as the DF's sky component is), per-sensor relative RMS <= 3 %;
#   - the work-plane grid and the mid-air points, via their coefficients x RADIANCE's overcast
#     sky vector, with RADIANCE's rtrace DF (tests/data/radiance/df_office.csv), per-sensor
#     relative RMS <= 2 %.
# It runs a copy of the project as a daylight-factor study (`study: daylight_factor`: no sun
# bins, annual illuminance, metrics, images or report, none of which it checks): its
# daylight_factor.csv and coefficients_sky.mtx files are byte for byte those of the project as
# written (compared on 2026-12-03), in 13.7 CPU s instead of 31.7; cli_example_wall_sensors
# runs the whole project.
# The bounds are the acceptance goals of the estimator. Measured on 2 cores: 0.82 % and
# 0.98 % for the walls (of which the references' own standard errors are 0.53 % and 0.55 %
# RMS; with the sky component on the Tregenza patches instead, as before 3 December 2026,
# 3.20 % and 2.00 %, means +2.3 % and +1.4 %), 1.59 % for the grid and 1.34 % for the points
# (seed 1); seed-to-seed scatter of these RMS
# values is a few tenths of a per cent, so a bound is 4 x or more the measured value and the
# test fails only when an estimate moves by several per cent (as the mid-air points did
# before the final gather: -15 % mean, 34 % RMS; the walls 14-23 % RMS).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
dayphoton="${DAYPHOTON:-$root/build/app/dayphoton}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The copy beside a link to ../office (its weather file); each changed line must be there.
mkdir -p "$work/p/wall_sensors"
ln -s "$root/projects/office" "$work/p/office"
cp "$root/projects/wall_sensors/project.yaml" "$root/projects/wall_sensors/workplane_points.pts" "$work/p/wall_sensors/"
project=$work/p/wall_sensors/project.yaml
sed -i 's/^version: 1$/version: 1\nstudy: daylight_factor/; s/^  annual_illuminance: true$/  annual_illuminance: false/;
        s/^  metrics: true$/  metrics: false/; s/^  images: true$/  images: false/; s/^  report: true$/  report: false/' \
  "$project"
for line in 'study: daylight_factor' '  annual_illuminance: false' '  metrics: false' '  images: false' '  report: false' \
            '  coefficients: true'; do
  grep -qx "$line" "$project" || { echo "wall_sensors: no line '$line' in the copy"; exit 1; }
done
"$dayphoton" run "$project" --output "$work/out" --quiet
python3 - "$root" "$work/out" <<'PY'
import csv, math, struct, sys
root, out = sys.argv[1], sys.argv[2]
ref = root + "/tests/data/reference/"
W = (0.265, 0.670, 0.065)

def read_matrix(path):
    with open(path, "rb") as f:
        data = f.read()
    head, _, body = data.partition(b"\n\n")
    info = {}
    for line in head.decode().splitlines():
        if "=" in line:
            k, v = line.split("=", 1)
            info[k.strip()] = v.strip()
    rows, cols, comp = int(info["NROWS"]), int(info["NCOLS"]), int(info.get("NCOMP", "3"))
    if info.get("FORMAT", "ascii") == "ascii":
        values = [float(x) for x in body.split()]
    else:
        fmt = "<" if "1" in info.get("BYTEORDER", "1") or "little" in info.get("BYTEORDER", "little").lower() else ">"
        size = 4 if info["FORMAT"] == "float" else 8
        values = list(struct.unpack(fmt + ("f" if size == 4 else "d") * (len(body) // size), body))
    assert len(values) == rows * cols * comp, path
    return rows, cols, comp, values

def rms(rel):
    return math.sqrt(sum(x * x for x in rel) / len(rel))

failed = False
def check(name, rel, bound):
    global failed
    r = rms(rel)
    ok = r <= bound
    failed |= not ok
    print(f"{'ok  ' if ok else 'FAIL'} {name}: {len(rel)} sensors, per-sensor RMS {100 * r:.2f} % "
          f"(bound {100 * bound:.0f} %), mean {100 * sum(rel) / len(rel):+.2f} %, largest {100 * max(rel, key=abs):+.2f} %")

for grid, reference in (("back_wall", "office_back_wall_backward.csv"), ("west_wall", "office_west_wall_backward.csv")):
    ours = [float(r["df_percent"]) for r in csv.DictReader(open(f"{out}/{grid}/daylight_factor.csv"))]
    theirs = [float(r["df_cie_continuous_percent"]) for r in csv.DictReader(open(ref + reference))]
    assert len(ours) == len(theirs), grid
    check(f"{grid} vs backward reference", [o / t - 1 for o, t in zip(ours, theirs)], 0.03)

radiance = root + "/tests/data/radiance/"
_, _, _, sky = read_matrix(radiance + "skyvec_overcast_m1.vec")
rtrace = [float(r["DF_main_pct"]) for r in csv.DictReader(open(radiance + "df_office.csv"))]
for grid in ("workplane", "workplane_points"):
    rows, cols, comp, c = read_matrix(f"{out}/{grid}/coefficients_sky.mtx")
    assert rows == len(rtrace) and comp == 3, grid
    df = []
    for s in range(rows):
        e = sum(W[k] * c[(s * cols + p) * 3 + k] * sky[p * 3 + k] for p in range(cols) for k in range(3))
        df.append(179.0 * e / 10000.0 * 100.0)
    check(f"{grid} vs rtrace", [o / t - 1 for o, t in zip(df, rtrace)], 0.02)
sys.exit(1 if failed else 0)
PY
