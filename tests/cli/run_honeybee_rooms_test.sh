#!/bin/bash
# A Honeybee room equals the same room written as a dayphoton `rooms:` entry
# (docs/honeybee-import.md, "Validation"): a 5 x 6 x 3 m room with a 3 x 1.5 m south
# window under a 0.8 m overhang, Honeybee's generic modifiers (floor 0.2, walls 0.5, ceiling
# 0.8, glass of visible transmittance 0.64, exterior shade 0.35) against lambertian
# 0.2/0.5/0.8/0.35, glass 0.64 and an overhang system (port: system: both overhangs are
# outdoor scatterers), the same 30 sensors as points (final gather in both). Daylight
# factors only.
#
# Tolerance from the variance: the room project is run with two seeds; the per-sensor
# differences of those runs, d_i, are differences of two independent estimates of one
# model, so their standard deviation s is that of H_i - R_i (Honeybee minus room, same
# seed) if the two are the same model. The grid mean of H - R then has a standard deviation
# of at most s (sensors fully correlated; less if they are independent), so
# |mean(H - R)| <= 4 s holds with probability > 99.99 % for equal models (normal errors).
# A wrong import (a material, a window lost or doubled, a port facing the wrong way)
# shifts every sensor the same way and fails it.
# First, placement: a sensor inside the imported room passes `check`, one outside is refused.
# Usage: DAYPHOTON=path/to/dayphoton bash run_honeybee_rooms_test.sh
set -eu
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

python3 - "$scratch" <<'PY'
import json, os, sys
d = sys.argv[1]
W, D, H = 5.0, 6.0, 3.0
def face(i, t, bc, b, **kw):
    f = {"type": "Face", "identifier": i, "face_type": t, "boundary_condition": {"type": bc},
         "geometry": {"type": "Face3D", "boundary": b}, "properties": {}}
    f.update(kw)
    return f
win = [[1, 0, 0.9], [4, 0, 0.9], [4, 0, 2.4], [1, 0, 2.4]]
overhang = {"type": "Shade", "identifier": "overhang", "properties": {},
            "geometry": {"type": "Face3D", "boundary": [[0.7, 0, 2.5], [0.7, -0.8, 2.5], [4.3, -0.8, 2.5], [4.3, 0, 2.5]]}}
faces = [
    face("south", "Wall", "Outdoors", [[0, 0, 0], [W, 0, 0], [W, 0, H], [0, 0, H]],
         apertures=[{"type": "Aperture", "identifier": "window", "boundary_condition": {"type": "Outdoors"},
                     "geometry": {"type": "Face3D", "boundary": win}, "properties": {},
                     "outdoor_shades": [overhang]}]),
    face("north", "Wall", "Outdoors", [[W, D, 0], [0, D, 0], [0, D, H], [W, D, H]]),
    face("west", "Wall", "Outdoors", [[0, D, 0], [0, 0, 0], [0, 0, H], [0, D, H]]),
    face("east", "Wall", "Outdoors", [[W, 0, 0], [W, D, 0], [W, D, H], [W, 0, H]]),
    face("floor", "Floor", "Ground", [[0, 0, 0], [0, D, 0], [W, D, 0], [W, 0, 0]]),
    face("ceiling", "RoofCeiling", "Outdoors", [[0, 0, H], [W, 0, H], [W, D, H], [0, D, H]]),
]
sensors = [{"pos": [x + 0.5, y + 0.5, 0.8], "dir": [0, 0, 1]} for y in range(6) for x in range(5)]
model = {"type": "Model", "identifier": "one_room", "units": "Meters", "tolerance": 0.01,
         "rooms": [{"type": "Room", "identifier": "room", "faces": faces, "properties": {}}],
         "properties": {"radiance": {"sensor_grids": [{"type": "SensorGrid", "identifier": "grid", "sensors": sensors}]}}}
