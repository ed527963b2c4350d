#!/usr/bin/env python3
"""Where the reference office's daylight-factor error comes from (docs/validation.md, "The
daylight factor against the converged result"): runs `dayphoton run projects/office/project.yaml`
with seeds 1..N (optionally other photon settings) and compares each run's DF (its sky
coefficients x RADIANCE's overcast sky vector, as scripts/validate_office.py) per sensor with
the converged result on the same basis and sky vector, the brute-force backward Monte Carlo
reference (bench/office_backward_reference, all rows, with its matrix and its per-sensor CSV).

It splits the mean square of the per-sensor relative difference of one run into
  - our noise: the run's own reported variance (df_stderr_percent / df_percent of
    daylight_factor.csv; the same relative error under either overcast vector), checked against
    the spread of the seeds;
  - the reference's noise: its reported standard error (write_csv of the bench);
  - the bias: what the mean over the seeds keeps beyond the noise left in it,
    MS(mean) - mean(var_ours / N + var_ref), and where it sits: per sensor row and per sky
    band (ground bin, the seven Tregenza rows and the zenith), as a share of the sensor's DF.
Also prints each run's wall and CPU time (user + sys of the child) and its DF against rtrace.
Plain Python, no third-party modules.

Usage: python3 scripts/office_df_error.py --backward BW.mtx --backward-csv BW.csv [--seeds 8]
           [--photons N] [--bandwidth B] [--accuracy PERCENT] [--direct-samples N]
           [--point-reference PTS_CSV SENSORS]... [--annual] [--dayphoton build/app/dayphoton]
           [--work DIR]
--annual keeps the project's annual outputs, images and report (a timing of the whole study);
without it they are off (the sky coefficients and DF are the same: they come first).
"""
import argparse
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import validate_office as v  # noqa: E402  (matrix and CSV readers, photometry)

COLUMNS = 11  # the office grid: 11 sensors per row, 15 rows (y = 0.5 + 0.5 r m)


def band_ranges():
    """Ground bin, the seven Tregenza rows (30, 30, 24, 24, 18, 12, 6 patches) and the zenith."""
    ranges, start = [("ground", 0, 1)], 1
    for r, n in enumerate((30, 30, 24, 24, 18, 12, 6)):
        ranges.append((f"{12 * r}-{12 * r + 12} deg", start, start + n))
        start += n
    ranges.append(("zenith", start, start + 1))
    return ranges


def df_per_band(c, rows, cols, sv):
    """DF (%) of every sensor split by sky band: list over sensors of lists over bands."""
    out = []
    for s in range(rows):
        per = []
        for _, p0, p1 in band_ranges():
            e = sum(v.W[k] * c[(s * cols + p) * 3 + k] * sv[p * 3 + k] for p in range(p0, p1) for k in range(3))
            per.append(179.0 * e / 100.0)
        out.append(per)
    return out


def rms(xs):
    return math.sqrt(sum(x * x for x in xs) / len(xs))


