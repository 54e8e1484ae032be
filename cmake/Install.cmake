# `cmake --install` lays out PREFIX/bin/globe, PREFIX/lib/libglobe_*.a, PREFIX/include/globe/...,
# PREFIX/share/globe/{shaders,assets} and PREFIX/lib/cmake/globe, so that another project can
# `find_package(globe)` and link globe::render (headless) or globe::viewer (tests/consumer checks it).
include(CMakePackageConfigHelpers)
get_property(globe_libraries GLOBAL PROPERTY GLOBE_LIBRARIES)
get_property(globe_test_only GLOBAL PROPERTY GLOBE_LIBRARIES_TEST_ONLY)
if(globe_test_only)
  list(REMOVE_ITEM globe_libraries ${globe_test_only})
endif()
install(TARGETS ${globe_libraries} EXPORT globeTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS globe RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY planet engine DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/globe FILES_MATCHING PATTERN "*.h"
        PATTERN cli EXCLUDE PATTERN research EXCLUDE)
install(DIRECTORY shaders/include DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/globe/shaders FILES_MATCHING PATTERN "*.h")
install(DIRECTORY ${GLOBE_SHADER_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/globe/shaders FILES_MATCHING
        PATTERN "*.spv")
install(DIRECTORY assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/globe/assets)
install(EXPORT globeTargets NAMESPACE globe:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/globe)
configure_package_config_file(cmake/globeConfig.cmake.in ${PROJECT_BINARY_DIR}/globeConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/globe)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/globeConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/globeConfig.cmake ${PROJECT_BINARY_DIR}/globeConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/globe)
