#!/usr/bin/env bash
# Builds tidepool and renders the gallery: the built-in default scene and
# the example scenes, at 1280x720 with 8 jittered samples a pixel
# (anti-aliased), to PNGs in docs/images/ (docs/gallery.md shows them; the
# README shows default.png). Each picture is written under a temporary name
# and renamed into place, so an interrupted run never leaves a half-written
# one. TIDEPOOL_GALLERY_SIZE=640x360 gives a quick look.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
mkdir -p docs/images
# name, scene file (- for the built-in scene), frame
pictures=(
  "default - 0"
  "default_frame60 - 60"
  "underwater scenes/underwater.json 30"
  "glass scenes/glass.json 30"
  "glossy scenes/glossy.json 30"
  "wake scenes/wake.json 60"
  "low_sun scenes/low_sun.json 30"
  "brick scenes/brick.json 30"
)
for picture in "${pictures[@]}"; do
  read -r name scene frame <<<"$picture"
  args=(--size "${TIDEPOOL_GALLERY_SIZE:-1280x720}" --samples 8 --frame "$frame" --out "docs/images/$name.png")
  [ "$scene" = "-" ] || args+=(--scene "$scene")
  echo "gallery: $name"
  build/tidepool render "${args[@]}"
done
