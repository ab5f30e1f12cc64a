#!/usr/bin/env bash
# Unity's own Standard shader, compiled against Unity's own include files,
# against facet's stdlib Standard, on one scene (examples/scenes/standard_compare.json:
# metallic x smoothness spheres, a directional, a point and a spot light, a
# sky's SH and reflections, linear fog): renders it once as it is (facet's
# Standard) and once with every object's shader replaced by Unity's
# Standard.shader (`facet render -I <Unity>/CGIncludes`), then prints
# OpenImageIO's comparison of the two images (mean and maximum difference,
# in 0..1 of the 8-bit output) and writes both and their difference x8.
#
#   scripts/compare-unity-standard.sh UNITY_SHADERS [FACET] [OUT_DIR]
#
# UNITY_SHADERS is the folder of Unity's built-in shaders that holds
# DefaultResourcesExtra/Standard.shader and CGIncludes/ (the "Shaders" folder
# of a snapshot of chsxf/unity-built-in-shaders; Unity's code is not part of
# facet and is read only from there). Results: docs/compatibility.md.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
unity=${1:?usage: $0 UNITY_SHADERS [FACET] [OUT_DIR]}
facet=${2:-$root/build/runtime/facet}
out=${3:-$root/out/unity-standard}
unity=$(cd "$unity" && pwd)
[[ -f $unity/DefaultResourcesExtra/Standard.shader && -d $unity/CGIncludes ]] ||
  { echo "$0: $unity has no DefaultResourcesExtra/Standard.shader and CGIncludes/" >&2; exit 2; }
mkdir -p "$out"
scene=$root/examples/scenes/standard_compare.json
# Variants of the scene written beside the original, so that its relative
# paths stay right: Unity's shader instead of facet's, and linear fog on.
tmp=$root/examples/scenes/.standard_compare
trap 'rm -f "$tmp".*.json' EXIT
for fog in off linear; do
  sed "s|\"mode\": \"off\"|\"mode\": \"$fog\"|" "$scene" >"$tmp.facet-$fog.json"
  sed "s|\"../../stdlib/Shaders/Standard.shader\"|\"$unity/DefaultResourcesExtra/Standard.shader\"|" \
    "$tmp.facet-$fog.json" >"$tmp.unity-$fog.json"
  "$facet" render "$tmp.facet-$fog.json" -o "$out/facet-fog-$fog.png"
  "$facet" render "$tmp.unity-$fog.json" -I "$unity/CGIncludes" -o "$out/unity-fog-$fog.png" --depfile "$out/unity.d"
  echo "== fog $fog: facet's Standard against Unity's ($(tr ' ' '\n' <"$out/unity.d" | grep -c "^$unity/CGIncludes/") of Unity's include files read)"
  oiiotool "$out/facet-fog-$fog.png" "$out/unity-fog-$fog.png" --diff --absdiff --mulc 8 \
    -o "$out/difference-x8-fog-$fog.png" | grep -E "Mean error|Max error|pixels" | sort -u || true
done
echo "images in $out"
