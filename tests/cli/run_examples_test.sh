#!/bin/bash
# Every example project runs (issue 6 acceptance: "every system has an example project that
# runs in CI in under a minute at reduced photon counts"). For each projects/*/project.yaml,
# `dayphoton run` into a fresh folder must succeed within MAX_SECONDS (default 60) and write
# summary.json and, for the base case and every variant, each grid's daylight_factor.csv and
# (unless the study is daylight-factor only) metrics.csv with finite, non-negative values (the index and x,y,z columns excepted). Prints
# each project's wall time. The example projects keep their own photon counts small enough
# for this (docs/daylight-systems.md, "Examples"), but for those whose counts are a validation
# test's, which runs them as written: those run here as a copy with fewer photons (`reduced`
# below).
# Usage: DAYPHOTON=path/to/dayphoton bash run_examples_test.sh [name ...]  (from the
# repository root; names restrict the run to those projects).
set -u
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
max_seconds=${MAX_SECONDS:-60}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

if [ $# -gt 0 ]; then
  projects=()
  for name in "$@"; do projects+=("projects/$name/project.yaml"); done
else
  projects=(projects/*/project.yaml)
fi

# Checks one run's output folder: prints nothing and exits 0 when it is complete.
check_outputs() {
  python3 - "$1" <<'PY'
import csv, json, math, os, sys
out = sys.argv[1]
problems = []
with open(os.path.join(out, "summary.json")) as f:
    summary = json.load(f)
cases = [("base", summary["grids"])] + [(v["name"], v["grids"]) for v in summary["variants"]]
# A daylight-factor-only study (study: daylight_factor) writes no annual metrics.
outputs = ("daylight_factor.csv",) if summary.get("study") == "daylight_factor" else ("daylight_factor.csv", "metrics.csv")
for case, grids in cases:
    if not grids:
        problems.append(f"{case}: no grids")
    for g in grids:
        for name in outputs:
            path = os.path.join(g["folder"], name)
            if not os.path.isfile(path):
                problems.append(f"{case}/{g['name']}: no {name}")
                continue
            with open(path, newline="") as f:
                rows = list(csv.reader(f))
            header, body = rows[0], rows[1:]
            if len(body) != g["sensors"]:
                problems.append(f"{path}: {len(body)} rows for {g['sensors']} sensors")
            values = [c for c, h in enumerate(header) if h not in ("index", "x", "y", "z")]
            if not values:
                problems.append(f"{path}: no value columns in {header}")
            for r, row in enumerate(body, start=2):
                for c in values:
                    v = float(row[c])
                    if not math.isfinite(v) or v < 0:
                        problems.append(f"{path}:{r}: {header[c]} = {row[c]}")
                        break
for p in problems[:20]:
    print("  " + p)
sys.exit(1 if problems else 0)
PY
}

# Examples whose photon counts are set by a validation test that runs them as written:
# projects/wall_sensors (cli_sensor_reference, which runs it as a daylight-factor study: 20 000
# photons per bin and 1,024 gather rays per sensor for its 2 and 3 % RMS goals; the whole
# project 27 CPU s, 85 s wall at a load of 13 on 2 cores). Here
# the same project with a quarter of both (10 CPU s, 33 s wall at that load): the same steps
# and output files, and what this test checks of them (present, a row per sensor, finite,
# non-negative) does not depend on the noise. name -> sed script for the copy, and the lines
# it writes (separated by |), each of which must then be there (a changed project file fails
# the test instead of running unreduced).
declare -A reduced=(
  [wall_sensors]='s/^  photons_per_bin: 20000 .*$/  photons_per_bin: 5000/; s/^  direct_samples_per_bin: 64$/&\n  gather_rays: 256/'
)
declare -A reduced_lines=([wall_sensors]='  photons_per_bin: 5000|  gather_rays: 256')

# The project file to run for example $1: projects/$1/project.yaml, or its reduced copy in a
# mirror of projects/ made of links (so that relative paths such as ../office's weather file
# stay valid, and nothing of a results folder is copied). Prints it.
project_to_run() {
  local name=$1
  if [ -z "${reduced[$name]:-}" ]; then echo "projects/$name/project.yaml"; return 0; fi
  local mirror=$scratch/projects entry line lines
  mkdir -p "$mirror/$name"
  for entry in projects/*; do [ -e "$mirror/${entry#projects/}" ] || ln -s "$PWD/$entry" "$mirror/"; done
  for entry in "projects/$name"/*; do
    [ "${entry##*/}" = project.yaml ] || ln -s "$PWD/$entry" "$mirror/$name/"
  done
  local copy=$mirror/$name/project.yaml
  cp "projects/$name/project.yaml" "$copy"
  sed -i "${reduced[$name]}" "$copy"
  IFS='|' read -ra lines <<<"${reduced_lines[$name]}"
  for line in "${lines[@]}"; do grep -qxF "$line" "$copy" || return 1; done
  echo "$copy"
}

failed=0
for project in "${projects[@]}"; do
  name=$(basename "$(dirname "$project")")
  out="$scratch/$name"
  if ! project=$(project_to_run "$name"); then
    echo "FAIL $name: its reduced copy lacks the changed lines (${reduced_lines[$name]})"; failed=$((failed + 1)); continue
  fi
  start=$(date +%s%N)
  "$bin" run "$project" --output "$out" --quiet >"$scratch/$name.log" 2>&1
  status=$?
  ms=$((($(date +%s%N) - start) / 1000000))
  shown="$((ms / 1000)).$((ms % 1000 / 100))"
  if [ $status -ne 0 ]; then
    echo "FAIL $name: exit $status after $shown s"; tail -5 "$scratch/$name.log"; failed=$((failed + 1)); continue
  fi
  if ! problems=$(check_outputs "$out"); then
    echo "FAIL $name: outputs ($shown s)"; echo "$problems"; failed=$((failed + 1)); continue
  fi
  if [ $ms -gt $((max_seconds * 1000)) ]; then
    echo "FAIL $name: $shown s, more than $max_seconds s"; failed=$((failed + 1)); continue
  fi
  capped=$(grep -h "capped at" "$out/run.log" | sed 's/^/       /')
  note=
  [ -n "${reduced[$name]:-}" ] && note=" (reduced copy: fewer photons and gather rays)"
  echo "ok   $name: $shown s$note"
  [ -n "$capped" ] && echo "$capped"
done
[ $failed -eq 0 ] || { echo "$failed of ${#projects[@]} example projects failed"; exit 1; }
echo "all ${#projects[@]} example projects ran"
