#include "render/gl/shader_sources.h"

#include <stdexcept>

namespace kappa::render {

const char* shader_text(const std::string& name) {
    for (const auto& s : embedded_shaders())
        if (name == s.name) return s.text;
    throw std::runtime_error("shader file '" + name + "' is not embedded (shaders/" + name + ")");
}

}  // namespace kappa::render
