# kappa_embed_shaders(ROOT OUT_VAR): a build step that embeds ROOT/shaders/*/*.glsl as string
# literals (cmake/render_embed_shaders.cmake) into a generated .cpp, whose path goes to OUT_VAR.
# Shared by the desktop renderer (cmake/render.cmake) and the web page (web/CMakeLists.txt).
function(kappa_embed_shaders root out_var)
  file(GLOB_RECURSE shader_files CONFIGURE_DEPENDS ${root}/shaders/*.glsl)
  set(out ${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${out} -DSHADER_DIR=${root}/shaders
            -P ${root}/cmake/render_embed_shaders.cmake
    DEPENDS ${shader_files} ${root}/cmake/render_embed_shaders.cmake
    COMMENT "Embedding shaders/*/*.glsl"
    VERBATIM)
  set(${out_var} ${out} PARENT_SCOPE)
endfunction()
