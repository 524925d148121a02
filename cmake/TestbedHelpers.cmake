# Build helpers shared by the core, the techniques, the tests and the benchmarks.

# testbed_embed_shaders(<target> FILES a.frag b.glsl ...)
# Embeds GLSL sources into <target> at build time. Each file is registered under its path
# relative to the repository root, which is also the name `#include "..."` uses.
function(testbed_embed_shaders target)
  cmake_parse_arguments(ARG "" "" "FILES" ${ARGN})
  set(outputs "")
  foreach(file IN LISTS ARG_FILES)
    get_filename_component(abs "${file}" ABSOLUTE)
    file(RELATIVE_PATH key "${CMAKE_SOURCE_DIR}" "${abs}")
    string(MAKE_C_IDENTIFIER "${key}" ident)
    set(out "${CMAKE_CURRENT_BINARY_DIR}/embedded/${ident}.cpp")
    add_custom_command(
      OUTPUT "${out}"
      COMMAND ${CMAKE_COMMAND} -DINPUT=${abs} -DOUTPUT=${out} -DKEY=${key} -DIDENT=${ident}
              -P "${CMAKE_SOURCE_DIR}/cmake/EmbedShader.cmake"
      DEPENDS "${abs}" "${CMAKE_SOURCE_DIR}/cmake/EmbedShader.cmake"
      COMMENT "Embedding ${key}")
    list(APPEND outputs "${out}")
  endforeach()
  target_sources(${target} PRIVATE ${outputs})
endfunction()

# testbed_add_technique(<name> SOURCES ... SHADERS ...)
# A technique is an OBJECT library so that its static self-registration object is always
# linked (a static archive would let the linker drop it, since nothing references it).
function(testbed_add_technique name)
  cmake_parse_arguments(ARG "" "" "SOURCES;SHADERS" ${ARGN})
  set(target technique_${name})
  add_library(${target} OBJECT ${ARG_SOURCES})
  target_link_libraries(${target} PUBLIC testbed_core)
  if(ARG_SHADERS)
    testbed_embed_shaders(${target} FILES ${ARG_SHADERS})
  endif()
  set_property(GLOBAL APPEND PROPERTY TESTBED_TECHNIQUE_TARGETS ${target})
endfunction()

# testbed_link_techniques(<executable>): links the core, the ground truth and every
# registered technique.
function(testbed_link_techniques exe)
  get_property(targets GLOBAL PROPERTY TESTBED_TECHNIQUE_TARGETS)
  target_link_libraries(${exe} PRIVATE testbed_core testbed_groundtruth ${targets})
endfunction()