def project_text(args):
    text = open(os.path.join(ROOT, "projects", "office", "project.yaml")).read()
    if not args.annual:
        for key in ("annual_illuminance", "metrics", "images", "report"):
            text = text.replace(key + ": true", key + ": false")
    if args.photons is not None:
        text = re.sub(r"photons_per_bin: \d+", f"photons_per_bin: {args.photons}", text)
    if args.bandwidth is not None:
        text = re.sub(r"bandwidth: \d+", f"bandwidth: {args.bandwidth}", text)
    if args.direct_samples is not None:
        text = re.sub(r"direct_samples_per_bin: \d+", f"direct_samples_per_bin: {args.direct_samples}", text)
    if args.accuracy is not None:
        text = re.sub(r"  photons_per_bin: \d+\n",
                      f"  accuracy: {{target_df_relative_stderr_percent: {args.accuracy}}}\n", text)
    return text


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--backward", required=True, metavar="MATRIX", help="the bench's matrix (all rows)")
    ap.add_argument("--backward-csv", required=True, metavar="CSV", help="the bench's per-sensor DF and standard error")
    ap.add_argument("--seeds", type=int, default=8)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--photons", type=int, default=None, help="simulation.photons_per_bin")
    ap.add_argument("--bandwidth", type=int, default=None, help="simulation.bandwidth")
    ap.add_argument("--accuracy", type=float, default=None,
                    help="simulation.accuracy target (percent) instead of photons_per_bin")
    ap.add_argument("--direct-samples", type=int, default=None, help="simulation.direct_samples_per_bin")
    ap.add_argument("--point-reference", nargs=2, action="append", default=[], metavar=("CSV", "SENSORS"),
                    help="a more converged backward reference at a few sensors: the --csv of "
                         "`office_backward_reference --pts` and the grid indices of its sensors in file order "
                         "(comma-separated); repeatable")
    ap.add_argument("--annual", action="store_true", help="keep the annual outputs, images and report")
    ap.add_argument("--dayphoton", default=os.path.join(ROOT, "build", "app", "dayphoton"))
    ap.add_argument("--work", default=None)
    args = ap.parse_args()
    if args.seeds < 2:
        raise SystemExit("--seeds: at least 2 (the spread needs two runs)")
    work = args.work or tempfile.mkdtemp(prefix="dayphoton-df-error-")
    os.makedirs(work, exist_ok=True)
    text = project_text(args)
    epw = "USA_CA_Oakland.Intl.AP.724930_TMY3.epw"
    with open(os.path.join(ROOT, "projects", "office", epw), "rb") as src, open(os.path.join(work, epw), "wb") as dst:
        dst.write(src.read())

    _, _, _, sv = v.read_matrix(os.path.join(v.REF, "skyvec_overcast_m1.vec"))
    rtrace = [float(r["DF_main_pct"]) for r in v.read_csv(os.path.join(v.REF, "df_office.csv"))]
    rows, cols, _, bc = v.read_matrix(args.backward)
    bw_band = df_per_band(bc, rows, cols, sv)
    bw = [sum(b) for b in bw_band]
    bw_csv = {int(r["index"]): r for r in v.read_csv(args.backward_csv)}
    if sorted(bw_csv) != list(range(rows)):
        raise SystemExit(f"{args.backward_csv}: expected sensors 0..{rows - 1} (the bench with rows 0 14)")
    for s in range(rows):  # the CSV and the matrix must be the same run
        if abs(float(bw_csv[s]["df_radiance_percent"]) / bw[s] - 1) > 1e-4:
            raise SystemExit(f"{args.backward_csv}: sensor {s} DF {bw_csv[s]['df_radiance_percent']} is not the "
                             f"matrix's {bw[s]:.6f}: not the same run")
    bw_relvar = [(float(bw_csv[s]["df_radiance_se_percent"]) / bw[s]) ** 2 for s in range(rows)]

    runs = []  # per seed: DF per sensor and band, relative variance, times
    for seed in range(args.first_seed, args.first_seed + args.seeds):
        project = os.path.join(work, f"seed{seed}.yaml")
        with open(project, "w") as f:
            f.write(re.sub(r"seed: \d+", f"seed: {seed}", text))
        out = os.path.join(work, f"seed{seed}")
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.monotonic()
        subprocess.run([args.dayphoton, "run", project, "--output", out, "--force", "--quiet"], check=True)
        wall = time.monotonic() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        r_, c_, _, c = v.read_matrix(os.path.join(out, "workplane", "coefficients_sky.mtx"))
        assert (r_, c_) == (rows, cols)
        band = df_per_band(c, rows, cols, sv)
        df = [sum(b) for b in band]
        own = v.read_csv(os.path.join(out, "workplane", "daylight_factor.csv"))
        relvar = [(float(r["df_stderr_percent"]) / float(r["df_percent"])) ** 2 for r in own]
        rel = [o / b - 1 for o, b in zip(df, bw)]
        rel_rt = [o / b - 1 for o, b in zip(df, rtrace)]
        runs.append({"df": df, "band": band, "relvar": relvar, "wall": wall, "cpu": cpu})
        print(f"seed {seed}: vs backward RMS {100 * rms(rel):.3f} %, largest {100 * max(rel, key=abs):+.3f} % "
              f"(beyond 3 %: {sum(1 for x in rel if abs(x) > 0.03)}); vs rtrace RMS {100 * rms(rel_rt):.3f} %, "
              f"largest {100 * max(rel_rt, key=abs):+.3f} %; reported noise RMS {100 * math.sqrt(statistics.mean(relvar)):.3f} %"
              f"; {wall:.2f} s wall, {cpu:.2f} s CPU", flush=True)

    n = len(runs)
    mean_df = [statistics.mean(r["df"][s] for r in runs) for s in range(rows)]
    m = [d / b - 1 for d, b in zip(mean_df, bw)]
    our_relvar = [statistics.mean(r["relvar"][s] for r in runs) for s in range(rows)]
    spread_relvar = [statistics.variance([r["df"][s] / mean_df[s] for r in runs]) for s in range(rows)]
    single_ms = statistics.mean(statistics.mean((r["df"][s] / bw[s] - 1) ** 2 for s in range(rows)) for r in runs)
    noise_in_mean = [our_relvar[s] / n + bw_relvar[s] for s in range(rows)]
    bias_ms = statistics.mean(x * x for x in m) - statistics.mean(noise_in_mean)
    print()
    changed = ", ".join(f"{k} {getattr(args, k)}" for k in ("photons", "bandwidth", "accuracy", "direct_samples")
                        if getattr(args, k) is not None)
    print(f"{n} runs, seeds {args.first_seed}-{args.first_seed + n - 1}, settings: {changed or 'as shipped'}")
    print(f"time per run: wall {statistics.mean(r['wall'] for r in runs):.2f} s (min {min(r['wall'] for r in runs):.2f}),"
          f" CPU {statistics.mean(r['cpu'] for r in runs):.2f} s (min {min(r['cpu'] for r in runs):.2f})")
    print(f"one run vs backward: RMS over runs' mean square {100 * math.sqrt(single_ms):.3f} %")
    print(f"  our noise, reported: RMS {100 * math.sqrt(statistics.mean(our_relvar)):.3f} %; "
          f"observed spread over the seeds: RMS {100 * math.sqrt(statistics.mean(spread_relvar)):.3f} % "
          f"(observed / reported variance {statistics.mean(spread_relvar) / statistics.mean(our_relvar):.3f})")
    print(f"  the reference's noise: RMS {100 * math.sqrt(statistics.mean(bw_relvar)):.3f} %, "
          f"largest {100 * math.sqrt(max(bw_relvar)):.3f} %")
    print(f"  mean over the seeds vs backward: RMS {100 * rms(m):.3f} %, largest {100 * max(m, key=abs):+.3f} % "
          f"(sensor {max(range(rows), key=lambda s: abs(m[s]))}); mean {100 * statistics.mean(m):+.3f} %, "
          f"noise left in it RMS {100 * math.sqrt(statistics.mean(noise_in_mean)):.3f} %")
    print(f"  bias RMS (beyond that noise): {100 * math.sqrt(max(0.0, bias_ms)):.3f} %"
          f"{' (none measurable)' if bias_ms <= 0 else ''}")
    print(f"  decomposition of one run's mean square: bias {1e4 * max(0.0, bias_ms):.3f} + our noise "
          f"{1e4 * statistics.mean(our_relvar):.3f} + reference noise {1e4 * statistics.mean(bw_relvar):.3f} = "
          f"{1e4 * (max(0.0, bias_ms) + statistics.mean(our_relvar) + statistics.mean(bw_relvar)):.3f} (%^2), "
          f"observed {1e4 * single_ms:.3f}")
    # One run against a converged result (no reference noise): the bias and our noise alone.
    print(f"  one run against a converged result (no reference noise): expected RMS "
          f"{100 * math.sqrt(max(0.0, bias_ms) + statistics.mean(our_relvar)):.3f} %")
    rt_mean = [d / r - 1 for d, r in zip(mean_df, rtrace)]
    print(f"  mean over the seeds vs rtrace: RMS {100 * rms(rt_mean):.3f} %, largest {100 * max(rt_mean, key=abs):+.3f} %"
          f"; the backward reference vs rtrace: RMS {100 * rms([b / r - 1 for b, r in zip(bw, rtrace)]):.3f} %")

    for path, indices in args.point_reference:
        sensors = [int(x) for x in indices.split(",")]
        refs = v.read_csv(path)
        if len(refs) != len(sensors):
            raise SystemExit(f"{path}: {len(refs)} sensors, {len(sensors)} indices given")
        print(f"  sensors of {os.path.basename(path)} (a more converged reference): per sensor the mean over the "
              f"seeds (its standard error), the seeds' spread, the runs beyond 3 %")
        for s, r in zip(sensors, refs):
            ref, ref_se = float(r["df_radiance_percent"]), float(r["df_radiance_se_percent"])
            xs = [run["df"][s] / ref - 1 for run in runs]
            print(f"    sensor {s} (x {0.5 + 0.5 * (s % COLUMNS):.1f} m, y {0.5 + 0.5 * (s // COLUMNS):.1f} m): "
                  f"{100 * statistics.mean(xs):+.2f} % "
                  f"(+-{100 * math.hypot(statistics.stdev(xs) / math.sqrt(n), ref_se / ref):.2f}), spread "
                  f"{100 * statistics.stdev(xs):.2f} %, beyond 3 %: {sum(1 for x in xs if abs(x) > 0.03)} of {n}; "
                  f"the full-grid reference there {100 * (bw[s] / ref - 1):+.2f} %")

    print()
    print("per row (y from the window): mean over the seeds vs backward (mean, its standard error), one run's RMS,"
          " our reported noise RMS, the reference's noise RMS")
    for row in range(rows // COLUMNS):
        ss = range(row * COLUMNS, (row + 1) * COLUMNS)
        mm = statistics.mean(m[s] for s in ss)
        se = math.sqrt(sum(noise_in_mean[s] for s in ss)) / COLUMNS
        one = math.sqrt(statistics.mean(statistics.mean((r["df"][s] / bw[s] - 1) ** 2 for s in ss) for r in runs))
        print(f"  y {0.5 + 0.5 * row:.1f} m: {100 * mm:+.3f} % (+-{100 * se:.3f}), one run {100 * one:.3f} %, "
              f"ours {100 * math.sqrt(statistics.mean(our_relvar[s] for s in ss)):.3f} %, "
              f"reference {100 * math.sqrt(statistics.mean(bw_relvar[s] for s in ss)):.3f} %")

    print()
    print("per sky band: share of the DF (reference), and the mean over the seeds of (ours - reference) in the band"
          " as a share of the sensor's DF (reference): grid mean, front (y < 4.5 m) and back (y >= 4.5 m) means,"
          " largest |.| of a sensor")
    for b, (name, _, _) in enumerate(band_ranges()):
        d = [(statistics.mean(r["band"][s][b] for r in runs) - bw_band[s][b]) / bw[s] for s in range(rows)]
        share = sum(bw_band[s][b] for s in range(rows)) / sum(bw)
        front = [d[s] for s in range(rows) if s // COLUMNS < 8]
        back = [d[s] for s in range(rows) if s // COLUMNS >= 8]
        print(f"  {name:10s} {100 * share:5.1f} % of the light: {100 * statistics.mean(d):+.3f} %, front "
              f"{100 * statistics.mean(front):+.3f} %, back {100 * statistics.mean(back):+.3f} %, largest "
              f"{100 * max(d, key=abs):+.3f} %")

    print()
    print("per sensor group: the mean over the seeds vs backward (its standard error), and the ground bin's mean "
          "difference as a share of the ground bin (its share of the DF)")
    for name, group in sensor_groups(rows):
        mm = statistics.mean(m[s] for s in group)
        se = math.sqrt(sum(noise_in_mean[s] for s in group)) / len(group)
        ground = statistics.mean((statistics.mean(r["band"][s][0] for r in runs) - bw_band[s][0]) / bw_band[s][0]
                                 for s in group)
        share = statistics.mean(bw_band[s][0] / bw[s] for s in group)
        print(f"  {name:34s} {100 * mm:+.2f} % (+-{100 * se:.2f}); ground bin {100 * ground:+.1f} % "
              f"({100 * share:.0f} % of the DF)")
    return 0


def sensor_groups(rows):
    """The office grid by distance to the walls: the sensors of the first and last column and
    row are 0.5 m from a wall, the four corners from two."""
    last_row, last_col = rows // COLUMNS - 1, COLUMNS - 1
    col = lambda s: s % COLUMNS  # noqa: E731
    row = lambda s: s // COLUMNS  # noqa: E731
    side = lambda s: col(s) in (0, last_col)  # noqa: E731
    return [
        ("front half (y < 4.5 m), columns 1-9", [s for s in range(rows) if row(s) < 8 and not side(s)]),
        ("back half interior (rows 8-13, 1-9)", [s for s in range(rows) if 8 <= row(s) < last_row and not side(s)]),
        ("side walls, front half (rows 0-7)", [s for s in range(rows) if side(s) and row(s) < 8]),
        ("side walls, back half (rows 8-13)", [s for s in range(rows) if side(s) and 8 <= row(s) < last_row]),
        ("back row (y 7.5 m), columns 1-9", [s for s in range(rows) if row(s) == last_row and not side(s)]),
        ("back corners", [s for s in range(rows) if row(s) == last_row and side(s)]),
    ]


if __name__ == "__main__":
    sys.exit(main())
