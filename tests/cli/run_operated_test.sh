#!/bin/bash
# Operated shading end to end (project key `operation`, LM-83 blinds rule): `dayphoton run`
# on projects/blinds (open = raised, shaded = closed; small photon counts, ~10 s), then from
# the files alone:
#  1. operated/workplane/ has the annual files, shading_schedule.csv (8760 rows) and
#     operation.json; summary.json has `operated`;
#  2. every row of the operated illuminance.bin is, byte for byte, the closed variant's row
#     where the schedule says shaded and the raised variant's row elsewhere;
#  3. the schedule's `shaded` column is the rule applied to its own counts (100 sunlit > 2 n),
#     and the shaded-hour counts in operation.json agree with it;
#  4. the operated ASE equals the raised case's (LM-83: blinds retracted);
#  5. results.json gives LM-83's ASE and sDA verdicts to the operated result and the raised
#     case, and none to the cases with the blinds in place (their ASE is the sun through the
#     slats: 0 % for `tilted`, 30 % without the blinds);
#  6. a second run traces nothing, finds the same schedule and the same row choice.
# Usage: DAYPHOTON=path/to/dayphoton bash run_operated_test.sh  (from the repository root)
set -u
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
fail() { echo "FAIL $*"; exit 1; }
out="$scratch/results"

start=$(date +%s)
"$bin" run projects/blinds/project.yaml --output "$out" --quiet || fail "run failed"
echo "ok   dayphoton run projects/blinds: $(($(date +%s) - start)) s"

op="$out/operated/workplane"
for f in sensors.csv illuminance.bin metrics.csv grid_metrics.json shading_schedule.csv operation.json; do
  [ -s "$op/$f" ] || fail "missing $op/$f"
done
[ "$(wc -l <"$op/shading_schedule.csv")" -eq 8761 ] || fail "shading_schedule.csv: $(wc -l <"$op/shading_schedule.csv") lines"
grep -q '"operated"' "$out/summary.json" || fail "summary.json has no operated section"
echo "ok   operated files and summary"

# 2. Row choice. The schedule's last column is `shaded`.
check_rows() {
python3 - "$op/shading_schedule.csv" "$out/variants/raised/workplane/illuminance.bin" \
    "$out/variants/closed/workplane/illuminance.bin" "$op/illuminance.bin" <<'PY' || fail "operated table"
import struct, sys
sched, raised, closed, operated = sys.argv[1:5]
tables = [open(p, "rb").read() for p in (raised, closed, operated)]
T, S = struct.unpack_from("<II", tables[0], 8)
if any(t[:16 + 8 * T] != tables[0][:16 + 8 * T] for t in tables):
    sys.exit("header or time stamps differ")
row = lambda t, i: t[16 + 8 * T + 4 * S * i:16 + 8 * T + 4 * S * (i + 1)]
rows = open(sched).read().splitlines()[1:]
if len(rows) != T or T != 8760:
    sys.exit(f"{len(rows)} schedule rows, {T} table rows")
shaded = differ = 0
for i, line in enumerate(rows):
    f = line.split(",")
    want = tables[1] if f[6] == "1" else tables[0]
    if row(tables[2], i) != row(want, i):
        sys.exit(f"row {i + 1} ({line}): operated row is not the {'closed' if f[6] == '1' else 'raised'} row")
    shaded += f[6] == "1"
    differ += row(tables[0], i) != row(tables[1], i)
if shaded == 0:
    sys.exit("no hour shaded: the test would not distinguish the cases")
print(f"ok   {T} operated rows: {shaded} from closed, {T - shaded} from raised ({differ} rows differ between the cases)")
PY
}
check_rows

# 3. The rule on the schedule's own counts, and the totals.
sensors=$(($(wc -l <"$op/sensors.csv") - 1))
read -r all occ < <(awk -F, -v n="$sensors" 'NR > 1 {
    want = (100 * $5 > 2 * n) ? 1 : 0
    if ($7 != want) { print "bad " NR; exit 1 }
    all += $7; if ($4 == 1) occ += $7 } END { print all, occ }' "$op/shading_schedule.csv")
[ "$all" != "bad" ] || fail "shading_schedule.csv: a row breaks the rule"
grep -q "\"shaded_hours\": $all," "$op/operation.json" || fail "operation.json shaded_hours != $all"
grep -q "\"shaded_occupied_hours\": $occ" "$op/operation.json" || fail "operation.json shaded_occupied_hours != $occ"
echo "ok   schedule follows the rule: $all hours shaded, $occ of them occupied"

# 4. ASE of the operated result = ASE of the open (raised) case.
ase() { grep '"ase_percent"' "$1" | head -1 | tr -d ' ,'; }
[ "$(ase "$op/grid_metrics.json")" = "$(ase "$out/variants/raised/workplane/grid_metrics.json")" ] ||
  fail "operated ASE $(ase "$op/grid_metrics.json") != raised $(ase "$out/variants/raised/workplane/grid_metrics.json")"
echo "ok   operated ASE = raised ASE: $(ase "$op/grid_metrics.json")"

# 5. The verdicts: LM-83 sDA and ASE only where no blinds are in place (every hour, or in the
# open case of the operated result).
python3 - "$out/results.json" <<'PY' || fail "LM-83 verdicts with blinds in place"
import json, sys
m = json.load(open(sys.argv[1]))
for c in m["cases"]:
    name = c["name"] or "base"
    blinds = c.get("blinds_in_place", [])
    assert (blinds == ["venetian"]) == (c["kind"] != "operated" and name != "raised"), (name, blinds)
    for g in c["grids"]:
        for v in g["verdicts"]:
            if v["standard"].startswith(("IES", "LEED")):
                assessed = v["outcome"] != "not assessed"
                assert assessed == (not blinds), (name, v)
                assert blinds or v["value"] is not None, (name, v)
                assert not blinds or "'venetian' are in place every hour" in v["reason"], (name, v)
PY
echo "ok   LM-83 verdicts only for the operated result and the raised case"

# A second run takes every case from the cache and operates again. (Its tables are not
# byte-compared with the first run's: a fresh and a cached sun-bins run differ in rare last
# float bits, for every case, operated or not.)
"$bin" run projects/blinds/project.yaml --output "$out" --quiet || fail "second run failed"
grep -q "photons: traced 0 of" "$out/run.log" || fail "second run traced photons"
grep -q "sun photons: traced 0 of" "$out/run.log" || fail "second run traced sun photons"
grep -q "^operated workplane: 'closed' in $all of 8760 hours" "$out/run.log" || fail "second run: $(grep operated "$out/run.log")"
check_rows
echo "ok   second run: nothing traced, the same schedule, rows from the cases again"
echo "6 passed, 0 failed"
