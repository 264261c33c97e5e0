#include "window/imgui_painter.hpp"

#include <gl/errors.hpp>

#include <imgui.h>

#include <cstddef>
#include <cstdint>
#include <utility>

namespace window {
namespace {

constexpr GLuint kPosition = 0, kUv = 1, kColor = 2;

constexpr const char* kVertexShader = R"(#version 300 es
uniform mat4 projection;
layout(location = 0) in vec2 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 color;
out vec2 frag_uv;
out vec4 frag_color;
void main() {
    frag_uv = uv;
    frag_color = color;
    gl_Position = projection * vec4(position, 0.0, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 300 es
precision mediump float;
uniform sampler2D atlas;
in vec2 frag_uv;
in vec4 frag_color;
out vec4 out_color;
void main() { out_color = frag_color * texture(atlas, frag_uv); }
)";

} // namespace

ImGuiPainter::ImGuiPainter(const gl::Functions& fn, gl::Program program, gl::Texture font, gl::Buffer vertices,
                           gl::Buffer indices, gl::VertexArray vertex_array)
    : fn_(&fn), program_(std::move(program)), font_(std::move(font)), vertices_(std::move(vertices)),
      indices_(std::move(indices)), vertex_array_(std::move(vertex_array)) {
    projection_location_ = fn.GetUniformLocation(program_.id(), "projection");
    texture_location_ = fn.GetUniformLocation(program_.id(), "atlas");
}

frustum::Result<ImGuiPainter> ImGuiPainter::create(const gl::Functions& fn) {
    auto program = gl::Program::build(fn, kVertexShader, kFragmentShader);
    if (!program) {
        return frustum::Error{"window::ImGuiPainter::create(): " + program.error()};
    }
    auto font = gl::Texture::create(fn);
    auto vertices = gl::Buffer::create(fn);
    auto indices = gl::Buffer::create(fn);
    auto vertex_array = gl::VertexArray::create(fn);
    if (!font || !vertices || !indices || !vertex_array) {
        return frustum::Error{"window::ImGuiPainter::create(): cannot make its GL objects"};
    }
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    ImGuiIO& io = ImGui::GetIO();
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    fn.BindTexture(GL_TEXTURE_2D, font->id());
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    fn.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    fn.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    fn.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(font->id())));

    fn.BindVertexArray(vertex_array->id());
    fn.BindBuffer(GL_ARRAY_BUFFER, vertices->id());
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices->id());
    const auto stride = static_cast<GLsizei>(sizeof(ImDrawVert));
    fn.EnableVertexAttribArray(kPosition);
    fn.EnableVertexAttribArray(kUv);
    fn.EnableVertexAttribArray(kColor);
    fn.VertexAttribPointer(kPosition, 2, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(offsetof(ImDrawVert, pos)));
    fn.VertexAttribPointer(kUv, 2, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(ImDrawVert, uv)));
    fn.VertexAttribPointer(kColor, 4, GL_UNSIGNED_BYTE, GL_TRUE, stride,
                           reinterpret_cast<const void*>(offsetof(ImDrawVert, col)));
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    if (auto status = gl::check_error(fn, "window::ImGuiPainter::create()"); !status) {
        return status.take_error();
    }
    return ImGuiPainter(fn, std::move(*program), std::move(*font), std::move(*vertices), std::move(*indices),
                        std::move(*vertex_array));
}

frustum::Status ImGuiPainter::draw(const ImDrawData& data, int width_px, int height_px) const {
    const gl::Functions& fn = *fn_;
    fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    fn.Viewport(0, 0, width_px, height_px);
    fn.Enable(GL_BLEND);
    fn.BlendEquation(GL_FUNC_ADD);
    fn.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    fn.Disable(GL_CULL_FACE);
    fn.Disable(GL_DEPTH_TEST);
    fn.Enable(GL_SCISSOR_TEST);
    // ImGui's pixels (origin top-left, y down) to clip space: an orthographic
    // box over the display, the one matrix of ImGui's backends.
    const ImVec2 origin = data.DisplayPos;
    const ImVec2 scale = data.FramebufferScale;
    const float l = origin.x, r = origin.x + data.DisplaySize.x, t = origin.y, b = origin.y + data.DisplaySize.y;
    const float projection[16] = {2.0f / (r - l), 0, 0, 0, 0, 2.0f / (t - b), 0, 0, 0, 0, -1.0f, 0,
                                  (r + l) / (l - r), (t + b) / (b - t), 0, 1.0f};
    fn.UseProgram(program_.id());
    fn.UniformMatrix4fv(projection_location_, 1, GL_FALSE, projection);
    fn.Uniform1i(texture_location_, 0);
    fn.ActiveTexture(GL_TEXTURE0);
    fn.BindVertexArray(vertex_array_.id());
    fn.BindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.id());
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList& list = *data.CmdLists[n];
        fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.VtxBuffer.Size * sizeof(ImDrawVert)),
                      list.VtxBuffer.Data, GL_STREAM_DRAW);
        fn.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.IdxBuffer.Size * sizeof(ImDrawIdx)),
                      list.IdxBuffer.Data, GL_STREAM_DRAW);
        for (const ImDrawCmd& cmd : list.CmdBuffer) {
            const float x0 = (cmd.ClipRect.x - origin.x) * scale.x, y0 = (cmd.ClipRect.y - origin.y) * scale.y;
            const float x1 = (cmd.ClipRect.z - origin.x) * scale.x, y1 = (cmd.ClipRect.w - origin.y) * scale.y;
            if (x1 <= x0 || y1 <= y0) {
                continue;
            }
            fn.Scissor(static_cast<GLint>(x0), static_cast<GLint>(height_px - y1), static_cast<GLsizei>(x1 - x0),
                       static_cast<GLsizei>(y1 - y0));
            fn.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(reinterpret_cast<std::uintptr_t>(cmd.GetTexID())));
            fn.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(cmd.ElemCount),
                            sizeof(ImDrawIdx) == 2 ? GL_UNSIGNED_SHORT : GL_UNSIGNED_INT,
                            reinterpret_cast<const void*>(cmd.IdxOffset * sizeof(ImDrawIdx)));
        }
    }
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    fn.Disable(GL_SCISSOR_TEST);
    fn.Disable(GL_BLEND);
    fn.Enable(GL_DEPTH_TEST);
    return gl::check_error(fn, "window::ImGuiPainter::draw()");
}

} // namespace window
