#include "render/scene_pass.hpp"

#include "render/alpha_order.hpp"
#include "render/face_state.hpp"

#include <frustum/culling.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <vector>

namespace render {
namespace {

constexpr float kPointSizePx = 3.0f;
constexpr GLenum kProgramPointSize = 0x8642; // GL_PROGRAM_POINT_SIZE, desktop GL only

// The cofactor matrix [b x c, c x a, a x b] of A = [a b c] is det(A) A^-T:
// the inverse transpose up to a factor. Multiplied by sign(det) it points
// normals the right way even for a mirroring transform, and it stays finite
// for a singular one (the shader normalizes).
glm::mat3 normal_matrix(const glm::mat4& model) {
    const glm::mat3 a(model);
    const glm::mat3 cofactor(glm::cross(a[1], a[2]), glm::cross(a[2], a[0]), glm::cross(a[0], a[1]));
    return glm::determinant(a) < 0.0f ? -cofactor : cofactor;
}

Shading shading_for(const GpuPrimitive& primitive, const GpuMaterial& material) {
    if (material.unlit) {
        return Shading::Unlit;
    }
    if (primitive.has_normals) {
        return Shading::VertexNormals;
    }
    const bool triangles = primitive.mode == GL_TRIANGLES || primitive.mode == GL_TRIANGLE_STRIP ||
                           primitive.mode == GL_TRIANGLE_FAN;
    return triangles ? Shading::FlatNormals : Shading::Unlit;
}

// The frame uniforms of one scene program variant.
void use_program(const PassContext& ctx, const SceneProgram& p, const SceneDraw& draw) {
    p.use();
    p.set_view_projection(ctx.depth.to_gpu(draw.camera).matrix());
    p.set_point_size_px(kPointSizePx);
    // A mirrored view turns cross(dFdx, dFdy) away from the viewer.
    p.set_flat_normal_sign(draw.camera.flips_winding() ? -1.0f : 1.0f);
    p.set_light(glm::mat3(draw.pre_model) * ctx.lighting.to_light, ctx.lighting.ambient, ctx.lighting.diffuse);
    if (draw.clip_plane) {
        p.set_clip_plane(draw.clip_plane->abcd);
    }
    p.set_base_color_texture_unit(0);
}

// One primitive of one instance, and where it goes in the draw order.
struct DrawItem {
    std::size_t instance = 0;
    const GpuPrimitive* primitive = nullptr;
    AlphaGroup group = AlphaGroup::Opaque;
    float depth = 0.0f; // view_depth() of its centre: BLEND only
};

// The world box around the primitive's object-space box placed by `model`.
frustum::Aabb<float> world_box(const glm::mat4& model, const GpuPrimitive& primitive) {
    frustum::Aabb<float> box;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 local((corner & 1) ? primitive.high.x : primitive.low.x,
                              (corner & 2) ? primitive.high.y : primitive.low.y,
                              (corner & 4) ? primitive.high.z : primitive.low.z);
        const glm::vec3 world(model * glm::vec4(local, 1.0f));
        box.min = corner == 0 ? world : glm::min(box.min, world);
        box.max = corner == 0 ? world : glm::max(box.max, world);
    }
    return box;
}

} // namespace

void set_frame_state(const PassContext& ctx) {
    const gl::Functions& fn = ctx.fn;
    fn.Disable(GL_SCISSOR_TEST);
    fn.Disable(GL_BLEND);
    fn.Enable(GL_DEPTH_TEST);
    fn.DepthFunc(GL_LESS);
    fn.DepthMask(GL_TRUE);
    fn.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (ctx.api == gl::Api::GlCore) {
        fn.Enable(kProgramPointSize);
    }
}

void clear_frame(const PassContext& ctx) {
    const gl::Functions& fn = ctx.fn;
    fn.ClearColor(ctx.clear_color.r, ctx.clear_color.g, ctx.clear_color.b, ctx.clear_color.a);
    fn.ClearDepthf(1.0f);
    fn.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

void begin_frame(const PassContext& ctx) {
    set_frame_state(ctx);
    clear_frame(ctx);
}

void draw_scene(const PassContext& ctx, const SceneDraw& draw) {
    const gl::Functions& fn = ctx.fn;
    const bool view_flips = draw.camera.flips_winding();
    const auto& instances = ctx.scene.instances();
    const auto model_of = [&](std::size_t i) { return draw.pre_model * instances[i].world; };

    // Without a culling frustum of its own (a mirror or portal view's), a
    // draw culls by its camera's (raw planes: only signs are used), so that
    // a poster's tile or a lens tile skips what its crop does not see.
    std::optional<frustum::FrustumPlanes<float>> own_cull;
    if (!draw.cull) {
        own_cull = frustum::raw_planes(draw.camera);
    }
    const frustum::FrustumPlanes<float>& cull = draw.cull ? *draw.cull : *own_cull;

    std::vector<DrawItem> items;
    for (std::size_t i = 0; i < instances.size(); ++i) {
        if (static_cast<int>(i) == draw.skip_instance ||
            std::find(draw.skip_more.begin(), draw.skip_more.end(), static_cast<int>(i)) != draw.skip_more.end()) {
            continue;
        }
        for (const GpuPrimitive& primitive : ctx.scene.meshes()[static_cast<std::size_t>(instances[i].mesh)]) {
            if (frustum::classify(cull, world_box(model_of(i), primitive)) == frustum::Containment::Outside) {
                if (draw.counts) {
                    ++draw.counts->culled;
                }
                continue;
            }
            if (draw.counts) {
                ++draw.counts->drawn;
            }
            DrawItem item{i, &primitive, alpha_group(ctx.scene.material(primitive.material).alpha_mode)};
            if (item.group == AlphaGroup::Blend) {
                item.depth = view_depth(draw.camera, glm::vec3(model_of(i) * glm::vec4(primitive.center, 1.0f)));
            }
            items.push_back(item);
        }
    }
    // Opaque, then masked, then blended from the farthest to the nearest.
    std::stable_sort(items.begin(), items.end(), [](const DrawItem& a, const DrawItem& b) {
        if (a.group != b.group) {
            return a.group < b.group;
        }
        return a.group == AlphaGroup::Blend && a.depth > b.depth;
    });

    fn.ActiveTexture(GL_TEXTURE0);
    const SceneProgram* current = nullptr;
    bool blending = false;
    for (const DrawItem& item : items) {
        const SceneProgram& p = ctx.programs.scene_program(draw.clip_plane.has_value(), item.group == AlphaGroup::Mask);
        if (&p != current) {
            use_program(ctx, p, draw);
            current = &p;
        }
        if (item.group == AlphaGroup::Blend && !blending) {
            begin_blending(fn);
            blending = true;
        }
        const glm::mat4 model = model_of(item.instance);
        const bool model_flips = glm::determinant(glm::mat3(model)) < 0.0f;
        p.set_model(model);
        p.set_normal_matrix(normal_matrix(model));
        const GpuMaterial& material = ctx.scene.material(item.primitive->material);
        p.set_material(material, ctx.scene.textures());
        p.set_shading(shading_for(*item.primitive, material));
        set_face_state(fn, material.double_sided, view_flips, model_flips);
        draw_primitive(fn, *item.primitive);
    }
    if (blending) {
        end_blending(fn);
    }
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    restore_face_state(fn);
}

} // namespace render
