#!/usr/bin/env bash
# facet's main job on a fresh Debian 12 machine: install dependencies, build,
# compile every example shader (all variants) into .facetpkg packages, then
# render the showcase scene with `facet render` (lavapipe by default).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh" "$root/build"
out="$root/out/packages"
mkdir -p "$out"
"$root/build/compiler/facetc" --all-variants --stats --out-dir "$out" "$root"/examples/shaders/*.shader
echo "packages written to $out"
"$root/build/runtime/facet" render "$root/examples/scenes/showcase.json" -o "$root/out/showcase.png" --stats
echo "showcase scene rendered to $root/out/showcase.png"
