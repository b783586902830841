// GLSL sources of shaders/*/*.glsl, embedded into the binary at build time
// (cmake/render_embed_shaders.cmake) so kappa runs from any directory.
#pragma once

#include <string>
#include <vector>

namespace kappa::render {

struct ShaderSource {
    const char* name;  // file name in shaders/, e.g. "surface/surface_frag.glsl"
    const char* text;
};

// Every embedded shader file, sorted by name (generated code).
const std::vector<ShaderSource>& embedded_shaders();

// The text of one embedded file; throws std::runtime_error naming the file
// when there is none.
const char* shader_text(const std::string& name);

}  // namespace kappa::render
