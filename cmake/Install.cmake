# `cmake --install` lays out PREFIX/bin/globe, PREFIX/lib/libglobe_*.a, PREFIX/include/globe/...,
# PREFIX/share/globe/{shaders,assets} and PREFIX/lib/cmake/globe, so that another project can
# `find_package(globe [COMPONENTS ...])` and link globe::planet alone, globe::render (headless) or
# globe::viewer (tests/consumer checks them). Each component is an export set of its own, so a consumer
# of `planet` finds none of the render, movie, bake or physics dependencies (globeConfig.cmake.in).
include(CMakePackageConfigHelpers)
get_property(globe_libraries GLOBAL PROPERTY GLOBE_LIBRARIES)
get_property(globe_test_only GLOBAL PROPERTY GLOBE_LIBRARIES_TEST_ONLY)
if(globe_test_only)
  list(REMOVE_ITEM globe_libraries ${globe_test_only})
endif()
set(globe_component_physics globe_physics)
set(globe_component_collision globe_collision)
set(globe_component_movie globe_movie)
set(globe_component_bake globe_bake)
set(globe_component_viewer globe_viewer)
set(globe_component_planet ${globe_libraries})
list(FILTER globe_component_planet INCLUDE REGEX "^globe_planet")
set(globe_component_render ${globe_libraries})
list(REMOVE_ITEM globe_component_render ${globe_component_planet} globe_physics globe_collision globe_movie globe_bake
     globe_viewer)
foreach(component planet physics render collision movie bake viewer)
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
