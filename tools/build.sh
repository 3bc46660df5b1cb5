#!/usr/bin/env bash
# Installs what is missing, configures build/ once, and builds incrementally.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build --parallel "$(nproc)"
