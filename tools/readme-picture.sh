#!/usr/bin/env bash
# Builds tidepool and renders the built-in default scene at 960x540 (eight
# jittered samples a pixel: anti-aliased) to
# docs/images/default.png, the picture at the top of README.md. render
# writes under a temporary name and renames into place, so an interrupted
# or failed run never leaves a half-written picture.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p docs/images
build/tidepool render --size 960x540 --samples 8 --out docs/images/default.png
