#!/usr/bin/env bash
# One image of every example scene: renders each examples/scenes/*.json with
# `facet render`, fits each into a 320 x 180 tile (OpenImageIO's oiiotool),
# writes the tiles side by side, four a row, and beside the image a .txt
# naming the scene of each tile (oiiotool's text needs fonts a bare machine
# lacks); lists what failed to render (exit 1 if any did).
#
#   scripts/contact-sheet.sh [FACET] [OUT.png]   # defaults: build/runtime/facet, out/contact-sheet.png
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
facet=${1:-$root/build/runtime/facet}
out=${2:-$root/out/contact-sheet.png}
[[ -x $facet ]] || { echo "$0: no facet binary at $facet (build it, or name it)" >&2; exit 2; }
command -v oiiotool >/dev/null || { echo "$0: oiiotool (Debian's openimageio-tools) is needed" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tiles=()
names=()
failed=()
for scene in "$root"/examples/scenes/*.json; do
  name=$(basename "$scene" .json)
  if ! "$facet" render "$scene" -o "$work/$name.png" >"$work/$name.log" 2>&1; then
    failed+=("$name")
    head -5 "$work/$name.log" | sed 's/^/  /' >&2
    continue
  fi
  oiiotool "$work/$name.png" --ch R,G,B --fit:pad=1 320x180 -o "$work/tile-$name.png"
  tiles+=("$work/tile-$name.png")
  names+=("$name")
done
if [[ ${#tiles[@]} -gt 0 ]]; then
  columns=4
  rows=$(((${#tiles[@]} + columns - 1) / columns))
  # Pad the last row with black tiles: --mosaic needs every cell filled.
  while [[ $((${#tiles[@]} % columns)) -ne 0 ]]; do
    oiiotool --pattern constant:color=0,0,0 320x180 3 -o "$work/blank-${#tiles[@]}.png"
    tiles+=("$work/blank-${#tiles[@]}.png")
  done
  mkdir -p "$(dirname "$out")"
  oiiotool "${tiles[@]}" --mosaic:pad=4 "${columns}x${rows}" -o "$out"
  legend="$(dirname "$out")/$(basename "$out" .png).txt"
  for i in "${!names[@]}"; do
    echo "row $((i / columns + 1)), column $((i % columns + 1)): ${names[$i]}"
  done >"$legend"
  echo "contact sheet of ${#names[@]} scenes written to $out (tiles named in $legend)"
fi
if [[ ${#failed[@]} -gt 0 ]]; then
  echo "$0: these scenes did not render: ${failed[*]}" >&2
  exit 1
fi
