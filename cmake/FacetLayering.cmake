# The stage layering the build enforces (docs/architecture.md, "Layering").
#
#   facet_layering_stage(NAME DIR <private folder> HEADERS <public headers> DEPS <stages>)
#     declares a stage: the folder of its private sources and headers, the
#     public headers it owns (paths or globs relative to the include root,
#     e.g. facet/backend.h or facet/diag/*.def) and the stages it may use.
#   facet_layering_check(<check target> INCLUDE_ROOT <folder>)
#     adds <check target>, which fails the build when a stage (its sources or
#     its public headers) includes a public header of a stage it does not
#     depend on, directly or through others, or a private header of another
#     stage, or when a public header under the include root belongs to no
#     stage. Make each stage's library depend on the check target.
#
# The check runs again whenever a scanned file changes.

set(FACET_LAYERING_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/FacetLayeringCheck.cmake)

function(facet_layering_stage name)
  cmake_parse_arguments(ARG "" "DIR" "HEADERS;DEPS" ${ARGN})
  if(NOT ARG_DIR)
    message(FATAL_ERROR "facet_layering_stage(${name}): DIR is required")
  endif()
  set_property(GLOBAL APPEND PROPERTY FACET_LAYERING_STAGES ${name})
  set_property(GLOBAL PROPERTY FACET_LAYERING_${name}_DIR ${ARG_DIR})
  set_property(GLOBAL PROPERTY FACET_LAYERING_${name}_HEADERS ${ARG_HEADERS})
  set_property(GLOBAL PROPERTY FACET_LAYERING_${name}_DEPS ${ARG_DEPS})
endfunction()

function(facet_layering_check check_target)
  cmake_parse_arguments(ARG "" "INCLUDE_ROOT" "" ${ARGN})
  get_property(stages GLOBAL PROPERTY FACET_LAYERING_STAGES)
  set(rules "")
  set(inputs ${FACET_LAYERING_SCRIPT})
  foreach(stage ${stages})
    get_property(dir GLOBAL PROPERTY FACET_LAYERING_${stage}_DIR)
    get_property(patterns GLOBAL PROPERTY FACET_LAYERING_${stage}_HEADERS)
    get_property(deps GLOBAL PROPERTY FACET_LAYERING_${stage}_DEPS)
    set(headers "")
    foreach(pattern ${patterns})
      file(GLOB found CONFIGURE_DEPENDS RELATIVE ${ARG_INCLUDE_ROOT} ${ARG_INCLUDE_ROOT}/${pattern})
      if(NOT found)
        message(FATAL_ERROR "stage '${stage}' declares the public header '${pattern}', which is not in ${ARG_INCLUDE_ROOT}")
      endif()
      list(APPEND headers ${found})
    endforeach()
    file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${dir}/*.h ${dir}/*.hpp ${dir}/*.cpp ${dir}/*.inc ${dir}/*.def)
    list(APPEND inputs ${sources})
    foreach(header ${headers})
      list(APPEND inputs ${ARG_INCLUDE_ROOT}/${header})
    endforeach()
    list(JOIN deps "," deps_text)
    list(JOIN headers "," headers_text)
    string(APPEND rules "${stage}|${dir}|${deps_text}|${headers_text}\n")
  endforeach()
  set(rules_file ${CMAKE_CURRENT_BINARY_DIR}/${check_target}_rules.txt)
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${check_target}.stamp)
  file(WRITE ${rules_file} "${rules}")
  add_custom_command(OUTPUT ${stamp}
    COMMAND ${CMAKE_COMMAND} -DRULES=${rules_file} -DINCLUDE_ROOT=${ARG_INCLUDE_ROOT} -DSTAMP=${stamp}
            -P ${FACET_LAYERING_SCRIPT}
    DEPENDS ${inputs} ${rules_file}
    COMMENT "Checking the stage layering"
    VERBATIM)
  add_custom_target(${check_target} DEPENDS ${stamp})
endfunction()
