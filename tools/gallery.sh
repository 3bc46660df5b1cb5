#!/usr/bin/env bash
# Builds tidepool and renders the gallery, the pictures listed in
# docs/images/gallery.txt, at 1280x720 with 8 jittered samples a pixel
# (anti-aliased), to PNGs in docs/images/ (docs/gallery.md shows them; the
# README shows default.png). Each picture is written under a temporary name
# and renamed into place, so an interrupted run never leaves a half-written
# one. TIDEPOOL_GALLERY_SIZE=640x360 gives a quick look.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p docs/images
# docs/images/gallery.txt: name, scene file (- for the built-in scene), frame
grep -v '^#' docs/images/gallery.txt | while read -r name scene frame; do
  [ -n "$name" ] || continue
  args=(--size "${TIDEPOOL_GALLERY_SIZE:-1280x720}" --samples 8 --frame "$frame" --out "docs/images/$name.png")
  [ "$scene" = "-" ] || args+=(--scene "$scene")
  echo "gallery: $name"
  build/tidepool render "${args[@]}" </dev/null
done
