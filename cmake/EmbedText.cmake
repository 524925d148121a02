# Script mode: turns one text file into a C++ source defining `const char <SYMBOL>[]` in
# namespace testbed with the file's bytes (report_html.cpp's script and style).
file(READ "${INPUT}" content)
set(delim "text_embed")
string(FIND "${content}" ")${delim}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )${delim}\"")
endif()
file(WRITE "${OUTPUT}.tmp"
"// Generated from ${INPUT}; do not edit.\nnamespace testbed {\nextern const char ${SYMBOL}[];\nconst char ${SYMBOL}[] = R\"${delim}(${content})${delim}\";\n}  // namespace testbed\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
