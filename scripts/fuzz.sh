#!/usr/bin/env bash
# Builds and runs facet's libFuzzer targets (tests/fuzz/, docs/reliability.md).
#
#   scripts/fuzz.sh TARGET SECONDS [libFuzzer args...]   e.g. scripts/fuzz.sh shaderlab 60
#   scripts/fuzz.sh all SECONDS [libFuzzer args...]      every target in turn
#
# TARGET is a name from the list below, with or without its "fuzz_" prefix.
# The fuzz build lives in build-fuzz/ (clang-14, configured on first use;
# only the fuzz targets and the libraries they link are built). Each target
# starts from its committed corpus, tests/fuzz/corpus/<target>/, which it
# never writes: new inputs go to build-fuzz/fuzz-corpus/<target>/, findings
# (crash-, leak-, timeout-, oom- files) to build-fuzz/fuzz-findings/<target>/,
# the log to build-fuzz/fuzz-logs/<target>.log. Prints executions, exec/s,
# coverage and corpus size per target; exits 1 when any target found something.
#
# Environment: FACET_FUZZ_BUILD_DIR (default build-fuzz), FACET_FUZZ_JOBS
# (build parallelism, default: all cores), FACET_FUZZ_WORKERS=N (N libFuzzer
# worker processes, -jobs=N -workers=N, each for SECONDS; their logs go to
# build-fuzz/fuzz-logs/<target>/fuzz-<i>.log and the summary adds up their
# executions), FACET_FUZZ_NO_BUILD=1 (run the
# targets as built, e.g. while another build of the folder runs), CC/CXX
# (default clang-14/clang++-14), FACET_FUZZ_REPLAY_ONLY="t1 t2" (those
# targets only run their committed corpus once, no mutation: for a target
# with an open finding, so that a smoke run stays a regression check).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(realpath -m "${FACET_FUZZ_BUILD_DIR:-$root/build-fuzz}")  # absolute: workers run in their log folder
jobs=${FACET_FUZZ_JOBS:-$(nproc)}
all_targets=(shaderlab frontend hlsl package cache scene obj gltf image)

usage() {
  echo "usage: $0 TARGET|all SECONDS [libFuzzer args...]" >&2
  echo "targets: ${all_targets[*]}" >&2
  exit 2
}
[[ $# -ge 2 ]] || usage
which=${1#fuzz_}
seconds=$2
shift 2
extra=("$@")
[[ $seconds =~ ^[0-9]+$ ]] || usage
if [[ $which == all ]]; then
  targets=("${all_targets[@]}")
elif [[ " ${all_targets[*]} " == *" $which "* ]]; then
  targets=("$which")
else
  echo "$0: unknown target '$1'" >&2
  usage
fi

# LeakSanitizer matches tests/fuzz/lsan.supp by function name, which needs a
# symbolizer: without one, OpenImageIO's known leak is reported at exit.
if [[ -z ${ASAN_SYMBOLIZER_PATH:-} ]] && ! command -v llvm-symbolizer >/dev/null && ! command -v addr2line >/dev/null; then
  echo "$0: warning: no llvm-symbolizer or addr2line on PATH (or ASAN_SYMBOLIZER_PATH): leak suppressions cannot match" >&2
fi

configure() {
  if [[ -f $build/CMakeCache.txt ]] && grep -q '^FACET_FUZZ:BOOL=ON' "$build/CMakeCache.txt"; then
    return
  fi
  # -O1 without NDEBUG: fast enough to fuzz, assertions kept. The test suite
  # needs OpenImageIO's comparisons and GoogleTest, none of which fuzzing uses.
  cmake -S "$root" -B "$build" -G Ninja \
    -DCMAKE_C_COMPILER="${CC:-clang-14}" -DCMAKE_CXX_COMPILER="${CXX:-clang++-14}" \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 \
    -DFACET_FUZZ=ON -DFACET_BUILD_TESTS=OFF
}

# libFuzzer arguments of one target: the ShaderLab dictionary for the targets
# that read .shader text, and size limits that keep glslang's inputs small.
target_args() {
  case $1 in
    shaderlab) echo "-dict=$root/tests/fuzz/shaderlab.dict -max_len=16384" ;;
    frontend) echo "-dict=$root/tests/fuzz/shaderlab.dict -max_len=4096" ;;
    hlsl) echo "-dict=$root/tests/fuzz/shaderlab.dict -max_len=2048" ;;
    package | cache) echo "-max_len=65536" ;;
    # OpenImageIO 2.4 leaks 31 bytes per refused file (ImageInput::geterror),
    # which made libFuzzer run LeakSanitizer's whole-heap scan after nearly
    # every input (six times slower); ASan and UBSan still check every read.
    image) echo "-max_len=65536 -detect_leaks=0" ;;
    *) echo "-max_len=16384" ;;
  esac
}

