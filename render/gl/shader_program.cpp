#include "render/gl/shader_program.h"

#include "render/gl/shader_sources.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <regex>
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

// GLSL ES 3.00 (OpenGL ES 3.0) has no blocks between stages: each `in|out Name { members } instance;`
// becomes one variable a member, named Name_member (stages then match by the block's name, as blocks
// do), and `instance.member` becomes Name_member. Comments go first (they may hold ';' or '}').
std::string without_interface_blocks(const std::string& source) {
    static const std::regex comment(R"(//[^\n]*|/\*[^*]*\*+([^/*][^*]*\*+)*/)");
    static const std::regex block(R"(\b(in|out)\s+(\w+)\s*\{([^}]*)\}\s*(\w+)\s*;)");
    static const std::regex member(R"(([^;]*?)(\w+)\s*(\[[^\]]*\])?\s*;)");
    std::string text = std::regex_replace(source, comment, "");
    std::smatch b;
    while (std::regex_search(text, b, block)) {
        const std::string direction = b[1], name = b[2], members = b[3], instance = b[4];
        std::string variables;
        for (auto m = std::sregex_iterator(members.begin(), members.end(), member); m != std::sregex_iterator(); ++m) {
            std::string type = (*m)[1];  // "flat vec4 ": interpolation, then the direction, then the type
            const size_t flat = type.find("flat");
            const std::string interpolation = flat == std::string::npos ? "" : "flat ";
            if (flat != std::string::npos) type.erase(flat, 4);
            variables += interpolation + direction + " " + type + " " + name + "_" + std::string((*m)[2]) +
                         std::string((*m)[3]) + ";\n";
        }
        text = std::string(b.prefix()) + variables + std::string(b.suffix());
        text = std::regex_replace(text, std::regex("\\b" + instance + "\\.(\\w+)"), name + "_$1");
    }
    return text;
}

GLuint compile(const ShaderStage& stage) {
    // "#line 1 N" makes GL logs report "N:line" with N = index of the file
    // (0 is the version line): the error message lists the files in order.
    // GLSL 3.30 (GL 3.3) for the drawing stages; compute passes need 4.30.
    // OpenGL ES 3.0 (web/): the same sources as GLSL ES 3.00, with every precision high.
    const char* version = kGles ? "#version 300 es\nprecision highp float;\nprecision highp int;\n"
                                  "precision highp sampler2D;\nprecision highp sampler2DShadow;\n"
                          : stage.type == GL_COMPUTE_SHADER ? "#version 430 core\n"
                                                            : "#version 330 core\n";
    std::vector<std::string> parts{version + stage.defines};
    for (size_t i = 0; i < stage.files.size(); ++i)
        parts.push_back("#line 1 " + std::to_string(i + 1) + "\n" +
                        (kGles ? without_interface_blocks(shader_text(stage.files[i])) : shader_text(stage.files[i])) +
                        "\n");
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

ShaderProgram geometry_stage_program(const std::vector<ShaderStage>& stages) {
    return kGles ? ShaderProgram() : ShaderProgram(stages);
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
