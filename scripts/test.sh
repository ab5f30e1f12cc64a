#!/usr/bin/env bash
# The whole test suite on a fresh Debian 12 machine: install dependencies,
# build with AddressSanitizer + UndefinedBehaviorSanitizer, run every test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${FACET_TEST_BUILD_DIR:-$root/build-asan}
"$root/scripts/install-deps.sh"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_SANITIZE=ON
cmake --build "$build" -j"$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j"$(nproc)"
# Each fuzz target 20 s on its corpus (docs/reliability.md).
"$root/scripts/fuzz.sh" all 20
