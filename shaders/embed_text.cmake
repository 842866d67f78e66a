# Writes a text file into a C++ header as a raw string literal.
#   cmake -DINPUT=file -DOUTPUT=header -DSYMBOL=name -P embed_text.cmake
file(READ ${INPUT} text)
file(WRITE ${OUTPUT} "// Generated from ${INPUT}; do not edit.\n#pragma once\ninline constexpr const char ${SYMBOL}[] = R\"lightcts(${text})lightcts\";\n")
