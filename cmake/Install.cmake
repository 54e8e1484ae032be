# `cmake --install` lays out PREFIX/bin/globe, PREFIX/lib/libglobe_*.a, PREFIX/include/globe/...,
# PREFIX/share/globe/{shaders,assets} and PREFIX/lib/cmake/globe, so that another project can
# `find_package(globe [COMPONENTS ...])` and link globe::planet alone (no GDAL), with globe::planet_gdal
# (real data), globe::render (headless) or globe::viewer (tests/consumer checks them). Each component is
# an export set of its own, so a consumer of `planet` finds none of the GDAL, render, movie, bake or
# physics dependencies (globeConfig.cmake.in).
include(CMakePackageConfigHelpers)
get_property(globe_libraries GLOBAL PROPERTY GLOBE_LIBRARIES)
get_property(globe_test_only GLOBAL PROPERTY GLOBE_LIBRARIES_TEST_ONLY)
if(globe_test_only)
  list(REMOVE_ITEM globe_libraries ${globe_test_only})
endif()
# Each installed library's component: globe_planet* are `planet` (but the GDAL readers, `gdal`), the
# render stages `render`, the others their own (a library not built, like the viewer in the bundle preset,
# is simply absent).
set(globe_component_render "")
foreach(library IN LISTS globe_libraries)
  string(REGEX REPLACE "^globe_" "" name ${library})
  if(name STREQUAL "planet_gdal")
    set(globe_component_gdal ${library})
  elseif(name MATCHES "^planet")
    list(APPEND globe_component_planet ${library})
  elseif(name MATCHES "^(physics|collision|movie|bake|viewer)$")
    set(globe_component_${name} ${library})
  else()
    list(APPEND globe_component_render ${library})
  endif()
endforeach()
foreach(component planet gdal physics render collision movie bake viewer)
  if(globe_component_${component})
    install(TARGETS ${globe_component_${component}} EXPORT globe-${component}
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
    install(EXPORT globe-${component} NAMESPACE globe:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/globe
            FILE globe-${component}-targets.cmake)
  endif()
endforeach()
install(TARGETS globe RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The public headers: every header of an installed library but its private ones (globe_private_headers),
# and the C++/GLSL layout headers of shaders/include. Installed under include/globe/ with their project
# includes prefixed ("planet/core/error.h" -> "globe/planet/core/error.h"), so a consumer has one include
# root and writes #include <globe/planet/model/planet_file.h>.
set(globe_public_headers "")
foreach(library IN LISTS globe_libraries)
  get_target_property(type ${library} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    continue()
  endif()
  get_target_property(folder ${library} SOURCE_DIR)
  get_target_property(private ${library} GLOBE_PRIVATE_HEADERS)
  file(GLOB headers CONFIGURE_DEPENDS ${folder}/*.h)
  if(private)
    list(REMOVE_ITEM headers ${private})
  endif()
  list(APPEND globe_public_headers ${headers})
endforeach()
file(GLOB shader_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/shaders/include/*.h)
list(APPEND globe_public_headers ${shader_headers})
install(CODE "set(GLOBE_PUBLIC_HEADERS \"${globe_public_headers}\")
              set(GLOBE_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
              set(GLOBE_INCLUDE_DIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
              include(\"${PROJECT_SOURCE_DIR}/cmake/InstallHeaders.cmake\")")
install(DIRECTORY ${GLOBE_SHADER_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/globe/shaders FILES_MATCHING
        PATTERN "*.spv")
install(DIRECTORY assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/globe/assets)
configure_package_config_file(cmake/globeConfig.cmake.in ${PROJECT_BINARY_DIR}/globeConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/globe)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/globeConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/globeConfig.cmake ${PROJECT_BINARY_DIR}/globeConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/globe)