replay_args() {
  if [[ " ${FACET_FUZZ_REPLAY_ONLY:-} " == *" $1 "* ]]; then echo "-runs=0"; fi
}

# Runs one target; prints its summary line; returns 1 on a finding.
run_target() {
  local name=fuzz_$1
  local scratch=$build/fuzz-corpus/$1 findings=$build/fuzz-findings/$1 log=$build/fuzz-logs/$1.log
  mkdir -p "$scratch" "$findings" "$(dirname "$log")"
  local status=0 workers=${FACET_FUZZ_WORKERS:-1} jobs_dir=$build/fuzz-logs/$1 run_dir=$PWD
  local parallel=()
  if [[ $workers -gt 1 ]]; then
    # libFuzzer writes each worker's log as fuzz-<i>.log in the current folder.
    rm -rf "$jobs_dir" && mkdir -p "$jobs_dir"
    parallel=(-jobs="$workers" -workers="$workers")
    run_dir=$jobs_dir
  fi
  # shellcheck disable=SC2046  # target_args is a word list by design
  (cd "$run_dir" && ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
  LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0} \
    "$build/tests/fuzz/$name" "$scratch" "$root/tests/fuzz/corpus/$1" \
    -max_total_time="$seconds" $(replay_args "$1") -timeout=30 -rss_limit_mb=4096 -print_final_stats=1 \
    -artifact_prefix="$findings/" $(target_args "$1") "${parallel[@]}" "${extra[@]}") >"$log" 2>&1 || status=$?
  local runs rate final cov corp logs=("$log")
  if [[ $workers -gt 1 ]]; then
    logs=("$jobs_dir"/fuzz-*.log)
    # Each worker's final statistics: executions add up, coverage is the largest.
    # A worker that reports something prints its statistics again after the
    # report: only the last block of each log counts.
    runs=$(for l in "${logs[@]}"; do sed -n 's/^stat::number_of_executed_units: *//p' "$l" | tail -1; done |
      awk '{s += $1} END {print s + 0}')
    rate=$((runs / (seconds > 0 ? seconds : 1)))
    cov=$(cat "${logs[@]}" | sed -nE 's/^#[0-9]+.* cov: ([0-9]+).*/\1/p' | sort -n | tail -1)
    corp="$(find "$scratch" -type f | wc -l)_inputs"
  else
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
    final=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
    cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$final")
    corp=$(sed -nE 's/.* corp: ([^ ]+).*/\1/p' <<<"$final")
  fi
  printf '%-15s %10s runs in %4ss  %8s exec/s  cov %-6s corpus %-12s' \
    "$name" "${runs:-?}" "$seconds" "${rate:-?}" "${cov:-?}" "${corp:-?}"
  local found
  found=$(cat "${logs[@]}" | sed -nE 's/.*Test unit written to (.*)$/\1/p')
  if [[ $status -ne 0 || -n $found ]]; then
    echo " FINDING (exit $status)"
    [[ -n $found ]] && echo "  input: $found"
    echo "  log:   $log"
    # The report's first line and the top of its stack: in CI the log and
    # the input stay on the CI machine, so this is what there is to read.
    cat "${logs[@]}" | grep -m1 -A24 -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error:|property failed|internal compiler error' \
      | grep -E 'ERROR|runtime error|property failed|internal compiler error|^(READ|WRITE) |^ *#[0-9]+ |allocated by|located' \
      | head -20 | sed 's/^/  /' || true
    return 1
  fi
  echo " no findings"
}

if [[ -z ${FACET_FUZZ_NO_BUILD:-} ]]; then
  configure
  if [[ $which == all ]]; then
    cmake --build "$build" -j"$jobs" --target fuzz_all
  else
    cmake --build "$build" -j"$jobs" --target "fuzz_$which"
  fi
fi
failed=0
for t in "${targets[@]}"; do
  run_target "$t" || failed=1
done
exit $failed
