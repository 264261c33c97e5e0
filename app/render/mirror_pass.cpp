#include "render/mirror_pass.hpp"

#include "render/face_state.hpp"
#include "render/scene_pass.hpp"

#include <gl/errors.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <optional>

namespace render {
namespace {

// The reflection: the scene without the mirror surface (it lies on the
// oblique near plane / the rectangle's near plane), winding flipped for a
// reflected pair.
frustum::Result<gl::OffscreenTarget> render_reflection(const PassContext& ctx, const ReflectionView& view,
                                                       int mirror_instance) {
    auto target = gl::OffscreenTarget::create(
        ctx.fn, {view.texture_width_px, view.texture_height_px, gl::ColorStorage::Texture, gl::DepthFormat::Depth24,
                 ctx.samples});
    if (!target) {
        return frustum::Error{"render::draw_mirror_frame(): reflection texture: " + target.error()};
    }
    begin_frame(ctx);
    SceneDraw draw{view.pair};
    draw.skip_instance = mirror_instance;
    draw_scene(ctx, draw);
    target->resolve();
    return target;
}

// The mirror surface: uv = (M_reflection world).xy / w * 0.5 + 0.5.
void draw_mirror_surface(const PassContext& ctx, const frustum::MatrixPair<float>& camera, int mirror_instance,
                         const gl::Texture& reflection, const ReflectionView& view, const glm::vec3& tint) {
    const gl::Functions& fn = ctx.fn;
    const MirrorCompositeProgram& p = ctx.programs.mirror_composite;
    const scene::Instance& instance = ctx.scene.instances()[static_cast<std::size_t>(mirror_instance)];
    fn.UseProgram(p.program.id());
    fn.UniformMatrix4fv(p.view_projection, 1, GL_FALSE, glm::value_ptr(ctx.depth.to_gpu(camera).matrix()));
    fn.UniformMatrix4fv(p.model, 1, GL_FALSE, glm::value_ptr(instance.world));
    // Rows 0, 1 and 3 (x, y, w) do not depend on the depth range: no conversion.
    fn.UniformMatrix4fv(p.reflection_matrix, 1, GL_FALSE, glm::value_ptr(view.pair.matrix()));
    fn.Uniform3f(p.tint, tint.r, tint.g, tint.b);
    fn.ActiveTexture(GL_TEXTURE0);
    fn.BindTexture(GL_TEXTURE_2D, reflection.id());
    fn.Uniform1i(p.reflection, 0);
    const bool model_flips = glm::determinant(glm::mat3(instance.world)) < 0.0f;
    for (const GpuPrimitive& primitive : ctx.scene.meshes()[static_cast<std::size_t>(instance.mesh)]) {
        set_face_state(fn, ctx.scene.material(primitive.material).double_sided, camera.flips_winding(), model_flips);
        draw_primitive(fn, primitive);
    }
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    restore_face_state(fn);
}

} // namespace

frustum::Status draw_mirror_frame(const PassContext& ctx, const gl::OffscreenTarget& frame, const MirrorDraw& draw) {
    auto plan = plan_reflection(draw.mirror, draw.camera, frame.width(), frame.height(), draw.method, draw.bounds);
    if (!plan) {
        return plan.take_error();
    }
    const int surface = draw.mirror.instance;
    if (!plan->has_value() || surface < 0) {
        frame.bind();
        begin_frame(ctx);
        draw_scene(ctx, SceneDraw{draw.camera});
        return {};
    }
    const ReflectionView& view = **plan;
    auto reflection = render_reflection(ctx, view, surface);
    if (!reflection) {
        return reflection.take_error();
    }
    frame.bind();
    begin_frame(ctx);
    SceneDraw main{draw.camera};
    main.skip_instance = surface;
    draw_scene(ctx, main);
    draw_mirror_surface(ctx, draw.camera, surface, reflection->color_texture(), view, draw.tint);
    return gl::check_error(ctx.fn, "render::draw_mirror_frame()");
}

} // namespace render
