#!/usr/bin/env bash
# A grid of a daylight-factor run against an independent backward Monte Carlo reference made by
# bench/office_backward_reference (docs/validation.md; the references and how they were made:
# tests/data/reference/README.md), column df_cie_continuous_percent: the CIE overcast sky,
# continuous, as the DF's sky component is.
#
#   run_backward_reference_test.sh PROJECT GRID REFERENCE_CSV [--daylight-factor]
#
# --daylight-factor runs a copy of PROJECT as a daylight-factor study (`study: daylight_factor`,
# its weather line dropped), for a shipped annual project. Per sensor z = (DF - reference) /
# sqrt(se^2 + se_ref^2), with the run's df_stderr_percent and the reference's standard error.
# Bounds from the variance alone, for n independent sensors at a 1 % false-alarm rate each:
# RMS z below the square root of the chi-square 99.9th percentile with n degrees of freedom
# over n (Wilson and Hilferty's approximation, within 0.2 % of the tables for n >= 20), and
# every |z| within the two-sided normal bound of 0.01 / n (Bonferroni).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
dayphoton="${DAYPHOTON:-$root/build/app/dayphoton}"
project=$1 grid=$2 reference=$3 mode=${4:-}
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
if [ "$mode" = --daylight-factor ]; then
  copy=$work/$(basename "$project")
  sed 's/^version: 1$/version: 1\nstudy: daylight_factor/; /^weather: /d' "$project" > "$copy"
  grep -qx 'study: daylight_factor' "$copy" || { echo "$project: no version line to put the study after"; exit 1; }
  # Files the project names relative to its folder.
  for f in "$(dirname "$project")"/*; do [ -e "$work/$(basename "$f")" ] || ln -s "$f" "$work/$(basename "$f")"; done
  project=$copy
fi
"$dayphoton" run "$project" --output "$work/out" --quiet
python3 - "$work/out/$grid/daylight_factor.csv" "$reference" "$grid" <<'PY'
import csv, math, statistics, sys
ours = list(csv.DictReader(open(sys.argv[1])))
ref = list(csv.DictReader(l for l in open(sys.argv[2]) if not l.startswith("#")))
assert len(ours) == len(ref) and ours, (len(ours), len(ref))
z = []
for o, r in zip(ours, ref):
    for k in ("x", "y", "z"):
        assert abs(float(o[k]) - float(r[k])) < 1e-9, (o, r)
    d, s = float(o["df_percent"]), float(o["df_stderr_percent"])
    t, u = float(r["df_cie_continuous_percent"]), float(r["df_cie_continuous_se_percent"])
    z.append((d - t) / math.hypot(s, u))
    print(f"  ({o['x']}, {o['y']}): DF {d:.4f} +- {s:.4f} %, reference {t:.4f} +- {u:.4f} %, "
          f"{100 * (d / t - 1):+.2f} %, z {z[-1]:+.2f}")
n = len(z)
normal = statistics.NormalDist()
h = 2 / (9 * n)
chi2_999 = n * (1 - h + normal.inv_cdf(0.999) * math.sqrt(h)) ** 3
rms_bound = math.sqrt(chi2_999 / n)
z_bound = normal.inv_cdf(1 - 0.005 / n)
rms = math.sqrt(sum(v * v for v in z) / n)
worst = max(z, key=abs)
ok = rms <= rms_bound and abs(worst) <= z_bound
print(f"{'ok  ' if ok else 'FAIL'} {sys.argv[3]} vs backward reference ({n} sensors): RMS z {rms:.2f} "
      f"(bound {rms_bound:.3f}), largest z {worst:+.2f} (bound {z_bound:.2f})")
sys.exit(0 if ok else 1)
PY
