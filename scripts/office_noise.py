#!/usr/bin/env python3
"""Run-to-run noise of the reference office against RADIANCE (docs/validation.md, "The
reference office in CI"): runs `dayphoton run projects/office/project.yaml` (annual outputs
off) with seeds 1..N and prints, per seed and as mean and sample standard deviation, the seven
aggregates that tests/study/office_validation_test.cpp checks against these numbers:
the RMS and the largest of the per-sensor relative DF differences to rtrace (coefficients x
RADIANCE's overcast sky vector), the DF ratio of the grid and of its back half (y >= 4.5 m),
the ground bin against rfluxmtx, the sum of the other compared bins (above 0.2 % of the total)
and the largest of their differences. Plain Python, no third-party modules.

Usage: python3 scripts/office_noise.py [--seeds 10] [--dayphoton build/app/dayphoton] [--work DIR]
"""
import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import validate_office as v  # noqa: E402  (matrix and CSV readers, photometry)


def aggregates(c, rows, cols, sv, ref_df, ref_bin, compared):
    df = [179.0 * sum(v.W[k] * c[(s * cols + p) * 3 + k] * sv[p * 3 + k] for p in range(cols) for k in range(3)) / 100.0
          for s in range(rows)]
    bins = [sum(v.photometric(c, (s * cols + p) * 3) for s in range(rows)) for p in range(cols)]
    rel = [o / r - 1 for o, r in zip(df, ref_df)]
    back = [s for s in range(rows) if s // 11 >= 8]
    sky = [p for p in compared if p > 0]
    return {
        "sensor RMS": math.sqrt(sum(x * x for x in rel) / len(rel)),
        "sensor largest": max(abs(x) for x in rel),
        "grid ratio - 1": sum(df) / sum(ref_df) - 1,
        "back half ratio - 1": sum(df[s] for s in back) / sum(ref_df[s] for s in back) - 1,
        "ground bin - 1": bins[0] / ref_bin[0] - 1,
        "other bins' sum - 1": sum(bins[p] for p in sky) / sum(ref_bin[p] for p in sky) - 1,
        "other bins' largest": max(abs(bins[p] / ref_bin[p] - 1) for p in sky),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--dayphoton", default=os.path.join(ROOT, "build", "app", "dayphoton"))
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="dayphoton-noise-")
    text = open(os.path.join(ROOT, "projects", "office", "project.yaml")).read()
    for key in ("annual_illuminance", "metrics", "images", "report"):
        text = text.replace(key + ": true", key + ": false")
    epw = "USA_CA_Oakland.Intl.AP.724930_TMY3.epw"
    with open(os.path.join(ROOT, "projects", "office", epw), "rb") as src, open(os.path.join(work, epw), "wb") as dst:
        dst.write(src.read())
    _, _, _, sv = v.read_matrix(os.path.join(v.REF, "skyvec_overcast_m1.vec"))
    ref_df = [float(r["DF_main_pct"]) for r in v.read_csv(os.path.join(v.REF, "df_office.csv"))]
    _, _, _, dc = v.read_matrix(os.path.join(v.REF, "office_dc_classic.mtx.gz"))
    ref_bin = [sum(v.photometric(dc, (s * 146 + p) * 3) for s in range(165)) for p in range(146)]
    compared = [p for p in range(146) if ref_bin[p] > 0.002 * sum(ref_bin)]
    values = {}
    for seed in range(1, args.seeds + 1):
        project = os.path.join(work, f"seed{seed}.yaml")
        with open(project, "w") as f:
            f.write(re.sub(r"seed: \d+", f"seed: {seed}", text))
        out = os.path.join(work, f"seed{seed}")
        subprocess.run([args.dayphoton, "run", project, "--output", out, "--quiet"], check=True)
        rows, cols, _, c = v.read_matrix(os.path.join(out, "workplane", "coefficients_sky.mtx"))
        a = aggregates(c, rows, cols, sv, ref_df, ref_bin, compared)
        print(f"seed {seed}: " + ", ".join(f"{k} {x:+.5f}" for k, x in a.items()), flush=True)
        for k, x in a.items():
            values.setdefault(k, []).append(x)
    for k, xs in values.items():
        print(f"{k:22s} mean {statistics.mean(xs):+.5f} sd {statistics.stdev(xs):.5f} "
              f"(min {min(xs):+.5f}, max {max(xs):+.5f}, {len(xs)} seeds)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
