#!/usr/bin/env bash
# Builds tidepool and runs every test (on lavapipe, with validation on).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# The CPU-side code again, built by clang with AddressSanitizer and
# UndefinedBehaviorSanitizer: its tests, and the two fuzz targets for a
# bounded time each (cmake/sanitized_cpu.cmake).
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DTIDEPOOL_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build build-fuzz --parallel "$(nproc)"
ctest --test-dir build-fuzz --output-on-failure --parallel "$(nproc)"
