# Shared by run_complete_test.sh and run_disk_full_test.sh (sourced; needs $scratch):
# the office at small photon counts, and the checks of a complete and of an interrupted
# output folder (docs/outputs.md, "Complete or marked incomplete").

# The office at 4000 photons per bin, sun spread (no sun bins): a run of a few seconds.
mkdir -p "$scratch/office"
cp projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw "$scratch/office/"
sed -e 's/photons_per_bin: .*/photons_per_bin: 4000/' -e 's/images: true/images: false/' \
    -e 's/sun: bins/sun: spread/' projects/office/project.yaml >"$scratch/office/first.yaml"
# The changed inputs: other photons (a new photon pass) and no annual illuminance table.
sed -e 's/photons_per_bin: .*/photons_per_bin: 6000/' -e 's/annual_illuminance: true/annual_illuminance: false/' \
    "$scratch/office/first.yaml" >"$scratch/office/second.yaml"

# Prints the problems of a folder that claims to be complete; exit 0 if there are none.
check_complete() {
  python3 - "$1" <<'PY'
import hashlib, json, os, sys
out = sys.argv[1]
problems = []
if os.path.exists(os.path.join(out, "INCOMPLETE")): problems.append("INCOMPLETE present")
if os.path.exists(os.path.join(out, ".dayphoton.lock")): problems.append("lock file left behind")
summary = json.load(open(os.path.join(out, "summary.json")))
listed = set()
for f in summary["files"]:
    listed.add(f["path"])
    data = open(os.path.join(out, f["path"]), "rb").read()
    if len(data) != f["bytes"] or hashlib.sha256(data).hexdigest() != f["sha256"]:
        problems.append(f"{f['path']}: size or hash differs from summary.json")
for root, dirs, files in os.walk(out):
    for name in files:
        rel = os.path.relpath(os.path.join(root, name), out)
        if rel not in listed and rel not in ("summary.json", "run.log", "timings.json"):
            problems.append(f"{rel}: not in summary.json's files")
for p in problems[:20]: print("  " + p)
sys.exit(1 if problems else 0)
PY
}

# Prints the problems of an interrupted folder: it must be marked incomplete and hold no
# output older than the reference file $2 (the moment the interrupted run started).
check_incomplete() {
  python3 - "$1" "$2" <<'PY'
import os, sys
out, ref = sys.argv[1], os.path.getmtime(sys.argv[2])
problems = []
if os.path.exists(os.path.join(out, "summary.json")): problems.append("summary.json present")
if not os.path.exists(os.path.join(out, "INCOMPLETE")): problems.append("no INCOMPLETE marker")
for root, dirs, files in os.walk(out):
    for name in files:
        path = os.path.join(root, name)
        if os.path.getmtime(path) < ref:
            problems.append(f"{os.path.relpath(path, out)}: left by the earlier run")
for p in problems[:20]: print("  " + p)
sys.exit(1 if problems else 0)
PY
}

