#!/usr/bin/env bash
# Builds tidepool and runs every test (on lavapipe, with validation on).
#   bash tools/test.sh           every test: what CI runs
#   bash tools/test.sh --quick   the tests labelled quick, a few minutes: before a commit
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
case "${1:-}" in
  "") ;;
  --quick) quick=1 ;;
  *) echo "usage: bash tools/test.sh [--quick]" >&2; exit 2 ;;
esac
bash tools/build.sh
if [ "$quick" -eq 1 ]; then
  ctest --test-dir build --output-on-failure --parallel "$(nproc)" --label-regex '^quick$'
  exit 0
fi
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# The CPU-side code again, built by clang with AddressSanitizer and
# UndefinedBehaviorSanitizer: its tests, and the two fuzz targets for a
# bounded time each (cmake/sanitized_cpu.cmake).
if [ ! -f build-fuzz/CMakeCache.txt ]; then
  cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DTIDEPOOL_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build build-fuzz --parallel "$(nproc)"
ctest --test-dir build-fuzz --output-on-failure --parallel "$(nproc)"
