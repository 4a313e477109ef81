#!/usr/bin/env bash
# Sets up a fresh machine, builds Riemesh and runs the whole test suite (ctest).
# With --sanitize, also builds the unit tests with ASan+UBSan into build-asan/ and runs them.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
if [ "${1:-}" = "--sanitize" ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DRIEMESH_SANITIZE=ON \
        -DRIEMESH_BUILD_BENCH=OFF >/dev/null
  cmake --build build-asan -j "$(nproc)"
  ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
fi
