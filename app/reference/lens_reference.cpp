#include "reference/lens_reference.hpp"

#include "reference/embedded_shaders.hpp"

#include <render/program_support.hpp>
#include <render/scene_pass.hpp>

#include <frustum/crop.hpp>
#include <frustum/lens.hpp>
#include <gl/errors.hpp>
#include <gl/objects.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace reference {
namespace {

constexpr const char* kWhere = "reference::draw_lens_reference()";

// shaders/lens_remap.*: the per-pixel lens reference (eq. 34 in GLSL). Only
// this reference uses it, so it is built here, not by every Renderer.
class LensRemapProgram : public render::ShaderProgram {
public:
    static frustum::Result<LensRemapProgram> build(const gl::Functions& fn) {
        LensRemapProgram p;
        if (auto status = p.link(fn, {"lens remap", std::string(shaders::lens_remap_vert),
                                      std::string(shaders::lens_remap_frag)},
                                 {{"u_source", &p.source_},
                                  {"u_source_rect_m", &p.source_rect_m_},
                                  {"u_frame_px", &p.frame_px_},
                                  {"u_half_size_m", &p.half_size_m_},
                                  {"u_lens", &p.lens_}});
            !status) {
            return frustum::Error{status.error()};
        }
        return p;
    }

    void set_source_texture_unit(int unit) const { set(source_, unit); }
    // The unwarped view's near-plane rectangle: x0, y0, x1, y1 in metres.
    void set_source_rect_m(const glm::vec4& rect_m) const { set(source_rect_m_, rect_m); }
    void set_frame_px(const glm::vec2& size_px) const { set(frame_px_, size_px); }
    void set_half_size_m(const glm::vec2& half_m) const { set(half_size_m_, half_m); }
    void set_lens(const frustum::Lens<float>& lens) const {
        set(lens_, glm::vec4(lens.center_m.x, lens.center_m.y, lens.radius_m, lens.power));
    }

private:
    GLint source_ = -1, source_rect_m_ = -1, frame_px_ = -1, half_size_m_ = -1, lens_ = -1;
};

// How many times the near rectangle (about its centre) the warped pixel
// centres reach. eq. 34 moves points radially and monotonically about C, so
// the frame's image is bounded by the image of its border.
float warped_reach(const frustum::NearPlaneFrame<float>& frame, const frustum::Lens<float>& lens, int width_px,
                   int height_px) {
    float reach = 1.0f;
    const auto visit = [&](int x, int y) {
        const glm::vec2 ndc((x + 0.5f) / width_px * 2.0f - 1.0f, (y + 0.5f) / height_px * 2.0f - 1.0f);
        const glm::vec2 warped = frustum::lens_warp(ndc * glm::vec2(frame.half_width_m, frame.half_height_m), lens);
        reach = std::max({reach, std::abs(warped.x) / frame.half_width_m, std::abs(warped.y) / frame.half_height_m});
    };
    for (int x = 0; x < width_px; ++x) {
        visit(x, 0);
        visit(x, height_px - 1);
    }
    for (int y = 0; y < height_px; ++y) {
        visit(0, y);
        visit(width_px - 1, y);
    }
    return reach;
}

void draw_remap(const render::PassContext& ctx, const LensRemapProgram& p, const gl::Texture& source,
                const glm::vec4& rect_m, const render::LensDraw& draw, const frustum::NearPlaneFrame<float>& near,
                int width_px, int height_px) {
    const gl::Functions& fn = ctx.fn;
    p.use();
    fn.ActiveTexture(GL_TEXTURE0);
    fn.BindTexture(GL_TEXTURE_2D, source.id());
    p.set_source_texture_unit(0);
    p.set_source_rect_m(rect_m);
    p.set_frame_px(glm::vec2(static_cast<float>(width_px), static_cast<float>(height_px)));
    p.set_half_size_m(glm::vec2(near.half_width_m, near.half_height_m));
    p.set_lens(draw.lens);
    fn.DrawArrays(GL_TRIANGLES, 0, 3);
    fn.BindTexture(GL_TEXTURE_2D, 0);
}

} // namespace

frustum::Result<int> draw_lens_reference(const render::PassContext& ctx, const gl::OffscreenTarget& frame,
                                         const render::LensDraw& draw, int supersampling) {
    if (supersampling < 1 || supersampling > 8) {
        return frustum::Error{std::string(kWhere) + ": supersampling must be 1..8, got " +
                              std::to_string(supersampling)};
    }
    const auto near = frustum::near_plane_frame(draw.camera);
    if (!near) {
        return near.take_error_in(kWhere);
    }
    const int width_px = frame.width(), height_px = frame.height();
    const int texture_width_px = supersampling * width_px, texture_height_px = supersampling * height_px;
    // Level l spans 2^l near rectangles; its valid part ends half a texel inside.
    const float margin = 1.0f + 1.0f / static_cast<float>(std::min(texture_width_px, texture_height_px));
    const float reach = warped_reach(*near, draw.lens, width_px, height_px) * margin;
    const int levels = 1 + static_cast<int>(std::ceil(std::log2(reach) - 1e-6f));
    if (!(levels >= 1 && levels <= kMaxLensReferenceLevels)) {
        return frustum::Error{std::string(kWhere) + ": eq. 34 takes the frame to " + std::to_string(reach) +
                              " times its size, more than the " + std::to_string(kMaxLensReferenceLevels) +
                              " nested levels allow"};
    }
    auto program = LensRemapProgram::build(ctx.fn);
    if (!program) {
        return program.take_error_in(kWhere);
    }
    auto vertex_array = gl::VertexArray::create(ctx.fn); // the remap triangle has no attributes
    if (!vertex_array) {
        return vertex_array.take_error_in(kWhere);
    }
    frame.bind();
    render::begin_frame(ctx);
    for (int level = levels - 1; level >= 0; --level) { // widest first; narrower ones overwrite
        const float scale = std::ldexp(1.0f, level);
        const frustum::CropRect<float> camera_in_level{(scale - 1.0f) * width_px / 2.0f,
                                                       (scale - 1.0f) * height_px / 2.0f,
                                                       static_cast<float>(width_px),
                                                       static_cast<float>(height_px),
                                                       scale * width_px,
                                                       scale * height_px};
        auto pair = frustum::uncrop(draw.camera, camera_in_level);
        if (!pair) {
            return pair.take_error_in(kWhere);
        }
        auto source = gl::OffscreenTarget::create(
            ctx.fn, {texture_width_px, texture_height_px, gl::ColorStorage::Texture, gl::DepthFormat::Depth24});
        if (!source) {
            return source.take_error_in(kWhere);
        }
        render::begin_frame(ctx);
        render::SceneDraw scene{*pair};
        scene.skip_instance = draw.skip_instance;
        render::draw_scene(ctx, scene);

        frame.bind();
        ctx.fn.Disable(GL_DEPTH_TEST);
        ctx.fn.BindVertexArray(vertex_array->id());
        const glm::vec2 half_m = scale * glm::vec2(near->half_width_m, near->half_height_m);
        draw_remap(ctx, *program, source->color_texture(), glm::vec4(-half_m, half_m), draw, *near, width_px, height_px);
        ctx.fn.BindVertexArray(0);
        render::set_frame_state(ctx);
    }
    if (auto status = gl::check_error(ctx.fn, kWhere); !status) {
        return status.take_error();
    }
    return levels;
}

} // namespace reference
