# cmake -DOUTPUT=file.cpp -DSHADER_DIR=dir -P render_embed_shaders.cmake
# Writes a C++ file defining kappa::render::embedded_shaders(): every
# SHADER_DIR/*/*.glsl as a (path under SHADER_DIR, source text) pair of raw string
# literals: shaders are named by their room, e.g. "lines/line_quad.glsl".
file(GLOB_RECURSE files RELATIVE ${SHADER_DIR} ${SHADER_DIR}/*.glsl)
list(SORT files)
set(body "")
foreach(name ${files})
  file(READ ${SHADER_DIR}/${name} text)
  # Raw string literals: the delimiter must not occur in the shader text.
  string(APPEND body "    {\"${name}\", R\"kappa_glsl(${text})kappa_glsl\"},\n")
endforeach()
file(WRITE ${OUTPUT}
"// Generated from shaders/*/*.glsl by cmake/render_embed_shaders.cmake. Do not edit.
#include \"render/gl/shader_sources.h\"

namespace kappa::render {

const std::vector<ShaderSource>& embedded_shaders() {
  static const std::vector<ShaderSource> shaders = {
${body}  };
  return shaders;
}

}  // namespace kappa::render
")
