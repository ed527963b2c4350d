#!/usr/bin/env bash
# Bad-input tests: run the real binary ($DAYPHOTON) from the repository root on every case of
# a folder of bad inputs (tests/data/bad/<area>/) and compare exit code and combined
# stdout/stderr with the case's expected output.
#
#   run_bad_inputs.sh tests/data/bad/matrices
#
# The folder's `cases` file has one case per line, `NAME ARGS...` (blank lines and # comments
# skipped). In ARGS, $DATA is the folder, $EPW the office weather file and $SCRATCH a fresh
# temporary folder holding a named pipe `fifo`, a grid folder `fifo_grid` whose
# coefficients_sky.mtx is a named pipe and a results folder `fifo_results` whose
# summary.json is one. The expected output is NAME.expected in the folder:
# the output with the scratch path written as $SCRATCH, then "exit N". Every case must finish
# within 30 s (a hang is a failure). UPDATE=1 rewrites the expected files (review the diff).
set -u
cd "$(dirname "$0")/../.."
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
dir=${1:?usage: run_bad_inputs.sh FOLDER}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkfifo "$scratch/fifo"
mkdir "$scratch/fifo_grid"
mkfifo "$scratch/fifo_grid/coefficients_sky.mtx"
printf 'index,x,y,z,nx,ny,nz\n0,1,1,0.8,0,0,1\n' >"$scratch/fifo_grid/sensors.csv"
mkdir "$scratch/fifo_results"
mkfifo "$scratch/fifo_results/summary.json"
export DATA=$dir EPW=projects/office/USA_CA_Oakland.Intl.AP.724930_TMY3.epw SCRATCH=$scratch
passed=0
failed=0
while read -r name args; do
  case "$name" in '' | '#'*) continue ;; esac
  eval "set -- $args"
  out="$scratch/$name.out"
  timeout 30 "$bin" "$@" >"$out.raw" 2>&1
  code=$?
  sed "s|$scratch|\$SCRATCH|g" "$out.raw" >"$out"
  echo "exit $code" >>"$out"
  if [ "${UPDATE:-0}" = 1 ]; then cp "$out" "$dir/$name.expected"; fi
  if [ "$code" -eq 124 ]; then
    echo "FAIL $name: still running after 30 s"; failed=$((failed + 1)); continue
  fi
  if ! diff -u "$dir/$name.expected" "$out"; then
    echo "FAIL $name: output differs from $dir/$name.expected"; failed=$((failed + 1)); continue
  fi
  echo "ok   $name"; passed=$((passed + 1))
done <"$dir/cases"
echo "$dir: $passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
