# Shared by run_gathered_accuracy_test.sh and run_gathered_sun_accuracy_test.sh (sourced; needs
# $case_file, a case run from the source root): runs it with 1 and 2 threads, each without a
# cache, into $scratch/1 and $scratch/2 (removed on exit), and sets failed=0.
set -eu
bin=${DAYPHOTON:?set DAYPHOTON to the dayphoton executable}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The same output path for both runs (summary.json names it).
for threads in 1 2; do
  rm -rf "$scratch/run" "$scratch/.run-cache"
  "$bin" run "$case_file" --output "$scratch/run" --threads $threads --quiet
  mv "$scratch/run" "$scratch/$threads"
done
failed=0

# Sets failed=1 unless the two runs wrote the same bytes (run.log and timings.json aside).
check_same_bytes() {
  if diff -r -q -x run.log -x timings.json "$scratch/1" "$scratch/2"; then
    echo "ok   1 and 2 threads give the same bytes"
  else
    echo "FAIL 1 and 2 threads differ"; failed=1
  fi
}
