#!/usr/bin/env bash
# Builds tidepool and renders the built-in default scene at 960x540 to
# docs/images/default.png, the picture at the top of README.md. The PNG is
# written under a temporary name beside it and renamed into place, so an
# interrupted or failed run never leaves a half-written picture.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p docs/images
scratch=$(mktemp -d)
partial="docs/images/default.partial.$$.png"
trap 'rm -rf "$scratch"; rm -f "$partial"' EXIT
build/tidepool render --width 960 --height 540 --out "$scratch/default.exr" --png "$partial"
mv -f "$partial" docs/images/default.png
echo "wrote docs/images/default.png"
