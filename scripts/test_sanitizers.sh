#!/usr/bin/env bash
# CI's sanitizer pass (.ci/run, after the README's two commands): build the fast test suites
# with AddressSanitizer and UndefinedBehaviorSanitizer (gcc; any undefined behaviour is fatal)
# into build-asan/, then run them: the unit tests of core, weather, sky, metrics and project,
# and the replay of the fuzz corpora (tests/fuzz/). The long engine, study, CLI and report
# tests are left to the normal build. Extra CTest arguments are passed on.
#
#   bash scripts/test_sanitizers.sh [CTEST_ARGS...]
#
# docs/fuzzing.md ("Sanitizers in CI").
set -euo pipefail
cd "$(dirname "$0")/.."

suites=(core weather sky metrics project)
flags="-O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
[ -f build-asan/CMakeCache.txt ] ||
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="$flags" -DDAYPHOTON_BUILD_BENCH=OFF

targets=()
for s in "${suites[@]}"; do targets+=("${s}_tests"); done
for h in project epw obj pts matrix; do targets+=("fuzz_replay_$h"); done
cmake --build build-asan -j"$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
labels=$(IFS='|'; echo "${suites[*]}|fuzz")
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -L "^($labels)\$" "$@"
