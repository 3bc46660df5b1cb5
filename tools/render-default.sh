#!/usr/bin/env bash
# Builds tidepool and renders the built-in default scene to default.exr and default.png.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
build/tidepool render --out default.exr --out default.png "$@"
