# Compiles GLSL to SPIR-V at build time with glslangValidator, one custom command per shader.
# glslangValidator --depfile lets a change to a shared include rebuild every shader that includes it.
function(globe_add_shaders target)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES;VARIANTS" ${ARGN})
  set(outputs)
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(name ${src} NAME)
    globe_compile_shader(${src} ${name} "" ${ARG_OUTPUT_DIR})
    list(APPEND outputs ${ARG_OUTPUT_DIR}/${name}.spv)
  endforeach()
  # VARIANTS: "NAME=SOURCE:DEFINE,DEFINE..." compiles SOURCE (in the current source directory) again
  # with those preprocessor defines as NAME.spv: one shader body, several pipelines' variants.
  foreach(variant IN LISTS ARG_VARIANTS)
    string(REGEX MATCH "^([^=]+)=([^:]+):(.*)$" matched ${variant})
    if(NOT matched)
      message(FATAL_ERROR "shader variant '${variant}' is not NAME=SOURCE:DEFINE,...")
    endif()
    set(name ${CMAKE_MATCH_1})
    set(src ${CMAKE_CURRENT_SOURCE_DIR}/${CMAKE_MATCH_2})
    string(REPLACE "," ";" defines "${CMAKE_MATCH_3}")
    list(TRANSFORM defines PREPEND "-D")
    globe_compile_shader(${src} ${name} "${defines}" ${ARG_OUTPUT_DIR})
    list(APPEND outputs ${ARG_OUTPUT_DIR}/${name}.spv)
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${outputs})
endfunction()

# One glslang run: `src` to `outDir`/`name`.spv with the flags `defines` (-DNAME ...).
function(globe_compile_shader src name defines outDir)
  set(out ${outDir}/${name}.spv)
  set(dep ${outDir}/${name}.d)
  add_custom_command(
    OUTPUT ${out}
    COMMAND Vulkan::glslangValidator --target-env vulkan1.3 ${defines} -I${CMAKE_SOURCE_DIR}/shaders
            -I${CMAKE_SOURCE_DIR} --depfile ${dep} -o ${out} ${src}
    DEPENDS ${src}
    DEPFILE ${dep}
    COMMENT "glslang ${name}"
    VERBATIM)
endfunction()
