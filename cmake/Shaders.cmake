# Compiles GLSL to SPIR-V at build time with glslangValidator, one custom command per shader.
# glslangValidator --depfile lets a change to a shared include rebuild every shader that includes it.
function(globe_add_shaders target)
  cmake_parse_arguments(ARG "" "OUTPUT_DIR" "SOURCES" ${ARGN})
  set(outputs)
  foreach(src IN LISTS ARG_SOURCES)
    get_filename_component(name ${src} NAME)
    set(out ${ARG_OUTPUT_DIR}/${name}.spv)
    set(dep ${ARG_OUTPUT_DIR}/${name}.d)
    add_custom_command(
      OUTPUT ${out}
      COMMAND Vulkan::glslangValidator --target-env vulkan1.3 -I${CMAKE_SOURCE_DIR}/shaders
              -I${CMAKE_SOURCE_DIR} --depfile ${dep} -o ${out} ${src}
      DEPENDS ${src}
      DEPFILE ${dep}
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND outputs ${out})
  endforeach()
  add_custom_target(${target} ALL DEPENDS ${outputs})
endfunction()
