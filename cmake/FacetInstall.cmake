# Installs the compiler library, its headers, facetc and a CMake package
# config so that engines can `find_package(facet)`, link facet::compiler and
# compile shaders at build time with facet_add_shaders (FacetShaders.cmake).
include(CMakePackageConfigHelpers)

install(TARGETS ${FACET_STAGE_TARGETS} facet_compiler
  EXPORT facetTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS facetc EXPORT facetTargets RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/compiler/include/facet DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

set(FACET_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/facet)
install(EXPORT facetTargets NAMESPACE facet:: DESTINATION ${FACET_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/facetConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/facetConfig.cmake INSTALL_DESTINATION ${FACET_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/facetConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/facetConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/facetConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FacetShaders.cmake
  DESTINATION ${FACET_CMAKE_DIR})
