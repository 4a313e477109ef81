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
  # The heaviest CLI scripts (3D and surface remeshing end to end: about 210 of the 350 s the
  # sanitized tests took) run in the plain pass only; the unit tests run that library code sanitized.
  ctest --test-dir build-asan --output-on-failure -j "$(nproc)" \
        -E '^cli\.test_(adapt3d|adapt3d_curved|adapt3d_geometry|mesh3d|mesh|adapt_surface)$'
fi
