#!/usr/bin/env bash
# Rewrites the golden images listed in tests/golden/cases.txt with the
# tidepool built in build/ (run tools/build.sh first). Look at every image
# before committing it: the golden-image test trusts them.
set -euo pipefail
cd "$(dirname "$0")/.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
grep -v '^#' tests/golden/cases.txt | while read -r name scene frame; do
  [ -n "$name" ] || continue
  args=(--size 160x90 --frame "$frame" --out "$scratch/$name.exr" --out "tests/golden/$name.png")
  [ "$scene" = "-" ] || args+=(--scene "$scene")
  build/tidepool render --validate "${args[@]}"
done
