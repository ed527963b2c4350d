#!/usr/bin/env python3
"""Compare the annual outputs of two folders grid by grid (docs/validation.md, "annual on an
exported results folder against a full run").

Usage: python3 scripts/compare_annual_outputs.py REFERENCE_DIR OTHER_DIR

Each folder is a results folder of `dayphoton run` or the --output of `dayphoton annual
--coefficients RESULTS_DIR`: every grid folder below it with metrics.csv is compared with the
folder of the same relative path in the other. Per grid it prints: the grid means of DA300,
UDI 100-2000 and mean occupied illuminance in both and their difference, the largest per-sensor
difference of DA300 and UDI (points of occupied hours), sDA and ASE (grid_metrics.json) in both,
the largest per-sensor difference of ASE hours, the per-sensor RMS and largest relative
difference of the annual illuminance sum (illuminance.bin), and the hourly RMS difference over
the mean illuminance. Plain Python, no third-party modules.
"""
import csv
import json
import math
import os
import struct
import sys


def read_metrics(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return rows


def read_illuminance_bin(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"DPILLUM1":
        raise SystemExit(f"{path}: not an illuminance.bin")
    steps, sensors = struct.unpack_from("<II", data, 8)
    offset = 16 + 8 * steps
    values = struct.unpack_from(f"<{steps * sensors}f", data, offset)
    return steps, sensors, values


def grid_folders(root):
    for dirpath, _, files in os.walk(root):
        if "metrics.csv" in files:
            yield os.path.relpath(dirpath, root)


def compare(ref_dir, other_dir, grid):
    a_dir, b_dir = os.path.join(ref_dir, grid), os.path.join(other_dir, grid)
    a, b = read_metrics(os.path.join(a_dir, "metrics.csv")), read_metrics(os.path.join(b_dir, "metrics.csv"))
    if len(a) != len(b):
        raise SystemExit(f"{grid}: {len(a)} sensors against {len(b)}")
    da = next(k for k in a[0] if k.startswith("da") and k.endswith("_percent"))
    udi = next(k for k in a[0] if k.startswith("udi") and "_" in k and k[3:].split("_")[0].isdigit())
    out = {"grid": grid, "sensors": len(a)}

    def column(rows, key):
        return [float(r[key]) for r in rows]

    for key, name in ((da, "da"), (udi, "udi"), ("mean_occupied_lux", "lux")):
        x, y = column(a, key), column(b, key)
        out[name + "_mean"] = (sum(x) / len(x), sum(y) / len(y))
        out[name + "_largest"] = max(abs(p - q) for p, q in zip(x, y))
    if "ase_hours" in a[0] and "ase_hours" in b[0]:
        out["ase_hours_largest"] = max(abs(p - q) for p, q in zip(column(a, "ase_hours"), column(b, "ase_hours")))
    ga = json.load(open(os.path.join(a_dir, "grid_metrics.json")))
    gb = json.load(open(os.path.join(b_dir, "grid_metrics.json")))
    out["sda"] = (ga["sda_percent"], gb["sda_percent"])
    out["ase"] = (ga["ase_percent"], gb["ase_percent"])
    ta, sa, va = read_illuminance_bin(os.path.join(a_dir, "illuminance.bin"))
    tb, sb, vb = read_illuminance_bin(os.path.join(b_dir, "illuminance.bin"))
    if (ta, sa) != (tb, sb):
        raise SystemExit(f"{grid}: illuminance tables of {ta}x{sa} and {tb}x{sb}")
    sums_a, sums_b = [0.0] * sa, [0.0] * sa
    squares, total = 0.0, 0.0
    for t in range(ta):
        row = t * sa
        for s in range(sa):
            p, q = va[row + s], vb[row + s]
            sums_a[s] += p
            sums_b[s] += q
            squares += (p - q) ** 2
            total += p
    rel = [(q - p) / p for p, q in zip(sums_a, sums_b) if p > 0]
    out["sum_rms_percent"] = 100 * math.sqrt(sum(r * r for r in rel) / len(rel)) if rel else 0.0
    out["sum_largest_percent"] = 100 * max(abs(r) for r in rel) if rel else 0.0
    mean = total / (ta * sa)
    out["hourly_rms_over_mean_percent"] = 100 * math.sqrt(squares / (ta * sa)) / mean if mean > 0 else 0.0
    out["annual_mean_lux"] = (sum(sums_a) / (ta * sa), sum(sums_b) / (ta * sa))
    return out


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    ref_dir, other_dir = sys.argv[1], sys.argv[2]
    grids = sorted(g for g in grid_folders(other_dir))
    if not grids:
        raise SystemExit(f"no metrics.csv below {other_dir}")
    print("| grid | mean DA300 (ref / other, diff) | DA300 per sensor: largest diff | mean UDI 100-2000 (diff) | UDI "
          "largest | sDA | ASE % | ASE hours per sensor: largest diff | mean annual illuminance, lx (diff) | "
          "annual sum per sensor: RMS (largest) | hourly RMS / mean |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    for g in grids:
        c = compare(ref_dir, other_dir, g)
        (da_a, da_b), (u_a, u_b) = c["da_mean"], c["udi_mean"]
        (m_a, m_b) = c["annual_mean_lux"]
        ase = c["ase"]
        ase_text = "not computed" if ase[0] is None or ase[1] is None else f"{ase[0]:.2f} / {ase[1]:.2f}"
        print(f"| {c['grid']} | {da_a:.2f} / {da_b:.2f} ({da_b - da_a:+.2f}) | {c['da_largest']:.3f} | "
              f"{u_a:.2f} / {u_b:.2f} ({u_b - u_a:+.2f}) | {c['udi_largest']:.3f} | "
              f"{c['sda'][0]:.2f} / {c['sda'][1]:.2f} | {ase_text} | {c.get('ase_hours_largest', float('nan')):.0f} | "
              f"{m_a:.1f} / {m_b:.1f} ({100 * (m_b - m_a) / m_a:+.3f} %) | "
              f"{c['sum_rms_percent']:.3f} % ({c['sum_largest_percent']:.3f} %) | "
              f"{c['hourly_rms_over_mean_percent']:.3f} % |")


if __name__ == "__main__":
    main()
