#include "render/frustum_view_pass.hpp"

#include "render/gpu_scene.hpp"
#include "render/scene_pass.hpp"

#include <gl/errors.hpp>
#include <gl/objects.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <utility>

namespace render {

frustum::Status draw_frustum_view(const PassContext& ctx, const frustum::MatrixPair<float>& viewer,
                                  const std::vector<FrustumOverlay>& overlays, const plan::FrustumLineStyle& style) {
    begin_frame(ctx);
    draw_scene(ctx, SceneDraw{viewer});

    std::vector<glm::vec3> vertices;
    std::vector<std::pair<GLint, GLsizei>> ranges; // first vertex, count per overlay
    for (const FrustumOverlay& overlay : overlays) {
        const std::vector<glm::vec3> lines = plan::frustum_lines(overlay.pair, style);
        ranges.emplace_back(static_cast<GLint>(vertices.size()), static_cast<GLsizei>(lines.size()));
        vertices.insert(vertices.end(), lines.begin(), lines.end());
    }
    const gl::Functions& fn = ctx.fn;
    auto lines = create_position_buffer(fn, "render::draw_frustum_view()"); // bound
    if (!lines) {
        return lines.take_error();
    }
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(glm::vec3)), vertices.data(),
                  GL_STREAM_DRAW);

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
