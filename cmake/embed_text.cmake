# Writes OUTPUT, a C++ source defining `extern const char SYMBOL[]` (in pierre::io::detail) as
# the text of INPUT, so that the binary carries the layout it was built with.
#   cmake -DINPUT=... -DOUTPUT=... -DSYMBOL=... -P embed_text.cmake
file(READ "${INPUT}" text)
set(delim "pierre_layout")
string(FIND "${text}" ")${delim}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} holds the raw-string delimiter )${delim}\"")
endif()
file(WRITE "${OUTPUT}.tmp"
     "// Generated from ${INPUT} by cmake/embed_text.cmake: do not edit.\n"
     "namespace pierre::io::detail {\n"
     "extern const char ${SYMBOL}[];\n"
     "const char ${SYMBOL}[] = R\"${delim}(${text})${delim}\";\n"
     "}  // namespace pierre::io::detail\n")
# Rewritten only when it changes, so that an unchanged layout rebuilds nothing.
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
