# fxview_embed_text(TARGET NAME FILES...): compiles text files (built-in GLSL) into the binary so
# that the CLI works from any directory. Each file becomes `std::string_view NAME_<stem>_<ext>`.
function(fxview_embed_text target namespace)
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/${target}_embedded.cpp)
  set(inputs ${ARGN})
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${generated} -DNAMESPACE=${namespace}
            "-DINPUTS=${inputs}" -P ${PROJECT_SOURCE_DIR}/cmake/EmbedTextScript.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/EmbedTextScript.cmake
    COMMENT "Embedding ${namespace} text files"
    VERBATIM)
  target_sources(${target} PRIVATE ${generated})
endfunction()
