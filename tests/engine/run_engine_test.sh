#!/usr/bin/env bash
# Installs facet into a scratch prefix, builds examples/engine as a separate
# CMake project against it (find_package(facet) -> facet::runtime), builds
# the package it draws with the installed facetc, runs 300 frames of 1,000
# objects with validation on, and compares the last frame with
# tests/engine/last_frame.png (FACET_UPDATE_GOLDENS=1 writes it). One
# Renderer draws all frames, updating the frame it keeps.
# Usage: run_engine_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
test -f "$work/prefix/include/facet/runtime/renderer.h" || { echo "no runtime headers installed"; exit 1; }
cmake -S "$source/examples/engine" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
cmake --build "$work/build" > "$work/build.log"
# The example links the runtime alone: no compiler library among its shared
# libraries (TBB, curl, OpenSSL) or its symbols (glslang, SPIRV-Tools and
# SPIRV-Cross are static on Debian), as FacetPlayTest.LinksNoCompilerLibrary
# reads facet-play.
if readelf -d "$work/build/facet_engine" | grep -E -i 'glslang|SPIRV|spirv-cross|tbb|curl|ssl'; then
  echo "facet_engine links a compiler library"; exit 1
fi
nm -C "$work/build/facet_engine" > "$work/symbols.txt"
if grep -E 'glslang::|spvtools::|spirv_cross::|spv::|facet::Compiler::|facet::backend::' "$work/symbols.txt"; then
  echo "facet_engine holds compiler code"; exit 1
fi
grep -q 'facet::runtime::Renderer::render' "$work/symbols.txt" || { echo "no symbols to read in facet_engine"; exit 1; }
export FACET_STDLIB_DIR="$work/prefix/share/facet/stdlib"
# lavapipe's memory, unloaded before exit, cannot be matched by tests/lsan.supp
# (run_add_shaders_test.sh says why); facet's own is checked in process.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
"$work/prefix/bin/facetc" "$source/examples/shaders/Keywords.shader" -o "$work/Keywords.facetpkg"
"$work/build/facet_engine" "$work/Keywords.facetpkg" "$work/last.png" --validation | tee "$work/out.txt"
grep -q "^frames: 300, objects: 1000, " "$work/out.txt" || { echo "not 300 frames of 1000 objects"; exit 1; }
grep -q "shaders loaded: 1, " "$work/out.txt" || { echo "the package was loaded more than once"; exit 1; }
grep -q "^validation messages: 0$" "$work/out.txt" || { echo "validation messages"; exit 1; }
# Every frame after the first updates the kept one in place (FramePath::updated)
# and creates no GPU object: frame 0 drew both variants of every draw.
grep -q "^frames updated in place: 299, GPU objects created after the first frame: 0$" "$work/out.txt" ||
  { echo "a frame was prepared anew or created GPU objects"; exit 1; }
golden="$source/tests/engine/last_frame.png"
if [[ ${FACET_UPDATE_GOLDENS:-0} == 1 ]]; then
  cp "$work/last.png" "$golden"
  echo "wrote $golden"
fi
# The tolerance of the renderer's goldens (tests/unit/render/golden_support.h).
idiff -fail 0.05 -failpercent 1 -warn 0.05 -warnpercent 1 "$work/last.png" "$golden"
echo "engine example OK"
