// What every shader program shares (the base of the classes in
// programs.hpp): linking with a named error, text inserted after the
// "#version" line (defines, the frustum.glsl snippet), one table of
// uniform names looked up at link time (the first missing one is an
// error), and the typed glUniform* calls the setters use.
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

#include <glm/glm.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace render {

class ShaderProgram {
public:
    // glUseProgram; the setters change the uniforms of the program in use,
    // so call it first.
    void use() const;

protected:
    // The program's name in errors ("clipped scene") and its two stages.
    struct Source {
        const char* name = "";
        std::string vertex;
        std::string fragment;
    };
    // One row of a program's uniform table: the GLSL name and where its
    // location goes (a private member of the derived class).
    struct Uniform {
        const char* name;
        GLint* location;
    };

    // Links `source` and finds every uniform of the table. Errors:
    // "render::ShaderProgram::link(): <name> program: <stage and info log>" or
    // "render::ShaderProgram::link(): <name> program has no active uniform u_model".
    frustum::Status link(const gl::Functions& fn, const Source& source, const std::vector<Uniform>& uniforms);

    const gl::Functions& fn() const { return *fn_; }

    void set(GLint location, int value) const;
    void set(GLint location, float value) const;
    void set(GLint location, const glm::vec2& value) const;
    void set(GLint location, const glm::vec3& value) const;
    void set(GLint location, const glm::vec4& value) const;
    void set(GLint location, const glm::mat3& value) const;
    void set(GLint location, const glm::mat4& value) const;
    void set(GLint location, const glm::vec4* values, int count) const;

private:
    const gl::Functions* fn_ = nullptr;
    gl::Program program_;
};

namespace detail {

// `text` inserted after the "#version" line, which must stay first.
std::string insert_after_version(std::string_view source, std::string_view text);

} // namespace detail
} // namespace render
