#!/usr/bin/env bash
# `dayphoton annual --project` reproduces `run`'s metrics: tests/cli/cases/school (a school's
# week with a lunch break, a free Wednesday afternoon, holidays and US daylight saving time;
# sun spread into the sky patches, so the exported sky coefficients hold the whole result).
# The run and annual must give the same occupied hours, the same mean DA500 and a
# byte-identical metrics.csv, also without the project (the schedule recorded in results.json);
# annual with --occupancy-hours / --da-threshold overrides must differ as the settings say.
set -u
cd "$(dirname "$0")/../.."
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL $*"; exit 1; }
project=tests/cli/cases/school/project.yaml

"$bin" run "$project" --output "$scratch/run" --quiet || fail "run exited $?"
grep -q "^occupancy desks: Monday, Tuesday 08:00-12:00, 13:00-15:30; Wednesday 08:00-12:00;.* US daylight saving time; [0-9]* occupied hours of 8760$" \
  "$scratch/run/run.log" || fail "run.log does not state the schedule: $(grep occupancy "$scratch/run/run.log")"
"$bin" annual --coefficients "$scratch/run/desks" --project "$project" -o "$scratch/annual" >"$scratch/annual.out" ||
  fail "annual --project exited $?: $(cat "$scratch/annual.out")"
cmp -s "$scratch/run/desks/metrics.csv" "$scratch/annual/metrics.csv" || fail "metrics.csv of annual --project differs from run's"
python3 - "$scratch" <<'PY' || exit 1
import json, sys
d = sys.argv[1]
run = next(g for g in json.load(open(d + "/run/summary.json"))["grids"] if g["name"] == "desks")["annual"]
ann = json.load(open(d + "/annual/grid_metrics.json"))
assert run["occupied_hours"] == ann["occupied_hours"], (run["occupied_hours"], ann["occupied_hours"])
assert run["mean"]["da500_percent"] == ann["mean"]["da500_percent"], (run["mean"], ann["mean"])
assert run["occupancy"] == ann["occupancy"] and run["thresholds"] == ann["thresholds"]
assert ann["occupancy"]["january_1"]["weekday"] == "Sunday"  # the EPW's DATA PERIODS
assert 0 < ann["occupied_hours"] < 3650
PY
# Without the project: the school's week, holidays and DST as the run recorded them in results.json.
"$bin" annual --coefficients "$scratch/run/desks" --weather projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw \
  -o "$scratch/recorded" --quiet || fail "annual without the project exited $?"
cmp -s "$scratch/run/desks/metrics.csv" "$scratch/recorded/metrics.csv" || fail "metrics.csv of annual from results.json differs from run's"
# The grid with its own schedule (every day, clock time): annual takes it from the folder's name.
grep -q "^occupancy club: Monday-Sunday 08:00-18:00; local clock time with US daylight saving time; 3650 occupied hours of 8760$" \
  "$scratch/run/run.log" || fail "run.log: $(grep "occupancy club" "$scratch/run/run.log")"
"$bin" annual --coefficients "$scratch/run/club" --project "$project" -o "$scratch/club" --quiet || fail "annual club exited $?"
cmp -s "$scratch/run/club/metrics.csv" "$scratch/club/metrics.csv" || fail "club: metrics.csv of annual --project differs from run's"
grep -q "mean DA500 " "$scratch/annual.out" || fail "annual does not print DA500: $(cat "$scratch/annual.out")"

# Overrides: the every-day LM-83 window and DA300 (3650 occupied hours, other values).
"$bin" annual --coefficients "$scratch/run/desks" --project "$project" --occupancy-hours 8 18 --da-threshold 300 \
  -o "$scratch/override" --quiet || fail "annual with overrides exited $?"
python3 - "$scratch" <<'PY' || exit 1
import json, sys
d = sys.argv[1]
o = json.load(open(d + "/override/grid_metrics.json"))
assert o["occupied_hours"] == 3650, o["occupied_hours"]
assert "da300_percent" in o["mean"] and o["thresholds"]["da_lux"] == 300
PY
# A CSV schedule (one 0/1 per record) equal to the LM-83 window gives the default's metrics.
python3 - "$scratch" "$PWD" <<'PY' || exit 1
import re, sys
d, root = sys.argv[1], sys.argv[2]
with open(d + "/lm83.csv", "w") as f:
    f.write("occupied\n" + "".join("1\n" if 8 <= i % 24 < 18 else "0\n" for i in range(8760)))
text = open(root + "/tests/cli/cases/school/project.yaml").read()
text = re.sub(r"weather: .*", "weather: " + root + "/projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw", text)
text = re.sub(r"  occupancy:\n(    .*\n)+", "  occupancy: {file: lm83.csv}\n", text)
open(d + "/csv_project.yaml", "w").write(text)
PY
"$bin" annual --coefficients "$scratch/run/desks" --project "$scratch/csv_project.yaml" -o "$scratch/csv" --quiet ||
  fail "annual with a CSV schedule exited $?"
"$bin" annual --coefficients "$scratch/run/desks" --project "$scratch/csv_project.yaml" --occupancy-hours 8 18 \
  -o "$scratch/window" --quiet || fail "annual with the window exited $?"
cmp -s "$scratch/csv/metrics.csv" "$scratch/window/metrics.csv" || fail "the CSV schedule's metrics differ from the window's"
grep -q '"file"' "$scratch/csv/grid_metrics.json" || fail "grid_metrics.json does not name the CSV"

# A bad override is a usage error (exit 2), and --weather is needed without a project.
"$bin" annual --coefficients "$scratch/run/desks" --project "$project" --occupancy-hours 18 8 --quiet >/dev/null 2>&1
[ $? -eq 2 ] || fail "--occupancy-hours 18 8 is not a usage error"
"$bin" annual --coefficients "$scratch/run/desks" --quiet >/dev/null 2>&1
[ $? -eq 2 ] || fail "annual without --weather and --project is not a usage error"
echo "ok   annual --project reproduces run's metrics (school week, holidays, US DST)"
