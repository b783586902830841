// A linked GLSL program built from embedded shaders/*/*.glsl files, named by
// their room ("lines/lines_frag.glsl"). Each stage is the concatenation of one
// or more files (shared functions first), after a "#version 330 core" line
// ("#version 430 core" for compute shaders; "#version 300 es" in the browser build, gles_compat.h);
// compile errors name the files and carry the GL log.
#pragma once

#include "render/gl/gl.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <string>
#include <unordered_map>
#include <vector>

namespace kappa::render {

struct ShaderStage {
    GLenum type;                     // GL_VERTEX_SHADER, GL_GEOMETRY_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::vector<std::string> files;  // embedded file names, concatenated in order
    std::string defines = {};        // lines inserted after #version, e.g. "#define KAPPA_HATCHING\n"
};

class ShaderProgram {
public:
    ShaderProgram() = default;
    // Compiles and links; throws std::runtime_error naming the files and
    // quoting the GL log.
    explicit ShaderProgram(const std::vector<ShaderStage>& stages);
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& o) noexcept;
    ShaderProgram& operator=(ShaderProgram&& o) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    void use() const { glUseProgram(id_); }
    GLuint id() const { return id_; }

    // Uniform setters for the program in use; unknown names (e.g. optimised
    // away) are ignored.
    void set(const char* name, int v);
    void set(const char* name, float v);
    void set(const char* name, glm::vec2 v);
    void set(const char* name, glm::vec3 v);
    void set(const char* name, glm::vec4 v);
    void set(const char* name, const glm::mat3& m);
    void set(const char* name, const glm::mat4& m);

private:
    GLint location(const char* name);
    GLuint id_ = 0;
    std::unordered_map<std::string, GLint> locations_;
};

// A program with a geometry stage, or none (id 0) on OpenGL ES, which has no geometry stage: the
// passes that use one are never taken there (gles_compat.h).
ShaderProgram geometry_stage_program(const std::vector<ShaderStage>& stages);

}  // namespace kappa::render
