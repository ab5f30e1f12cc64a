#!/usr/bin/env bash
# Installs facet from a build tree into a scratch prefix, builds examples/embed
# as a separate CMake project against it (find_package(facet) ->
# facet::compiler), runs it, and checks what it printed.
# Usage: run_embed_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/lib/cmake/facet/facetConfig.cmake" || { echo "no facetConfig.cmake installed"; exit 1; }
test -f "$work/prefix/include/facet/compiler.h" || { echo "no public headers installed"; exit 1; }
test -f "$work/prefix/share/facet/stdlib/UnityCG.cginc" || { echo "no stdlib installed"; exit 1; }
cmake -S "$source/examples/embed" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
# The installed stdlib, not the source tree's, is what an engine uses.
FACET_STDLIB_DIR="$work/prefix/share/facet/stdlib" \
  "$work/build/facet_embed" "$source/examples/shaders/Keywords.shader" FOG_LINEAR _EMISSION > "$work/out.txt"
cat "$work/out.txt"
expect() { grep -qF -- "$1" "$work/out.txt" || { echo "missing from the output: $1"; exit 1; }; }
expect "shader 'Examples/Keywords': 1 pass(es)"
expect ": 48 variants"
expect "with { FOG_LINEAR _EMISSION _OVERLAY_NONE }"
expect "fragment:"
expect "block \$Globals set 2 binding 0"
expect "read back OK"
expect "in-memory shader: \$Globals._Tint at offset 0"
echo "embed example OK"