json.dump(model, open(os.path.join(d, "room.hbjson"), "w"), indent=1)
head = """version: 1
site: {latitude: 37.72, longitude: -122.22, time_zone: -8}
outputs: {annual_illuminance: false, metrics: false, images: false, report: false, coefficients: false}
"""
sim = "simulation: {photons_per_bin: 5000, gather_rays: 256, seed: SEED}\n"
hb = head + "materials: {}\ngeometry: {honeybee: room.hbjson}\nsensors: {honeybee_grids: all}\n"
pts = ", ".join("[%g, %g, 0.8, 0, 0, 1]" % (s["pos"][0], s["pos"][1]) for s in sensors)
rooms = head + """materials:
  floor: {type: lambertian, reflectance: 0.2}
  walls: {type: lambertian, reflectance: 0.5}
  ceiling: {type: lambertian, reflectance: 0.8}
  glass: {type: glass, transmittance: 0.64}
  shade: {type: lambertian, reflectance: 0.35}
geometry:
  rooms:
    - name: room
      size: [5, 6, 3]
      materials: {floor: floor, ceiling: ceiling, walls: walls}
      windows: [{name: window, wall: south, width: 3, height: 1.5, sill: 0.9, offset: 1, material: glass}]
  systems:
    - {type: overhang, name: overhang, window: window, height: 2.5, depth: 0.8, extension: 0.3, material: shade}
sensors:
  points: [{name: grid, points: [%s]}]
""" % pts
# Placement: the imported room is a room to the placement check (a sensor inside passes, one
# 3 m in front of the window is outside every room).
for name, y in (("inside", 3), ("outside", -3)):
    open(os.path.join(d, name + ".yaml"), "w").write(
        head + "materials: {}\ngeometry: {honeybee: room.hbjson}\n"
        "sensors: {points: [{name: p, points: [[2.5, %g, 0.8, 0, 0, 1]]}]}\n" % y)
for name, text, seed in (("hb1", hb, 1), ("rooms1", rooms, 1), ("rooms2", rooms, 2)):
    open(os.path.join(d, name + ".yaml"), "w").write(text + sim.replace("SEED", str(seed)))
PY

"$bin" check "$scratch/inside.yaml" >"$scratch/inside.log" 2>&1 ||
  { echo "FAIL: a sensor inside the imported room is refused"; tail -5 "$scratch/inside.log"; exit 1; }
if "$bin" check "$scratch/outside.yaml" >"$scratch/outside.log" 2>&1 || ! grep -q "outside every room" "$scratch/outside.log"; then
  echo "FAIL: a sensor outside the imported room is not refused"; tail -5 "$scratch/outside.log"; exit 1
fi
echo "placement: a sensor inside the imported room passes, one outside is refused"

for run in hb1 rooms1 rooms2; do
  "$bin" run "$scratch/$run.yaml" --output "$scratch/out_$run" --quiet >"$scratch/$run.log" 2>&1 ||
    { echo "FAIL: dayphoton run $run"; tail -5 "$scratch/$run.log"; exit 1; }
done

python3 - "$scratch" <<'PY'
import csv, math, os, sys
d = sys.argv[1]
def df(run):
    with open(os.path.join(d, "out_" + run, "grid", "daylight_factor.csv"), newline="") as f:
        return [float(r["df_percent"]) for r in csv.DictReader(f)]
h, r1, r2 = df("hb1"), df("rooms1"), df("rooms2")
n = len(h)
seed_diff = [b - a for a, b in zip(r1, r2)]
m = sum(seed_diff) / n
s = math.sqrt(sum((x - m) ** 2 for x in seed_diff) / (n - 1))
bias = sum(a - b for a, b in zip(h, r1)) / n
mean_room = sum(r1) / n
print("mean DF: honeybee %.4f %%, rooms %.4f %%, rooms seed 2 %.4f %%; mean(H - R) = %.4f %%, s = %.4f %%, limit 4 s = %.4f %%"
      % (sum(h) / n, mean_room, sum(r2) / n, bias, s, 4 * s))
sys.exit(0 if abs(bias) <= 4 * s else 1)
PY
