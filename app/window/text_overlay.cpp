#include "window/text_overlay.hpp"

#include "window/text_layout.hpp"

#include <frustum/projection.hpp>
#include <gl/errors.hpp>
#include <render/gpu_scene.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <utility>

namespace window {
namespace {

constexpr float kMarginPx = 8.0f;   // panel from the framebuffer's corner, at scale 1
constexpr float kPaddingPx = 6.0f;  // text from the panel's edge, at scale 1
constexpr glm::vec4 kPanelColor{0.05f, 0.05f, 0.08f, 0.72f};
constexpr glm::vec4 kTextColor{1.0f, 1.0f, 1.0f, 1.0f};

// Two triangles covering [x0, x1] x [y0, y1].
void append_rectangle(std::vector<glm::vec3>& out, float x0, float y0, float x1, float y1) {
    for (const glm::vec2 p : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0),
                              glm::vec2(x1, y1), glm::vec2(x0, y1)}) {
        out.emplace_back(p, 0.0f);
    }
}

} // namespace

TextOverlay::TextOverlay(const gl::Functions& fn, gl::Buffer buffer, gl::VertexArray vertex_array)
    : fn_(&fn), buffer_(std::move(buffer)), vertex_array_(std::move(vertex_array)) {}

frustum::Result<TextOverlay> TextOverlay::create(const gl::Functions& fn) {
    auto made = render::create_position_buffer(fn, "window::TextOverlay::create()");
    if (!made) {
        return made.take_error();
    }
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    return TextOverlay(fn, std::move(made->buffer), std::move(made->vertex_array));
}

frustum::Status TextOverlay::draw(const render::LineProgram& program, frustum::DepthRange gpu_depth,
                                  const std::vector<std::string>& lines, int width_px, int height_px) const {
    // Pixels to clip space: an orthographic box over the framebuffer; z = 0
    // lies between its near (-1) and far (1) planes.
    auto pixels = frustum::orthographic<float>(0.0f, static_cast<float>(width_px), 0.0f,
                                               static_cast<float>(height_px), -1.0f, 1.0f, gpu_depth);
    if (!pixels) {
        return frustum::Error{"window::TextOverlay::draw(): " + pixels.error()};
    }
    const float scale = height_px >= 720 ? 2.0f : 1.0f;
    const float inset_px = (kMarginPx + kPaddingPx) * scale;
    const TextLayout text = layout_text(lines, glm::vec2(inset_px), scale, height_px);
    std::vector<glm::vec3> vertices;
    const float top = static_cast<float>(height_px) - kMarginPx * scale;
    append_rectangle(vertices, kMarginPx * scale, top - text.size_px.y - 2.0f * kPaddingPx * scale,
                     kMarginPx * scale + text.size_px.x + 2.0f * kPaddingPx * scale, top);
    vertices.insert(vertices.end(), text.triangles.begin(), text.triangles.end());

    const gl::Functions& fn = *fn_;
    fn.BindVertexArray(vertex_array_.id());
    fn.BindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)), vertices.data(),
                  GL_STREAM_DRAW);
    program.use();
    program.set_view_projection(pixels->matrix());
    fn.Disable(GL_DEPTH_TEST);
    fn.Disable(GL_CULL_FACE);
    fn.Enable(GL_BLEND);
    fn.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    program.set_color(kPanelColor);
    fn.DrawArrays(GL_TRIANGLES, 0, 6);
    program.set_color(kTextColor);
    fn.DrawArrays(GL_TRIANGLES, 6, static_cast<GLsizei>(text.triangles.size()));
    fn.Disable(GL_BLEND);
    fn.Enable(GL_DEPTH_TEST);
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    return gl::check_error(fn, "window::TextOverlay::draw()");
}

} // namespace window
