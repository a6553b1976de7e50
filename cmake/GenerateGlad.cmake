# Generates the GL 4.5 core loader with python3-glad at build time (no hand-written GL loading).
# The loader is filled through each context backend's get-proc-address, never by linking GL symbols.
set(GLAD_OUT ${CMAKE_BINARY_DIR}/glad)
set(GLAD_EXTENSIONS GL_KHR_debug,GL_ARB_debug_output,GL_EXT_texture_filter_anisotropic,GL_EXT_texture_compression_s3tc,GL_EXT_texture_sRGB)
add_custom_command(
  OUTPUT ${GLAD_OUT}/src/gl.c ${GLAD_OUT}/include/glad/gl.h
  COMMAND ${GLAD_EXECUTABLE} --api gl:core=4.5 --extensions ${GLAD_EXTENSIONS}
          --out-path ${GLAD_OUT} --reproducible --quiet c
  COMMENT "Generating the OpenGL 4.5 core loader with glad"
  VERBATIM)
add_library(fxview_glad STATIC ${GLAD_OUT}/src/gl.c)
target_include_directories(fxview_glad PUBLIC ${GLAD_OUT}/include)
set_target_properties(fxview_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
