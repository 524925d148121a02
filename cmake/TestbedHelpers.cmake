# Build helpers shared by the core, the techniques, the tests and the benchmarks, and
# included by plugin projects (TestbedPluginConfig.cmake in the build tree).

# This folder, for EmbedShader.cmake: a plugin project's CMAKE_SOURCE_DIR is its own.
set(TESTBED_CMAKE_DIR "${CMAKE_CURRENT_LIST_DIR}")

# testbed_embed_shaders(<target> FILES a.frag b.glsl ... [CHECK_INCLUDES])
# Embeds GLSL sources into <target> at build time. Each file is registered under its path
# relative to the repository root (a plugin's: its project root), which is also the name
# `#include "..."` uses. CHECK_INCLUDES (plugins): every include must be one of FILES or
# the testbed's own, checked when the file is embedded (EmbedShader.cmake).
function(testbed_embed_shaders target)
  cmake_parse_arguments(ARG "CHECK_INCLUDES" "" "FILES" ${ARGN})
  set(check "")
  if(ARG_CHECK_INCLUDES)
    set(keys "")
    foreach(file IN LISTS ARG_FILES)
      get_filename_component(abs "${file}" ABSOLUTE)
      file(RELATIVE_PATH key "${CMAKE_SOURCE_DIR}" "${abs}")
      list(APPEND keys "${key}")
    endforeach()
    list(JOIN keys "|" keys)
    get_filename_component(root "${TESTBED_CMAKE_DIR}/.." ABSOLUTE)
    set(check "-DSHADER_KEYS=${keys}" "-DTESTBED_ROOT=${root}" "-DTARGET=${target}")
  endif()
  set(outputs "")
  foreach(file IN LISTS ARG_FILES)
    get_filename_component(abs "${file}" ABSOLUTE)
    file(RELATIVE_PATH key "${CMAKE_SOURCE_DIR}" "${abs}")
    string(MAKE_C_IDENTIFIER "${key}" ident)
    set(out "${CMAKE_CURRENT_BINARY_DIR}/embedded/${ident}.cpp")
    add_custom_command(
      OUTPUT "${out}"
      COMMAND ${CMAKE_COMMAND} -DINPUT=${abs} -DOUTPUT=${out} -DKEY=${key} -DIDENT=${ident} ${check}
              -P "${TESTBED_CMAKE_DIR}/EmbedShader.cmake"
      DEPENDS "${abs}" "${TESTBED_CMAKE_DIR}/EmbedShader.cmake"
      COMMENT "Embedding ${key}"
      VERBATIM)
    list(APPEND outputs "${out}")
  endforeach()
  target_sources(${target} PRIVATE ${outputs})
endfunction()

# testbed_set_technique_family(<target> [<family>])
# A technique's family (`testbed list`, the records, the README table) is the name of the
# folder that defines it, unless given: TESTBED_TECHNIQUE_FAMILY="<folder>" for its sources,
# read by TESTBED_REGISTER_TECHNIQUE and PluginRegistrar::add<T>().
function(testbed_set_technique_family target)
  if(ARGC GREATER 1)
    set(family "${ARGV1}")
  else()
    get_filename_component(family "${CMAKE_CURRENT_SOURCE_DIR}" NAME)
  endif()
  target_compile_definitions(${target} PRIVATE TESTBED_TECHNIQUE_FAMILY="${family}")
endfunction()

# testbed_add_technique(<name> SOURCES ... SHADERS ...)
# A technique is an OBJECT library so that its static self-registration object is always
# linked (a static archive would let the linker drop it, since nothing references it).
function(testbed_add_technique name)
  cmake_parse_arguments(ARG "" "" "SOURCES;SHADERS" ${ARGN})
  set(target technique_${name})
  add_library(${target} OBJECT ${ARG_SOURCES})
  target_link_libraries(${target} PUBLIC testbed_core)
  testbed_set_technique_family(${target})
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

# testbed_add_plugin(<name> SOURCES ... [SHADERS ...] [FAMILY <family>])
# An out-of-tree technique library lib<name>.so for `testbed ... --plugin` (see
# testbed/technique/plugin.h). It compiles against testbed::plugin_api (headers and
# definitions only) and leaves the core's symbols undefined: they bind to the `testbed`
# executable at load time. Shader keys are paths relative to CMAKE_SOURCE_DIR; a key the
# testbed already has keeps the testbed's text, so keep shaders in a folder of your own.
# List every shader, helper .glsl files included: an include that is neither in SHADERS
# nor the testbed's stops the build.
function(testbed_add_plugin name)
  cmake_parse_arguments(ARG "" "FAMILY" "SOURCES;SHADERS" ${ARGN})
  add_library(${name} MODULE ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE testbed::plugin_api)
  testbed_set_technique_family(${name} ${ARG_FAMILY})
  if(ARG_SHADERS)
    testbed_embed_shaders(${name} FILES ${ARG_SHADERS} CHECK_INCLUDES)
  endif()
endfunction()
