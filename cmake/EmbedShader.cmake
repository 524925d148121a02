# Script mode: turns one GLSL file into a C++ source that registers it with the shader
# library at static-initialization time. Include directives are resolved at run time by
# the library, so the generated file holds the text unchanged.
file(READ "${INPUT}" content)
set(delim "glsl_embed")
string(FIND "${content}" ")${delim}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )${delim}\"")
endif()
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${KEY}; do not edit.\n#include \"testbed/gl/shader_library.h\"\nnamespace {\nconst testbed::ShaderRegistration reg_${IDENT}{\"${KEY}\", R\"${delim}(${content})${delim}\"};\n}\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
