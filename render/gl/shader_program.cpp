#include "render/gl/shader_program.h"

#include "render/gl/shader_sources.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <stdexcept>

namespace kappa::render {

namespace {

const char* stage_name(GLenum type) {
    switch (type) {
        case GL_VERTEX_SHADER: return "vertex";
        case GL_GEOMETRY_SHADER: return "geometry";
        case GL_FRAGMENT_SHADER: return "fragment";
        case GL_COMPUTE_SHADER: return "compute";
        default: return "shader";
    }
}

std::string join_names(const std::vector<std::string>& files) {
    std::string s;
    for (size_t i = 0; i < files.size(); ++i) s += (i ? " + " : "") + std::string("shaders/") + files[i];
    return s;
}

GLuint compile(const ShaderStage& stage) {
    // "#line 1 N" makes GL logs report "N:line" with N = index of the file
    // (0 is the version line): the error message lists the files in order.
    // GLSL 3.30 (GL 3.3) for the drawing stages; compute passes need 4.30.
    const char* version = stage.type == GL_COMPUTE_SHADER ? "#version 430 core\n" : "#version 330 core\n";
    std::vector<std::string> parts{version + stage.defines};
    for (size_t i = 0; i < stage.files.size(); ++i)
        parts.push_back("#line 1 " + std::to_string(i + 1) + "\n" + shader_text(stage.files[i]) + "\n");
    std::vector<const char*> ptrs;
    for (const auto& p : parts) ptrs.push_back(p.c_str());

    GLuint shader = glCreateShader(stage.type);
    glShaderSource(shader, GLsizei(ptrs.size()), ptrs.data(), nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetShaderInfoLog(shader, len, nullptr, log.data());
        glDeleteShader(shader);
        std::string files;
        for (size_t i = 0; i < stage.files.size(); ++i)
            files += " " + std::to_string(i + 1) + "=shaders/" + stage.files[i];
        throw std::runtime_error(std::string("cannot compile the ") + stage_name(stage.type) + " shader " +
                                 join_names(stage.files) + " (source numbers:" + files + "): " + log.c_str());
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::vector<ShaderStage>& stages) {
    std::vector<GLuint> shaders;
    std::string names;
    try {
        for (const auto& s : stages) {
            shaders.push_back(compile(s));
            names += (names.empty() ? "" : ", ") + join_names(s.files);
        }
    } catch (...) {
        for (GLuint s : shaders) glDeleteShader(s);
        throw;
    }
    id_ = glCreateProgram();
    for (GLuint s : shaders) glAttachShader(id_, s);
    glLinkProgram(id_);
    for (GLuint s : shaders) glDeleteShader(s);
    GLint ok = 0;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        glGetProgramInfoLog(id_, len, nullptr, log.data());
        glDeleteProgram(id_);
        id_ = 0;
        throw std::runtime_error("cannot link the shader program " + names + ": " + log.c_str());
    }
}

ShaderProgram::~ShaderProgram() {
    if (id_) glDeleteProgram(id_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& o) noexcept : id_(o.id_), locations_(std::move(o.locations_)) {
    o.id_ = 0;
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& o) noexcept {
    if (this != &o) {
        if (id_) glDeleteProgram(id_);
        id_ = o.id_;
        locations_ = std::move(o.locations_);
        o.id_ = 0;
    }
    return *this;
}

GLint ShaderProgram::location(const char* name) {
    auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    GLint loc = glGetUniformLocation(id_, name);
    locations_.emplace(name, loc);
    return loc;
}

void ShaderProgram::set(const char* name, int v) { glUniform1i(location(name), v); }
void ShaderProgram::set(const char* name, float v) { glUniform1f(location(name), v); }
void ShaderProgram::set(const char* name, glm::vec2 v) { glUniform2fv(location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, glm::vec3 v) { glUniform3fv(location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, glm::vec4 v) { glUniform4fv(location(name), 1, glm::value_ptr(v)); }
void ShaderProgram::set(const char* name, const glm::mat3& m) {
    glUniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(m));
}
void ShaderProgram::set(const char* name, const glm::mat4& m) {
    glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace kappa::render
