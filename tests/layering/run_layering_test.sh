#!/usr/bin/env bash
# Builds a two-stage project with facet's layering check (cmake/FacetLayering.cmake)
# and checks that the build passes or fails as the case says.
#
#   run_layering_test.sh FACET_SOURCE_DIR WORK_DIR CASE
#
# Stage "early" comes first; "late" depends on it. CASE is clean (the build
# passes), or one deliberate violation, which must fail the build with its
# file:line and message: later_public_header, private_header_by_stage_path,
# private_header_by_relative_path, public_header_includes_later_stage,
# public_header_of_no_stage.
set -euo pipefail
source_dir=$1
work=$2/$3
case=$3
rm -rf "$work"
mkdir -p "$work/include/proj" "$work/src/early" "$work/src/late"

cat > "$work/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(layering_case LANGUAGES CXX)
include($source_dir/cmake/FacetLayering.cmake)
foreach(stage early late)
  add_library(\${stage} STATIC src/\${stage}/\${stage}.cpp)
  target_include_directories(\${stage} PUBLIC include PRIVATE src/\${stage})
  add_dependencies(\${stage} layering)
endforeach()
target_link_libraries(late PUBLIC early)
facet_layering_stage(early DIR \${CMAKE_CURRENT_SOURCE_DIR}/src/early HEADERS proj/early.h)
facet_layering_stage(late DIR \${CMAKE_CURRENT_SOURCE_DIR}/src/late HEADERS proj/late.h DEPS early)
facet_layering_check(layering INCLUDE_ROOT \${CMAKE_CURRENT_SOURCE_DIR}/include)
CMAKE

echo 'int early_value();' > "$work/include/proj/early.h"
echo 'int late_value();' > "$work/include/proj/late.h"
echo 'inline int late_detail() { return 2; }' > "$work/src/late/detail.h"
printf '#include "proj/early.h"\n\nint early_value() { return 1; }\n' > "$work/src/early/early.cpp"
printf '#include "proj/late.h"\n#include "proj/early.h"\n#include "detail.h"\n\nint late_value() { return early_value() + late_detail(); }\n' \
  > "$work/src/late/late.cpp"

expect=""
case $case in
  clean) ;;
  later_public_header)
    sed -i '1a #include "proj/late.h"' "$work/src/early/early.cpp"
    expect="early.cpp:2: stage 'early' includes 'proj/late.h', a header of stage 'late', which 'early' does not depend on" ;;
  private_header_by_stage_path)
    sed -i '1a #include "late/detail.h"' "$work/src/early/early.cpp"
    expect="early.cpp:2: stage 'early' includes 'late/detail.h', a private header of stage 'late'" ;;
  private_header_by_relative_path)
    sed -i '1a #include "../late/detail.h"' "$work/src/early/early.cpp"
    expect="early.cpp:2: stage 'early' includes '../late/detail.h', a file outside its own folder" ;;
  public_header_includes_later_stage)
    sed -i '1i #include "proj/late.h"' "$work/include/proj/early.h"
    expect="early.h:1: stage 'early' includes 'proj/late.h', a header of stage 'late', which 'early' does not depend on" ;;
  public_header_of_no_stage)
    echo 'int stray();' > "$work/include/proj/stray.h"
    expect="stray.h:1: public header 'proj/stray.h' belongs to no stage" ;;
  *) echo "unknown case '$case'" >&2; exit 2 ;;
esac

cmake -S "$work" -B "$work/build" -G Ninja > "$work/configure.log" 2>&1
status=0
cmake --build "$work/build" > "$work/build.log" 2>&1 || status=$?
# CMake folds long messages; join the lines back before matching.
log=$(tr -s ' \n' ' ' < "$work/build.log")
if [[ -z $expect ]]; then
  [[ $status -eq 0 ]] || { cat "$work/build.log"; echo "FAIL: the clean project did not build" >&2; exit 1; }
  echo "ok: the clean project builds"
else
  [[ $status -ne 0 ]] || { echo "FAIL: the build passed despite the violation ($case)" >&2; exit 1; }
  [[ $log == *"$expect"* ]] || { cat "$work/build.log"; echo "FAIL: no message '$expect'" >&2; exit 1; }
  [[ ! -e $work/build/libearly.a ]] || { echo "FAIL: the stage was compiled before the check failed" >&2; exit 1; }
  echo "ok: $case fails the build: $expect"
fi
