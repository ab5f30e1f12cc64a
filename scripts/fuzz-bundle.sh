#!/usr/bin/env bash
# Packs built fuzz targets with the shared libraries they load and a
# symbolizer, to run them on a host without facet's dependencies (the
# 16-core host of docs/reliability.md):
#
#   scripts/fuzz-bundle.sh OUT_DIR MAX_MB TARGET...   e.g. scripts/fuzz-bundle.sh bundle 60 image frontend
#
# Writes OUT_DIR/fuzz-bundle-<i>.tar.xz, each at most MAX_MB compressed
# (libraries are spread over the parts), all extracted into one folder.
# On the host, from a checkout of the same commit:
#
#   for p in fuzz-bundle-*.tar.xz; do tar -C /tmp/fz -xJf $p; done
#   /tmp/fz/fuzz-on-host.sh TARGET SECONDS      # runs scripts/fuzz.sh with one worker a core
#
# The C library and the dynamic loader are left out: the host's own must be
# used (a copied libc beside another loader does not start).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[[ $# -ge 3 ]] || { echo "usage: $0 OUT_DIR MAX_MB TARGET..." >&2; exit 2; }
out=$(realpath -m "$1")
max_bytes=$(($2 * 1024 * 1024))
shift 2
build=$(realpath -m "${FACET_FUZZ_BUILD_DIR:-$root/build-fuzz}")
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/build/tests/fuzz" "$stage/lib" "$stage/bin" "$out"
programs=()
for t in "$@"; do
  t=${t#fuzz_}
  [[ -x $build/tests/fuzz/fuzz_$t ]] || { echo "$0: $build/tests/fuzz/fuzz_$t is not built (scripts/fuzz.sh $t 0)" >&2; exit 1; }
  cp "$build/tests/fuzz/fuzz_$t" "$stage/build/tests/fuzz/"
  programs+=("$build/tests/fuzz/fuzz_$t")
done
symbolizer=$(command -v addr2line)
cp "$symbolizer" "$stage/bin/"
programs+=("$symbolizer")
ldd "${programs[@]}" | awk '/=> \// {print $3}' | sort -u |
  grep -v -E '/(libc|libm|libpthread|libdl|librt|libresolv)\.so|/ld-linux' |
  while read -r lib; do cp -L "$lib" "$stage/lib/"; done
strip --strip-unneeded "$stage"/lib/* 2>/dev/null || true
cat >"$stage/fuzz-on-host.sh" <<'RUN'
#!/usr/bin/env bash
# Runs scripts/fuzz.sh (of the checkout in the current folder) on this bundle's targets.
here=$(cd "$(dirname "$0")" && pwd)
export LD_LIBRARY_PATH=$here/lib ASAN_SYMBOLIZER_PATH=$here/bin/addr2line
FACET_FUZZ_BUILD_DIR=$here/build FACET_FUZZ_NO_BUILD=1 FACET_FUZZ_WORKERS=${FACET_FUZZ_WORKERS:-$(nproc)} \
  exec scripts/fuzz.sh "$@"
RUN
chmod +x "$stage/fuzz-on-host.sh"
# Parts: the programs and the script first, then libraries, largest first,
# each into the first part with room (xz sizes are estimated at 40 %).
rm -f "$out"/fuzz-bundle-*.tar.xz
declare -a part_files part_bytes
part_files[0]="build bin fuzz-on-host.sh"
part_bytes[0]=$(( $(du -sb "$stage/build" "$stage/bin" | awk '{s += $1} END {print s}') * 4 / 10 ))
while read -r size name; do
  estimate=$((size * 4 / 10))
  placed=0
  for i in "${!part_bytes[@]}"; do
    if (( part_bytes[i] + estimate <= max_bytes )); then
      part_files[i]+=" lib/$name"; part_bytes[i]=$((part_bytes[i] + estimate)); placed=1; break
    fi
  done
  if (( !placed )); then
    i=${#part_bytes[@]}; part_files[i]="lib/$name"; part_bytes[i]=$estimate
  fi
done < <(cd "$stage/lib" && find . -type f -printf '%s %P\n' | sort -rn)
for i in "${!part_files[@]}"; do
  # shellcheck disable=SC2086  # a word list of paths without spaces
  tar -C "$stage" -cJf "$out/fuzz-bundle-$i.tar.xz" ${part_files[i]}
done
ls -l "$out"/fuzz-bundle-*.tar.xz
