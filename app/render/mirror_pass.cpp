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
frustum::Result<gl::OffscreenTarget> render_reflection(const PassContext& ctx, const plan::ReflectionView& view,
                                                       int mirror_instance) {
    auto target = gl::OffscreenTarget::create(
        ctx.fn, {view.texture_width_px, view.texture_height_px, gl::ColorStorage::Texture, gl::DepthFormat::Depth24,
                 ctx.samples});
    if (!target) {
        return target.take_error_in("render::draw_mirror_frame(): reflection texture");
    }
    begin_frame(ctx);
    SceneDraw draw{view.pair};
    draw.skip_instance = mirror_instance;
    draw_scene(ctx, draw);
    return target;
}

// The part of the reflection texture a window needs: Oblique and
// ReflectOnly textures cover the mirror's screen rectangle pixel for pixel,
// so the window's share is the rectangle intersected with the window
// (empty optional: all of it, the Rectangle method's texture spans the
// mirror, not the screen, or the window is the whole frame).
std::optional<plan::PixelRect> texture_part(const plan::ReflectionView& view, plan::MirrorMethod method,
                                            const FrameWindow& window) {
    if (method == plan::MirrorMethod::Rectangle) {
        return std::nullopt;
    }
    const auto part = intersect(view.screen_rect, window.rect);
    if (!part || (part->width == view.screen_rect.width && part->height == view.screen_rect.height)) {
        return std::nullopt;
    }
    return part;
}

// The reflection's fog: its depth decoded with the pair that wrote it, or
// (the counter-example) with the reflected pair before the oblique near
// plane, cropped alike.
frustum::Status fog_reflection(const PassContext& ctx, const gl::OffscreenTarget& target,
                               const plan::ReflectionView& view, const FrameWindow& window, const MirrorDraw& draw,
                               const FogDraw& fog) {
    frustum::MatrixPair<float> decode = view.pair;
    if (fog.decode_reflection_unclipped) {
        auto unclipped = plan::plan_reflection(draw.mirror, draw.camera, window.full_width_px, window.full_height_px,
                                               plan::MirrorMethod::ReflectOnly, draw.bounds);
        if (!unclipped) {
            return frustum::Error{unclipped.error()};
        }
        if (!unclipped->has_value()) {
            return frustum::Error{"render::draw_mirror_frame(): no unclipped reflection to decode the fog with"};
        }
        decode = (*unclipped)->pair;
        if (const auto part = texture_part(**unclipped, draw.method, window)) {
            auto cropped = crop_part(decode, (*unclipped)->screen_rect, *part);
            if (!cropped) {
                return cropped.take_error_in("render::draw_mirror_frame()");
            }
            decode = *cropped;
        }
    }
    return fog.pass->apply(ctx, target, decode, fog.params);
}

} // namespace

void draw_reflection_surface(const PassContext& ctx, const frustum::MatrixPair<float>& camera, int mirror_instance,
                             const gl::Texture& reflection, const glm::mat4& texture_matrix, const glm::vec3& tint) {
    const gl::Functions& fn = ctx.fn;
    const MirrorCompositeProgram& p = ctx.programs.mirror_composite;
    const scene::Instance& instance = ctx.scene.instances()[static_cast<std::size_t>(mirror_instance)];
    p.use();
    p.set_view_projection(ctx.depth.to_gpu(camera).matrix());
    p.set_model(instance.world);
    // Rows 0, 1 and 3 (x, y, w) do not depend on the depth range: no conversion.
    p.set_reflection_matrix(texture_matrix);
    p.set_tint(tint);
    fn.ActiveTexture(GL_TEXTURE0);
    fn.BindTexture(GL_TEXTURE_2D, reflection.id());
    p.set_reflection_texture_unit(0);
    const bool model_flips = glm::determinant(glm::mat3(instance.world)) < 0.0f;
    for (const GpuPrimitive& primitive : ctx.scene.meshes()[static_cast<std::size_t>(instance.mesh)]) {
        set_face_state(fn, ctx.scene.material(primitive.material).double_sided, camera.flips_winding(), model_flips);
        draw_primitive(fn, primitive);
    }
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    restore_face_state(fn);
}

frustum::Status draw_mirror_frame(const PassContext& ctx, const gl::OffscreenTarget& frame, const MirrorDraw& draw) {
    // Planned for the whole frame; the target draws its window's crop.
    const FrameWindow window = window_of(ctx, frame.width(), frame.height());
    auto plan = plan::plan_reflection(draw.mirror, draw.camera, window.full_width_px, window.full_height_px,
                                      draw.method, draw.bounds);
    if (!plan) {
        return plan.take_error();
    }
    auto on_frame = crop_to_window(draw.camera, window);
    if (!on_frame) {
        return on_frame.take_error_in("render::draw_mirror_frame()");
    }
    const int surface = draw.mirror.instance;
    // The screen-aligned texture covers the rectangle: a window that misses
    // it shows no mirror pixel (the rectangle bounds the surface's).
    const bool misses = plan->has_value() && draw.method != plan::MirrorMethod::Rectangle &&
                        !intersect((*plan)->screen_rect, window.rect);
    if (!plan->has_value() || surface < 0 || misses) {
        frame.bind();
        begin_frame(ctx);
        SceneDraw plain{*on_frame};
        plain.skip_instance = misses ? surface : -1;
        draw_scene(ctx, plain);
        return draw.fog ? draw.fog->pass->apply(ctx, frame, *on_frame, draw.fog->params) : frustum::Status{};
    }
    plan::ReflectionView view = **plan;
    if (const auto part = texture_part(view, draw.method, window)) {
        auto cropped = crop_part(view.pair, view.screen_rect, *part);
        if (!cropped) {
            return cropped.take_error_in("render::draw_mirror_frame()");
        }
        view = plan::ReflectionView{*cropped, part->width, part->height, *part};
    }
    // The rectangle method's texture spans the mirror, not the window: the
    // same for every tile of a poster, drawn once and kept resolved
    // (frame_cache.hpp). The screen-aligned ones are each tile's own crop.
    const bool shared = draw.method == plan::MirrorMethod::Rectangle && ctx.frame_cache;
    std::optional<gl::OffscreenTarget> own;
    std::optional<gl::OffscreenTarget>& slot = shared ? ctx.frame_cache->mirror_reflection : own;
    if (!slot) {
        auto drawn = render_reflection(ctx, view, surface);
        if (!drawn) {
            return drawn.take_error();
        }
        if (draw.fog) {
            if (auto status = fog_reflection(ctx, *drawn, view, window, draw, *draw.fog); !status) {
                return status;
            }
        }
        if (shared) {
            drawn->keep_resolved_only(); // resolves; only sampled from now on
        } else {
            drawn->resolve();
        }
        if (ctx.pass_end) {
            ctx.pass_end("reflection");
        }
        slot = std::move(*drawn);
    }
    const gl::OffscreenTarget* reflection = &*slot;
    frame.bind();
    begin_frame(ctx);
    SceneDraw main{*on_frame};
    main.skip_instance = surface;
    draw_scene(ctx, main);
    if (draw.fog) { // before the surface: its colour, the reflection, is fogged already
        if (auto status = draw.fog->pass->apply(ctx, frame, *on_frame, draw.fog->params); !status) {
            return status;
        }
    }
    draw_reflection_surface(ctx, *on_frame, surface, reflection->color_texture(), view.pair.matrix(), draw.tint);
    return gl::check_error(ctx.fn, "render::draw_mirror_frame()");
}

} // namespace render
