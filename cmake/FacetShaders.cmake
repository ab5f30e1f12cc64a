# facet_add_shaders: compiles .shader files to .facetpkg packages at build
# time, as part of a project that did find_package(facet).
#
#   facet_add_shaders(<target>
#     SHADERS <file>...                 the .shader files (relative to the current source folder)
#     [OUTPUT_DIRECTORY <dir>]          where the packages go (default: the current binary folder)
#     [INCLUDE_DIRECTORIES <dir>...]    facetc -I (and facet render -I for the scenes)
#     [MATERIALS <manifest>...]         facetc --materials: only the variants the materials use
#     [OPTIONS <facetc argument>...]    any other facetc arguments, e.g. --keywords "FOG_LINEAR"
#     [SCENES <scene.json>...])         also render each scene to <dir>/<name>.png (facet render)
#
# Each shader becomes <dir>/<name>.facetpkg, built by facetc with a depfile
# (-MD -MF), so that editing an include rebuilds exactly the packages that
# read it. A scene is rendered by `facet render --depfile`, whose depfile
# lists the scene, its meshes, textures and shaders and every file those
# included: it is rendered again when any of them changes (the renderer
# compiles only the variants the scene draws). <target> is a custom target,
# built by default, that depends on all of them; its properties
# FACET_PACKAGES and FACET_IMAGES list their paths. Needs CMake 3.20
# (depfiles of custom commands) with policy CMP0116 NEW, which
# cmake_minimum_required(VERSION 3.20) or later sets.
function(facet_add_shaders target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "OUTPUT_DIRECTORY" "SHADERS;INCLUDE_DIRECTORIES;MATERIALS;OPTIONS;SCENES")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "facet_add_shaders(${target}): unknown arguments: ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT ARG_SHADERS AND NOT ARG_SCENES)
    message(FATAL_ERROR "facet_add_shaders(${target}): SHADERS and SCENES name no file")
  endif()
  if(ARG_SCENES AND NOT TARGET facet::facet)
    message(FATAL_ERROR "facet_add_shaders(${target}): SCENES needs facet::facet, which this facet was installed without")
  endif()
  if(NOT TARGET facet::facetc)
    message(FATAL_ERROR "facet_add_shaders(${target}): facet::facetc is not defined; call find_package(facet) first")
  endif()
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR})
  if(ARG_OUTPUT_DIRECTORY)
    get_filename_component(out_dir ${ARG_OUTPUT_DIRECTORY} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_BINARY_DIR})
  endif()

  set(include_args)
  foreach(dir IN LISTS ARG_INCLUDE_DIRECTORIES)
    get_filename_component(dir ${dir} ABSOLUTE)
    list(APPEND include_args -I ${dir})
  endforeach()
  set(common_args ${include_args})
  set(common_depends)
  foreach(manifest IN LISTS ARG_MATERIALS)
    get_filename_component(manifest ${manifest} ABSOLUTE)
    list(APPEND common_args --materials ${manifest})
    list(APPEND common_depends ${manifest})
  endforeach()
  list(APPEND common_args ${ARG_OPTIONS})

  set(packages)
  set(names)
  foreach(shader IN LISTS ARG_SHADERS)
    get_filename_component(shader ${shader} ABSOLUTE)
    get_filename_component(name ${shader} NAME_WE)
    if(name IN_LIST names)
      message(FATAL_ERROR "facet_add_shaders(${target}): two shaders would both write ${name}.facetpkg")
    endif()
    list(APPEND names ${name})
    set(package ${out_dir}/${name}.facetpkg)
    add_custom_command(
      OUTPUT ${package}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
      COMMAND facet::facetc ${shader} -o ${package} -MD -MF ${package}.d -MT ${package} ${common_args}
      DEPENDS ${shader} ${common_depends} facet::facetc
      DEPFILE ${package}.d
      COMMENT "facetc ${name}.shader"
      VERBATIM)
    list(APPEND packages ${package})
  endforeach()
  set(images)
  foreach(scene IN LISTS ARG_SCENES)
    get_filename_component(scene ${scene} ABSOLUTE)
    get_filename_component(name ${scene} NAME_WE)
    if(name IN_LIST names)
      message(FATAL_ERROR "facet_add_shaders(${target}): two inputs are both named ${name}")
    endif()
    list(APPEND names ${name})
    set(image ${out_dir}/${name}.png)
    add_custom_command(
      OUTPUT ${image}
      COMMAND ${CMAKE_COMMAND} -E make_directory ${out_dir}
      COMMAND facet::facet render ${scene} -o ${image} --depfile ${image}.d ${include_args}
      DEPENDS ${scene} facet::facet
      DEPFILE ${image}.d
      COMMENT "facet render ${name}"
      VERBATIM)
    list(APPEND images ${image})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${packages} ${images})
  set_property(TARGET ${target} PROPERTY FACET_PACKAGES ${packages})
  set_property(TARGET ${target} PROPERTY FACET_IMAGES ${images})
endfunction()
