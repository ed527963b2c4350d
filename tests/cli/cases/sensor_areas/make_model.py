#!/usr/bin/env python3
"""Writes the Honeybee model of tests/cli/run_sensor_areas_test.sh (and of the measurements in
docs/validation.md, "Sensor areas") to argv[1]: a 5.2 x 4 x 3 m room (x 0..5.2, y 0..4) with a
2.4 x 1.5 m window in its east wall, and a floor grid at 0.8 m meshed as Honeybee's
Face3D.mesh_grid meshes a floor that is no multiple of its cell: cells of argv[2] m (default 1)
from the west wall, the last column trimmed at the east wall, one sensor at each face's centre."""
import json
import math
import sys

path = sys.argv[1]
cell = float(sys.argv[2]) if len(sys.argv) > 2 else 1.0
X, Y, Z, H = 5.2, 4.0, 3.0, 0.8


def face(ident, ftype, bc, boundary, apertures=None):
    f = {"type": "Face", "identifier": ident, "face_type": ftype, "boundary_condition": {"type": bc},
         "geometry": {"type": "Face3D", "boundary": boundary}}
    if apertures:
        f["apertures"] = apertures
    return f


def edges(extent):
    n = math.floor(extent / cell + 1e-9)
    e = [round(i * cell, 9) for i in range(n + 1)]
    if extent - e[-1] > 1e-9:
        e.append(extent)
    return e


window = {"type": "Aperture", "identifier": "east_window", "boundary_condition": {"type": "Outdoors"},
          "geometry": {"type": "Face3D", "boundary": [[X, 0.8, 0.9], [X, 3.2, 0.9], [X, 3.2, 2.4], [X, 0.8, 2.4]]}}
faces = [
    face("south", "Wall", "Outdoors", [[0, 0, 0], [X, 0, 0], [X, 0, Z], [0, 0, Z]]),
    face("north", "Wall", "Outdoors", [[X, Y, 0], [0, Y, 0], [0, Y, Z], [X, Y, Z]]),
    face("west", "Wall", "Outdoors", [[0, Y, 0], [0, 0, 0], [0, 0, Z], [0, Y, Z]]),
    face("east", "Wall", "Outdoors", [[X, 0, 0], [X, Y, 0], [X, Y, Z], [X, 0, Z]], [window]),
    face("floor", "Floor", "Ground", [[0, 0, 0], [0, Y, 0], [X, Y, 0], [X, 0, 0]]),
    face("ceiling", "RoofCeiling", "Outdoors", [[0, 0, Z], [X, 0, Z], [X, Y, Z], [0, Y, Z]]),
]
xs, ys = edges(X), edges(Y)
vertices, mesh_faces, sensors = [], [], []
index = {}
for j in range(len(ys)):
    for i in range(len(xs)):
        index[(i, j)] = len(vertices)
        vertices.append([xs[i], ys[j], H])
for j in range(len(ys) - 1):
    for i in range(len(xs) - 1):
        mesh_faces.append([index[(i, j)], index[(i + 1, j)], index[(i + 1, j + 1)], index[(i, j + 1)]])
        sensors.append({"pos": [round(0.5 * (xs[i] + xs[i + 1]), 9), round(0.5 * (ys[j] + ys[j + 1]), 9), H],
                        "dir": [0, 0, 1]})
grid = {"type": "SensorGrid", "identifier": "floor_grid", "sensors": sensors,
        "mesh": {"type": "Mesh3D", "vertices": vertices, "faces": mesh_faces}}
model = {"type": "Model", "identifier": "east_room", "units": "Meters", "tolerance": 0.01,
         "rooms": [{"type": "Room", "identifier": "room", "faces": faces}],
         "properties": {"type": "ModelProperties", "radiance": {"sensor_grids": [grid]}}}
with open(path, "w") as f:
    json.dump(model, f, indent=1)
