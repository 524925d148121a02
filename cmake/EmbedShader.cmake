# Script mode: turns one GLSL file into a C++ source that registers it with the shader
# library at static-initialization time. Include directives are resolved at run time by
# the library, so the generated file holds the text unchanged.
#
# With SHADER_KEYS ("|"-separated: the keys its target embeds) and TESTBED_ROOT (the
# testbed's source folder), it first checks every `#include "key"`: the key must be one
# of SHADER_KEYS, or the testbed's own (testbed/, techniques/ or groundtruth/, a file under
# TESTBED_ROOT). Else the build stops here, naming the file and line, instead of the
# shader failing to compile when the technique first runs.
cmake_minimum_required(VERSION 3.25)  # script mode: the policies of IN_LIST and continue()
file(READ "${INPUT}" content)
if(DEFINED SHADER_KEYS)
  string(REPLACE "|" ";" keys "${SHADER_KEYS}")
  # One list element per line: the text's own ';' and brackets would split or join them.
  string(REPLACE ";" "<s>" lines "${content}")
  string(REPLACE "[" "<l>" lines "${lines}")
  string(REPLACE "]" "<r>" lines "${lines}")
  string(REPLACE "\n" ";" lines "${lines}")
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    if(line MATCHES "^[ \t]*#[ \t]*include[ \t]*\"([^\"]*)\"")
      set(included "${CMAKE_MATCH_1}")
      if(included IN_LIST keys)
        continue()
      endif()
      if(included MATCHES "^(testbed|techniques|groundtruth)/" AND EXISTS "${TESTBED_ROOT}/${included}")
        continue()
      endif()
      message(FATAL_ERROR "${INPUT}:${number}: #include \"${included}\" is not in the SHADERS list of "
                          "${TARGET} (nor a shader of the testbed's): add it there so it is embedded")
    endif()
  endforeach()
endif()
set(delim "glsl_embed")
string(FIND "${content}" ")${delim}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )${delim}\"")
endif()
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${KEY}; do not edit.\n#include \"testbed/gl/shader_library.h\"\nnamespace {\nconst testbed::ShaderRegistration reg_${IDENT}{\"${KEY}\", R\"${delim}(${content})${delim}\"};\n}\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
