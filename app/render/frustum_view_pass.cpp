#include "render/frustum_view_pass.hpp"

#include "render/gpu_scene.hpp"
#include "render/scene_pass.hpp"

#include <gl/errors.hpp>
#include <gl/objects.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <utility>

namespace render {

frustum::Status draw_frustum_view(const PassContext& ctx, const frustum::MatrixPair<float>& viewer,
                                  const std::vector<FrustumOverlay>& overlays, const FrustumLineStyle& style) {
    begin_frame(ctx);
    draw_scene(ctx, SceneDraw{viewer});

    std::vector<glm::vec3> vertices;
    std::vector<std::pair<GLint, GLsizei>> ranges; // first vertex, count per overlay
    for (const FrustumOverlay& overlay : overlays) {
        const std::vector<glm::vec3> lines = frustum_lines(overlay.pair, style);
        ranges.emplace_back(static_cast<GLint>(vertices.size()), static_cast<GLsizei>(lines.size()));
        vertices.insert(vertices.end(), lines.begin(), lines.end());
    }
    const gl::Functions& fn = ctx.fn;
    auto buffer = gl::Buffer::create(fn);
    auto vertex_array = gl::VertexArray::create(fn);
    if (!buffer || !vertex_array) {
        return frustum::Error{"render::draw_frustum_view(): " + (!buffer ? buffer.error() : vertex_array.error())};
    }
    fn.BindVertexArray(vertex_array->id());
    fn.BindBuffer(GL_ARRAY_BUFFER, buffer->id());
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)), vertices.data(),
                  GL_STREAM_DRAW);
    fn.EnableVertexAttribArray(kPositionLocation);
    fn.VertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);

    const LineProgram& p = ctx.programs.line;
    p.use();
    p.set_view_projection(ctx.depth.to_gpu(viewer).matrix());
    fn.Disable(GL_DEPTH_TEST);
    for (std::size_t i = 0; i < overlays.size(); ++i) {
        p.set_color(overlays[i].color);
        fn.DrawArrays(GL_LINES, ranges[i].first, ranges[i].second);
    }
    fn.Enable(GL_DEPTH_TEST);
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    return gl::check_error(fn, "render::draw_frustum_view()");
}

} // namespace render
