#!/usr/bin/env bash
# Fuzz the input readers: build the libFuzzer harnesses of fuzz/ with clang, instrumented with
# AddressSanitizer and UndefinedBehaviorSanitizer (any undefined behaviour is fatal), into
# build-fuzz/, then run each harness for MINUTES minutes (default 5), one after the other.
#
#   bash scripts/fuzz.sh [MINUTES] [HARNESS...]     # harnesses: project epw obj pts matrix
#
# Each harness starts from its seeds in fuzz/corpus/<name>/ and grows build-fuzz/corpus/<name>/,
# with the dictionary fuzz/<name>.dict if there is one.
# It runs in libFuzzer's fork mode and keeps going after a finding, so one run reports every
# distinct crash, leak, timeout or out-of-memory of its time: the inputs are written to
# build-fuzz/artifacts/<name>/, the log to build-fuzz/<name>.log. The script ends with one line
# per harness (executions, coverage, findings) and exits 1 if anything was found.
# Needs Debian's clang and libfuzzer-14-dev (scripts/setup.sh installs them). docs/fuzzing.md.
set -euo pipefail
cd "$(dirname "$0")/.."

minutes=${1:-5}
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(project epw obj pts matrix)
case "$minutes" in ''|0|*[!0-9]*) echo "fuzz.sh: MINUTES must be a whole number from 1, got '$minutes'" >&2; exit 2;; esac

# libFuzzer's limits of one input (libFuzzer documentation, "Options"): a single allocation
# over 1 GiB, a process over 2 GiB or an input running longer than 10 s is a finding.
malloc_limit_mb=1024
rss_limit_mb=2048
timeout_s=10

flags="-O1 -g -fno-omit-frame-pointer -fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_FLAGS="$flags" -DDAYPHOTON_FUZZ=ON -DDAYPHOTON_BUILD_TESTS=OFF -DDAYPHOTON_BUILD_BENCH=OFF \
  "${launcher[@]}"
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build build-fuzz -j"$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
summary=()
found=0
for h in "${harnesses[@]}"; do
  mkdir -p "build-fuzz/corpus/$h" "build-fuzz/artifacts/$h"
  echo "fuzz.sh: fuzzing $h for $minutes min (log build-fuzz/$h.log)"
  dict=()
  [ ! -f "fuzz/$h.dict" ] || dict=(-dict="fuzz/$h.dict")
  # Fork mode with one worker: a finding is saved and the run goes on (-ignore_*).
  "build-fuzz/fuzz/fuzz_$h" -max_total_time=$((minutes * 60)) -timeout=$timeout_s \
    -malloc_limit_mb=$malloc_limit_mb -rss_limit_mb=$rss_limit_mb \
    -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 "${dict[@]}" \
    -artifact_prefix="build-fuzz/artifacts/$h/" "build-fuzz/corpus/$h" "fuzz/corpus/$h" \
    > "build-fuzz/$h.log" 2>&1 || true
  last=$(grep -E '^#[0-9]+: cov:' "build-fuzz/$h.log" | tail -1 || true)
  n=$(find "build-fuzz/artifacts/$h" -type f | wc -l)
  [ "$n" -eq 0 ] || found=1
  summary+=("$h: ${last:-no progress line, see build-fuzz/$h.log}; findings: $n")
done
printf 'fuzz.sh: %s\n' "${summary[@]}"
exit $found
