# The one function that configures every globe target: language level, warnings, and the
# definitions that keep double -> float narrowing explicit.
function(globe_configure_target target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  target_compile_definitions(${target} PUBLIC GLM_FORCE_EXPLICIT_CTOR GLM_FORCE_XYZW_ONLY
                                              GLM_FORCE_RADIANS GLM_FORCE_DEPTH_ZERO_TO_ONE)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wconversion -Wshadow -Wpedantic
                                           -Wno-missing-field-initializers)
  # IEEE semantics everywhere (fast-math is never enabled): planet-scale geodesy needs exact doubles.
  target_compile_options(${target} PRIVATE -fno-fast-math -ffp-contract=off)
  if(GLOBE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
    # GCC 12 at -O3 reports `"literal" + std::string` as overlapping memcpy (GCC bug 105329): a
    # false positive in libstdc++, kept as a warning so Release builds with -Werror still work.
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
      target_compile_options(${target} PRIVATE -Wno-error=restrict)
    endif()
  endif()
  if(GLOBE_BUILD_FUZZERS)
    # Coverage for libFuzzer in every library; the fuzz targets add -fsanitize=fuzzer at link time.
    target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
  if(GLOBE_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# A library of globe: the .cpp files of its folder (globbed, so a new file needs no CMake edit),
# configured as above, exported as globe::NAME (target globe_NAME, file libglobe_NAME.a).
# Headers are included by their path from the source root ("engine/vk/device.h"); installed, the public
# ones sit under PREFIX/include/globe/ and are included as <globe/engine/vk/device.h> (cmake/Install.cmake).
function(globe_add_library name)
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp ${CMAKE_CURRENT_SOURCE_DIR}/*/*.cpp)
  # A subfolder with its own CMakeLists.txt is a library of its own (planet/physics), not part of this one.
  foreach(source IN LISTS sources)
    get_filename_component(folder ${source} DIRECTORY)
    if(NOT folder STREQUAL CMAKE_CURRENT_SOURCE_DIR AND EXISTS ${folder}/CMakeLists.txt)
      list(REMOVE_ITEM sources ${source})
    endif()
  endforeach()
  add_library(globe_${name} STATIC ${sources})
  add_library(globe::${name} ALIAS globe_${name})
  set_target_properties(globe_${name} PROPERTIES EXPORT_NAME ${name})
  globe_configure_target(globe_${name})
  target_include_directories(globe_${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                                  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_property(GLOBAL APPEND PROPERTY GLOBE_LIBRARIES globe_${name})
endfunction()

# Headers of library globe_NAME that only its own files (and the tests) include: kept beside their
# sources, never installed. tests/cli/layers_test.py fails when another folder or a public header
# includes one, so the installed headers compile on their own.
function(globe_private_headers name)
  foreach(header IN LISTS ARGN)
    if(NOT EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/${header})
      message(FATAL_ERROR "globe_private_headers(${name}): no ${header} in ${CMAKE_CURRENT_SOURCE_DIR}")
    endif()
    set_property(TARGET globe_${name} APPEND PROPERTY GLOBE_PRIVATE_HEADERS ${CMAKE_CURRENT_SOURCE_DIR}/${header})
  endforeach()
endfunction()
