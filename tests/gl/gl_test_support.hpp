// Shared by the gl suite: a context plus its function table, a solid-colour
// shader and a one-triangle draw.
#pragma once

#include "image_printer.hpp"
#include "../skips.hpp"

#include <doctest/doctest.h>

#include <gl/context.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>
#include <image/image.hpp>

#include <array>
#include <cstdlib>
#include <memory>
#include <string>


namespace gl_test {

inline constexpr gl::Backend kBackends[] = {gl::Backend::Egl, gl::Backend::OsMesa};

// Declared in this order so the table dies before the context; GL objects
// of a test live in its own scope, which ends before this is destroyed.
struct Environment {
    std::unique_ptr<gl::Context> context;
    gl::Functions fn;
};

// Null, with the backend's error in `why`, when the backend cannot make a context.
inline std::unique_ptr<Environment> try_environment(gl::Backend backend, std::string& why,
                                                    const gl::ContextOptions& options = {}) {
    auto context = gl::create_offscreen_context(backend, options);
    if (!context) {
        why = std::string(gl::to_string(backend)) + ": " + context.error();
        return nullptr;
    }
    auto fn = gl::Functions::load(**context);
    REQUIRE_MESSAGE(fn.ok(), fn.error());
    return std::unique_ptr<Environment>(new Environment{std::move(*context), *fn});
}

// Null, after recording a skip (tests/skips.hpp), when the backend cannot
// make a context: the caller returns (or goes on to the next backend), and
// the suite reports a skip, not a pass.
inline std::unique_ptr<Environment> make_environment(gl::Backend backend,
                                                     const gl::ContextOptions& options = {}) {
    std::string why;
    auto env = try_environment(backend, why, options);
    if (!env) {
        test_skips::skip(why);
    }
    return env;
}

// EGL, else OSMesa; null (after recording a skip with both errors) when neither works.
inline std::unique_ptr<Environment> make_any_environment(const gl::ContextOptions& options = {}) {
    std::string why_not;
    for (gl::Backend backend : kBackends) {
        std::string why;
        if (auto env = try_environment(backend, why, options)) {
            return env;
        }
        why_not += (why_not.empty() ? "" : "; ") + why;
    }
    test_skips::skip(why_not);
    return nullptr;
}

// The ES 3.0 rerun that removes GL_EXT_clip_control (tests/app_tests.cmake):
// there a context without clip control is what was asked for, not a skip.
inline bool clip_control_removed_on_purpose() {
    const char* expect = std::getenv("FRUSTUM_EXPECT_GLES");
    return expect != nullptr && std::string(expect) == "3.0-no-clip-control";
}

inline bool near(const image::Rgba& a, const image::Rgba& b, int tolerance) {
    for (std::size_t c = 0; c < 4; ++c) {
        if (std::abs(int{a[c]} - int{b[c]}) > tolerance) {
            return false;
        }
    }
    return true;
}

inline constexpr const char* kVertexShader = R"(#version 300 es
layout(location = 0) in vec4 a_position;
void main() { gl_Position = a_position; }
)";

inline constexpr const char* kFragmentShader = R"(#version 300 es
precision mediump float;
uniform vec4 u_color;
out vec4 o_color;
void main() { o_color = u_color; }
)";

using Vertex = std::array<float, 4>; // clip-space x, y, z, w

// Draws one triangle of a solid colour with `program` (built from the two
// shaders above) into whatever framebuffer is bound.
inline void draw_triangle(const gl::Functions& fn, const gl::Program& program,
                          const std::array<Vertex, 3>& vertices, const std::array<float, 4>& color) {
    auto buffer = gl::Buffer::create(fn);
    auto vertex_array = gl::VertexArray::create(fn);
    REQUIRE_MESSAGE(buffer.ok(), buffer.error());
    REQUIRE_MESSAGE(vertex_array.ok(), vertex_array.error());
    fn.BindVertexArray(vertex_array->id());
    fn.BindBuffer(GL_ARRAY_BUFFER, buffer->id());
    fn.BufferData(GL_ARRAY_BUFFER, sizeof vertices, vertices.data(), GL_STATIC_DRAW);
    fn.EnableVertexAttribArray(0);
    fn.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    fn.UseProgram(program.id());
    fn.Uniform4fv(fn.GetUniformLocation(program.id(), "u_color"), 1, color.data());
    fn.DrawArrays(GL_TRIANGLES, 0, 3);
    fn.BindVertexArray(0);
}

} // namespace gl_test
