#!/usr/bin/env bash
# Installs facet into a scratch prefix, builds tests/add_shaders/project (a
# separate CMake project that calls facet_add_shaders) with Ninja, then
# touches includes, a shader and a scene and checks through ninja's explain
# output that exactly the packages and images that read them are rebuilt.
# Usage: run_add_shaders_test.sh BUILD_DIR SOURCE_DIR WORK_DIR
set -euo pipefail
build=$1 source=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
for tool in facetc facet; do
  test -x "$work/prefix/bin/$tool" || { echo "cmake --install did not install $tool"; exit 1; }
done
test -f "$work/prefix/lib/cmake/facet/FacetShaders.cmake" || { echo "no FacetShaders.cmake installed"; exit 1; }
cp -r "$source/tests/add_shaders/project" "$work/project"
export FACET_STDLIB_DIR="$work/prefix/share/facet/stdlib"
# In a sanitizer build, the scene's render would fail LeakSanitizer's exit
# check on lavapipe's memory: the Vulkan loader unloads the driver before
# exit, so its leaks show as "<unknown module>" and tests/lsan.supp cannot
# match them. The in-process render tests check facet's own memory.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
cmake -S "$work/project" -B "$work/build" -G Ninja -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log"
ninja -C "$work/build" > "$work/build-1.log"
packages=(Tinted Waves Plain)
for p in "${packages[@]}"; do
  test -s "$work/build/packages/$p.facetpkg" || { echo "no package $p.facetpkg"; cat "$work/build-1.log"; exit 1; }
done
test -s "$work/build/packages/TintedBall.png" || { echo "the scene was not rendered"; cat "$work/build-1.log"; exit 1; }
grep -q "ninja: no work to do" <(ninja -C "$work/build") || { echo "a second build was not a no-op"; exit 1; }

# What ninja would rebuild after a change, by its explain output: the set of
# packages named as dirty.
dirty_after() {
  sleep 1.1  # mtimes of 1 s resolution on some file systems
  touch "$work/project/$1"
  ninja -C "$work/build" -n -d explain > "$work/explain.log" 2>&1
  grep -oE 'packages/[A-Za-z]*\.(facetpkg|png) is dirty' "$work/explain.log" | sed 's|packages/||; s| is dirty||' | sort -u | tr '\n' ' '
  ninja -C "$work/build" > "$work/rebuild.log"
}
expect_dirty() {
  local changed=$1 want=$2 got
  got=$(dirty_after "$changed")
  if [[ $got != "$want " ]]; then
    echo "after touching $changed, ninja rebuilds: '$got', expected: '$want '"
    cat "$work/explain.log"
    exit 1
  fi
  echo "touching $changed rebuilds: $want"
}
# The scene draws Tinted.shader: its image depends on Tint.cginc too.
expect_dirty include/Tint.cginc "Tinted.facetpkg TintedBall.png"
expect_dirty include/Waves.cginc Waves.facetpkg
expect_dirty shaders/Plain.shader Plain.facetpkg
expect_dirty scenes/TintedBall.json TintedBall.png
grep -q "ninja: no work to do" <(ninja -C "$work/build") || { echo "the rebuild left work to do"; exit 1; }
echo "facet_add_shaders OK"
