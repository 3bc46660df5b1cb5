#!/usr/bin/env bash
# Builds tidepool and runs every test (on lavapipe, with validation on).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
