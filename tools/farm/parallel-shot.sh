#!/usr/bin/env bash
# A shot on one machine with GNU parallel: the frames FIRST..LAST in ranges
# of CHUNK, JOBS ranges at a time, each a `tidepool render --frames A-B`
# with the options after --, sharing the checkpoint folder.
#
#   tools/farm/parallel-shot.sh JOBS FIRST LAST CHUNK CHECKPOINTS -- --scene shot.json --out frames/shot.####.exr
#
# TIDEPOOL names the executable (default: tidepool on the PATH).
set -euo pipefail
if (($# < 6)) || [[ $6 != -- ]]; then
  echo "usage: $0 JOBS FIRST LAST CHUNK CHECKPOINTS -- RENDER_OPTIONS..." >&2
  exit 2
fi
jobs=$1 first=$2 last=$3 chunk=$4 checkpoints=$5
shift 6
TIDEPOOL=${TIDEPOOL:-tidepool}
mkdir -p "$checkpoints"
ranges=()
for ((a = first; a <= last; a += chunk)); do
  b=$((a + chunk - 1))
  if ((b > last)); then b=$last; fi
  ranges+=("$a-$b")
done
# --halt now,fail=1: one range failing stops the others and the exit code says so.
parallel -q --halt now,fail=1 -j "$jobs" "$TIDEPOOL" render --frames {} --checkpoint-every "$chunk" \
  --checkpoint-dir "$checkpoints" --resume "$@" ::: "${ranges[@]}"
