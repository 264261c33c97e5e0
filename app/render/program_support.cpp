#include "render/program_support.hpp"

#include <glm/gtc/type_ptr.hpp>

namespace render {
namespace {

constexpr const char* kLink = "render::ShaderProgram::link()";

} // namespace

void ShaderProgram::use() const { fn_->UseProgram(program_.id()); }

frustum::Status ShaderProgram::link(const gl::Functions& fn, const Source& source,
                                    const std::vector<Uniform>& uniforms) {
    auto program = gl::Program::build(fn, source.vertex, source.fragment);
    if (!program) {
        return frustum::Error{std::string(kLink) + ": " + source.name + " program: " + program.error()};
    }
    fn_ = &fn;
    program_ = std::move(*program);
    for (const Uniform& uniform : uniforms) {
        *uniform.location = fn.GetUniformLocation(program_.id(), uniform.name);
        if (*uniform.location < 0) {
            return frustum::Error{std::string(kLink) + ": " + source.name +
                                  " program has no active uniform " + uniform.name};
        }
    }
    return {};
}

void ShaderProgram::set(GLint location, int value) const { fn_->Uniform1i(location, value); }
void ShaderProgram::set(GLint location, float value) const { fn_->Uniform1f(location, value); }
void ShaderProgram::set(GLint location, const glm::vec2& value) const { fn_->Uniform2f(location, value.x, value.y); }
void ShaderProgram::set(GLint location, const glm::vec3& value) const {
    fn_->Uniform3f(location, value.x, value.y, value.z);
}
void ShaderProgram::set(GLint location, const glm::vec4& value) const {
    fn_->Uniform4fv(location, 1, glm::value_ptr(value));
}
void ShaderProgram::set(GLint location, const glm::mat3& value) const {
    fn_->UniformMatrix3fv(location, 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(GLint location, const glm::mat4& value) const {
    fn_->UniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(value));
}
void ShaderProgram::set(GLint location, const glm::vec4* values, int count) const {
    fn_->Uniform4fv(location, count, glm::value_ptr(values[0]));
}

namespace detail {

std::string insert_after_version(std::string_view source, std::string_view text) {
    const std::size_t line_end = source.find('\n') + 1;
    return std::string(source.substr(0, line_end)) + std::string(text) + std::string(source.substr(line_end));
}

} // namespace detail
} // namespace render
