# cmake -DINPUT=file -DOUTPUT=file.cpp -DSYMBOL=name -DNAMESPACE=ns -P EmbedText.cmake
# Writes OUTPUT defining `extern const char SYMBOL[]` in NAMESPACE with INPUT's text.
file(READ ${INPUT} text)
string(FIND "${text}" ")embedded\"" clash)
if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${INPUT} contains the raw-string delimiter )embedded\"")
endif()
file(WRITE ${OUTPUT} "// Generated from ${INPUT} by EmbedText.cmake.\nnamespace ${NAMESPACE} {\n"
                     "extern const char ${SYMBOL}[];\nconst char ${SYMBOL}[] = R\"embedded(${text})embedded\";\n}\n")
