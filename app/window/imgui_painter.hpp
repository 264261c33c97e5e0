// Dear ImGui's draw lists into framebuffer 0 through the project's own GL
// table (gl::Functions), so the panel needs no second GL loader: Debian's
// libimgui-dev ships the backends (imgui_impl_opengl3) compiled against
// their own loader for desktop libGL, which the window's EGL / GLES 3
// context does not go through. This is ImGui's documented "render your
// ImDrawData" loop: one program (GLSL ES 3.00), the font atlas as a texture,
// a vertex and an index buffer refilled per draw list, one scissored draw
// per command.
#pragma once

#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>

struct ImDrawData;

namespace window {

class ImGuiPainter {
public:
    // Needs the current ImGui context (its font atlas is uploaded here).
    static frustum::Result<ImGuiPainter> create(const gl::Functions& fn);

    // Draws `data` over framebuffer 0 (width_px x height_px pixels), blended,
    // no depth test; leaves blending, scissor and depth test as the
    // renderer expects them (off, off, on).
    frustum::Status draw(const ImDrawData& data, int width_px, int height_px) const;

private:
    ImGuiPainter(const gl::Functions& fn, gl::Program program, gl::Texture font, gl::Buffer vertices,
                 gl::Buffer indices, gl::VertexArray vertex_array);

    const gl::Functions* fn_;
    gl::Program program_;
    gl::Texture font_;
    gl::Buffer vertices_, indices_;
    gl::VertexArray vertex_array_;
    GLint projection_location_ = -1, texture_location_ = -1;
};

} // namespace window
