#!/usr/bin/env bash
# CI's sanitizer pass (.ci/run, after the README's two commands): build the fast test suites
# with AddressSanitizer and UndefinedBehaviorSanitizer (gcc; any undefined behaviour is fatal)
# into build-asan/, then run them: the unit tests of core, weather, metrics and project,
# and the replay of the fuzz corpora (tests/fuzz/). The long engine, study, CLI and report
# tests are left to the normal build. Extra CTest arguments are passed on.
#
#   bash scripts/test_sanitizers.sh [CTEST_ARGS...]
#
# docs/fuzzing.md ("Sanitizers in CI").
set -euo pipefail
cd "$(dirname "$0")/.."

# The parsers and the input-facing libraries; sky (pure arithmetic on validated inputs) runs in
# the normal build only, which keeps .ci/run under 20 minutes (docs/fuzzing.md).
suites=(core weather metrics project)
# -g1: line tables only, enough for file:line in sanitizer reports and a third less compile time
# than -g (measured on load_project.cpp: 27.9 against 40.4 CPU s). It is the Debug build type's
# own flag: CMake puts CMAKE_CXX_FLAGS_DEBUG (by default -g) after CMAKE_CXX_FLAGS, and gcc
# takes the last -g option. Configured every time (a second of CMake), so that a build-asan/
# of an earlier version of these flags gets them too.
flags="-O1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_CXX_FLAGS_DEBUG=-g1 \
  -DDAYPHOTON_BUILD_BENCH=OFF > /dev/null

targets=()
for s in "${suites[@]}"; do targets+=("${s}_tests"); done
# Every fuzz harness's corpus replay (the list is declared once, in fuzz/harnesses.cmake).
harnesses=$(sed -n 's/^set(DAYPHOTON_FUZZ_HARNESSES \(.*\))$/\1/p' fuzz/harnesses.cmake)
[ -n "$harnesses" ] || { echo "test_sanitizers.sh: no DAYPHOTON_FUZZ_HARNESSES in fuzz/harnesses.cmake" >&2; exit 1; }
for h in $harnesses; do targets+=("fuzz_replay_$h"); done
cmake --build build-asan -j"$(nproc)" --target "${targets[@]}"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
labels=$(IFS='|'; echo "${suites[*]}|fuzz")
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -L "^($labels)\$" "$@"
