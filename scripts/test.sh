#!/usr/bin/env bash
# The second set-up command of README.md: (re)build and run the whole test suite with CTest,
# which prints its summary ("100% tests passed, 0 tests failed out of N") at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -f build/CMakeCache.txt ] || cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
