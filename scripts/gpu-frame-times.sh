#!/usr/bin/env bash
# The GPU figures of docs/performance.md ("Rendering"): the frame-overhead
# benchmark at the scenes' own size and at 1920x1080, and `facet render
# --frames` of every example scene at 1920x1080.
#   scripts/gpu-frame-times.sh BIN_DIR OUT_DIR [DEVICE]
# BIN_DIR holds facet and facet_frame_bench (e.g. a -DFACET_IMAGE_IO=png
# build, whose shared libraries fit on a machine without OpenImageIO);
# DEVICE is the --device selector (default: NVIDIA).
set -euo pipefail
bin=$1 out=$2 device=${3:-NVIDIA}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
"$bin/facet_frame_bench" --device "$device" --frames 200 --rounds 3 | tee "$out/overhead_native.txt"
"$bin/facet_frame_bench" --device "$device" --frames 100 --rounds 3 --width 1920 --height 1080 | tee "$out/overhead_1080p.txt"
for scene in "$root"/examples/scenes/*.json; do
  name=$(basename "$scene" .json)
  echo "== $name"
  "$bin/facet" render "$scene" -o "$out/$name.png" --width 1920 --height 1080 --device "$device" --stats --frames 100 |
    grep -E '^(device|frame|draws|frames):'
done | tee "$out/render_1080p.txt"
