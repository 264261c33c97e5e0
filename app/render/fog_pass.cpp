#include "render/fog_pass.hpp"

#include "render/embedded_shaders.hpp"
#include "render/program_support.hpp"
#include "render/scene_pass.hpp"

#include <frustum/queries.hpp>
#include <gl/errors.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace render {
namespace {

constexpr const char* kApply = "render::FogPass::apply()";

// A single-sample GL_DEPTH_COMPONENT24 texture the size of `target`, in a
// framebuffer of its own, holding a copy (the resolve, when multisampled)
// of the target's depth.
struct DepthCopy {
    gl::Texture texture;
    gl::Framebuffer framebuffer;
};

frustum::Result<DepthCopy> copy_depth(const gl::Functions& fn, const gl::OffscreenTarget& target) {
    auto texture = gl::Texture::create(fn);
    auto framebuffer = gl::Framebuffer::create(fn);
    if (!texture || !framebuffer) {
        return frustum::Error{std::string(kApply) + ": " + (!texture ? texture.error() : framebuffer.error())};
    }
    fn.BindTexture(GL_TEXTURE_2D, texture->id());
    fn.TexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT24, target.width(), target.height());
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    fn.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    fn.BindFramebuffer(GL_FRAMEBUFFER, framebuffer->id());
    fn.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, texture->id(), 0);
    const GLenum status = fn.CheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(status));
        return frustum::Error{std::string(kApply) + ": the depth copy's framebuffer is incomplete (status " + hex +
                              ")"};
    }
    fn.BindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer().id());
    fn.BindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer->id());
    fn.BlitFramebuffer(0, 0, target.width(), target.height(), 0, 0, target.width(), target.height(),
                       GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    return DepthCopy{std::move(*texture), std::move(*framebuffer)};
}

} // namespace

FogParams fit_fog(const plan::FogOptions& options, const scene::Bounds& bounds, const glm::vec4& clear_color) {
    const float diagonal_m = glm::length(bounds.max - bounds.min);
    FogParams fog;
    fog.color = options.color.value_or(glm::vec3(clear_color));
    fog.density_per_m = options.density_per_m.value_or(std::log(2.0f) / (diagonal_m > 0.0f ? diagonal_m : 1.0f));
    fog.start_m = options.start_m;
    return fog;
}

frustum::Result<FogProgram> FogProgram::build(const gl::Functions& fn) {
    FogProgram program;
    // Fragment shaders have no default float precision: set it before the snippet.
    Source source{"fog", std::string(shaders::lens_remap_vert),
                  detail::insert_after_version(shaders::fog_frag, "precision highp float;\n" +
                                                                      std::string(shaders::frustum_glsl))};
    if (frustum::Status linked = program.link(fn, source,
                                              {{"u_depth", &program.depth_},
                                               {"u_inverse", &program.inverse_},
                                               {"u_z_range", &program.z_range_},
                                               {"u_frame_px", &program.frame_px_},
                                               {"u_eye", &program.eye_},
                                               {"u_fog_color", &program.fog_color_},
                                               {"u_density_per_m", &program.density_per_m_},
                                               {"u_start_m", &program.start_m_}});
        !linked) {
        return frustum::Error{linked.error()};
    }
    return program;
}

void FogProgram::set_depth_texture_unit(int unit) const { set(depth_, unit); }
void FogProgram::set_decode(const glm::mat4& inverse, const glm::vec2& z_range, const glm::vec2& frame_px) const {
    set(inverse_, inverse);
    set(z_range_, z_range);
    set(frame_px_, frame_px);
}
void FogProgram::set_eye(const glm::vec3& eye_m) const { set(eye_, eye_m); }
void FogProgram::set_fog(const glm::vec3& color, float density_per_m, float start_m) const {
    set(fog_color_, color);
    set(density_per_m_, density_per_m);
    set(start_m_, start_m);
}

frustum::Result<FogPass> FogPass::build(const gl::Functions& fn) {
    auto program = FogProgram::build(fn);
    if (!program) {
        return frustum::Error{program.error()};
    }
    auto vertex_array = gl::VertexArray::create(fn);
    if (!vertex_array) {
        return vertex_array.take_error_in("render::FogPass::build()");
    }
    FogPass pass;
    pass.program_ = std::move(*program);
    pass.vertex_array_ = std::move(*vertex_array);
    return pass;
}

frustum::Status FogPass::apply(const PassContext& ctx, const gl::OffscreenTarget& target,
                               const frustum::MatrixPair<float>& pair, const FogParams& fog) const {
    const gl::Functions& fn = ctx.fn;
    auto depth = copy_depth(fn, target);
    if (!depth) {
        return frustum::Error{depth.error()};
    }
    const frustum::MatrixPair<float> gpu = ctx.depth.to_gpu(pair);
    const glm::vec4 eye = frustum::key_points(gpu).eye;
    if (!(eye.w != 0.0f)) {
        return frustum::Error{std::string(kApply) + ": distance fog needs a perspective pair (finite eye)"};
    }
    const glm::vec3 eye_m = glm::vec3(eye) / eye.w;

    target.bind();
    fn.Disable(GL_DEPTH_TEST);
    fn.DepthMask(GL_FALSE);
    fn.Enable(GL_BLEND);
    fn.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE); // keep the frame's alpha
    program_.use();
    fn.ActiveTexture(GL_TEXTURE0);
    fn.BindTexture(GL_TEXTURE_2D, depth->texture.id());
    program_.set_depth_texture_unit(0);
    program_.set_decode(gpu.inverse(),
                        {frustum::clip_z_near<float>(gpu.depth()), frustum::clip_z_far<float>(gpu.depth())},
                        {static_cast<float>(target.width()), static_cast<float>(target.height())});
    program_.set_eye(eye_m);
    program_.set_fog(fog.color, fog.density_per_m, fog.start_m);
    fn.BindVertexArray(vertex_array_.id());
    fn.DrawArrays(GL_TRIANGLES, 0, 3);
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    set_frame_state(ctx);
    return gl::check_error(fn, kApply);
}

} // namespace render
