# lucent_embed_shaders(DIR FUNCTION HEADER OUTPUT): generates OUTPUT, defining
# `const char* lucent::FUNCTION(std::string_view file)` over the shader files of
# DIR (cmake/EmbedShaders.cmake), regenerated when any of them changes.
function(lucent_embed_shaders dir function header output)
  file(GLOB shader_files CONFIGURE_DEPENDS ${dir}/*.vert ${dir}/*.geom ${dir}/*.frag ${dir}/*.comp ${dir}/*.glsl
       ${dir}/*.cl ${dir}/gpu_layout.h ${dir}/cl_layout.h)
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DSHADER_DIR=${dir} -DFUNCTION=${function} -DHEADER=${header} -DOUTPUT=${output}
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake
    DEPENDS ${shader_files} ${PROJECT_SOURCE_DIR}/cmake/EmbedShaders.cmake
    COMMENT "Embedding the GLSL shaders of ${dir}")
endfunction()
