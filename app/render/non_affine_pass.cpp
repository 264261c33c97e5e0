#include "render/non_affine_pass.hpp"

#include "render/alpha_order.hpp"
#include "render/face_state.hpp"
#include "render/scene_pass.hpp"

#include <frustum/lens.hpp>
#include <frustum/queries.hpp>
#include <gl/errors.hpp>
#include <gl/objects.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <memory>
#include <optional>
#include <cstddef>
#include <string>
#include <vector>

namespace render {
namespace {

constexpr const char* kDraw = "render::draw_non_affine_frame()";

void set_material(const PassContext& ctx, const NonAffineProgram& p, const plan::WorldPrimitive& primitive) {
    const gl::Functions& fn = ctx.fn;
    const GpuMaterial& material = ctx.scene.material(primitive.material);
    p.set_material(material, ctx.scene.textures());
    p.set_shading(material.unlit           ? Shading::Unlit
                  : primitive.has_normals ? Shading::VertexNormals
                                          : Shading::FlatNormals);
    set_face_state(fn, material.double_sided, false, false);
}

void set_frame_uniforms(const PassContext& ctx, const NonAffineProgram& p,
                        const frustum::NonAffineFrustum<float>& frustum, const FrameWindow& window) {
    const gl::Functions& fn = ctx.fn;
    glm::vec4 planes[6];
    for (int i = 0; i < 6; ++i) {
        planes[i] = frustum.plane(i).abcd;
    }
    p.set_planes(planes);
    p.set_crop(window_ndc_scale_offset(window));
    p.set_clip_z(frustum::clip_z_near<float>(ctx.depth.gpu_range()), frustum::clip_z_far<float>(ctx.depth.gpu_range()));
    p.set_flat_normal_sign(1.0f);
    p.set_light(ctx.lighting.to_light, ctx.lighting.ambient, ctx.lighting.diffuse);
    fn.ActiveTexture(GL_TEXTURE0);
    p.set_base_color_texture_unit(0);
}

void set_vertex_layout(const gl::Functions& fn) {
    const auto stride = static_cast<GLsizei>(sizeof(plan::WorldVertex));
    const auto attribute = [&](GLuint location, GLint size, std::size_t offset) {
        fn.EnableVertexAttribArray(location);
        fn.VertexAttribPointer(location, size, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offset));
    };
    attribute(kPositionLocation, 3, offsetof(plan::WorldVertex, position));
    attribute(kNormalLocation, 3, offsetof(plan::WorldVertex, normal));
    attribute(kColorLocation, 4, offsetof(plan::WorldVertex, color));
    attribute(kTexcoordLocation, 2, offsetof(plan::WorldVertex, texcoord));
}

} // namespace


bool is_degenerate(const frustum::NonAffineFrustum<float>& frustum, const glm::vec3& p, float guard_m) {
    const glm::vec3 d = frustum.denominators(p);
    return !(d.x < -guard_m && d.y < -guard_m && d.z < -guard_m);
}

NonAffineBatch batch_non_affine(const plan::SplitGeometry& geometry, const frustum::NonAffineFrustum<float>& frustum,
                                const plan::NonAffineOptions& options) {
    NonAffineBatch batch;
    // One flag per gathered vertex (bytes: no bit packing in the hot loop).
    std::vector<unsigned char> degenerate(geometry.vertices.size(), 0);
    if (options.cull) {
        for (std::size_t v = 0; v < geometry.vertices.size(); ++v) {
            degenerate[v] = is_degenerate(frustum, geometry.vertices[v].position, options.guard_m) ? 1 : 0;
        }
    }
    for (std::size_t i = 0; i < geometry.split.primitives.size(); ++i) {
        const plan::WorldPrimitive& p = geometry.split.primitives[i];
        const std::uint32_t base = geometry.bases[i];
        const unsigned char* bad = degenerate.data() + base;
        NonAffineBatch::Range range{static_cast<std::uint32_t>(batch.indices.size()), 0, i};
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            ++batch.stats.triangles;
            if (bad[p.indices[t]] | bad[p.indices[t + 1]] | bad[p.indices[t + 2]]) {
                ++batch.stats.culled;
                continue;
            }
            batch.indices.insert(batch.indices.end(),
                                 {base + p.indices[t], base + p.indices[t + 1], base + p.indices[t + 2]});
        }
        range.count = static_cast<std::uint32_t>(batch.indices.size()) - range.first;
        if (range.count > 0) {
            batch.ranges.push_back(range);
        }
    }
    return batch;
}

frustum::Result<NonAffineStats> draw_non_affine_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                                      const plan::WorldGeometry& geometry,
                                                      const frustum::NonAffineFrustum<float>& frustum,
                                                      const plan::NonAffineOptions& options) {
    return draw_non_affine_frame(ctx, frame, plan::SplitGeometry::build(geometry, options.max_edge_m), frustum,
                                 options);
}

frustum::Result<NonAffineUpload> upload_non_affine(const PassContext& ctx, const plan::SplitGeometry& geometry,
                                                  const frustum::NonAffineFrustum<float>& frustum,
                                                  const plan::NonAffineOptions& options) {
    const NonAffineBatch batch = batch_non_affine(geometry, frustum, options);
    const gl::Functions& fn = ctx.fn;
    auto vertex_array = gl::VertexArray::create(fn);
    auto vertex_buffer = gl::Buffer::create(fn);
    auto index_buffer = gl::Buffer::create(fn);
    if (!vertex_array || !vertex_buffer || !index_buffer) {
        return frustum::Error{std::string(kDraw) + ": " + vertex_array.error() + vertex_buffer.error() +
                              index_buffer.error()};
    }
    NonAffineUpload upload{std::move(*vertex_array), std::move(*vertex_buffer), std::move(*index_buffer), {},
                           batch.stats};
    for (const NonAffineBatch::Range& kept : batch.ranges) {
        const plan::WorldPrimitive& p = geometry.split.primitives[kept.primitive];
        NonAffineUpload::Range range{static_cast<GLsizei>(kept.first), static_cast<GLsizei>(kept.count), &p};
        range.group = alpha_group(ctx.scene.material(p.material).alpha_mode);
        const std::size_t first = geometry.bases[kept.primitive], end = geometry.end_of(kept.primitive);
        if (range.group == AlphaGroup::Blend && first < end) {
            glm::vec3 low = geometry.vertices[first].position, high = low;
            for (std::size_t v = first; v < end; ++v) {
                low = glm::min(low, geometry.vertices[v].position);
                high = glm::max(high, geometry.vertices[v].position);
            }
            // The near plane is outward (plane 4): its distance is negative inside.
            range.depth_m = -frustum.plane(4).distance(0.5f * (low + high));
        }
        upload.ranges.push_back(range);
    }
    // Opaque, masked, then blended from the farthest to the nearest (alpha_order.hpp).
    std::stable_sort(upload.ranges.begin(), upload.ranges.end(),
                     [](const NonAffineUpload::Range& a, const NonAffineUpload::Range& b) {
                         return a.group != b.group ? a.group < b.group
                                                   : a.group == AlphaGroup::Blend && a.depth_m > b.depth_m;
                     });

    fn.BindVertexArray(upload.vertex_array.id());
    fn.BindBuffer(GL_ARRAY_BUFFER, upload.vertex_buffer.id());
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(geometry.vertices.size() * sizeof(plan::WorldVertex)),
                  geometry.vertices.data(), GL_STREAM_DRAW);
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, upload.index_buffer.id());
    static_assert(sizeof(GLuint) == sizeof(std::uint32_t));
    fn.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(batch.indices.size() * sizeof(GLuint)),
                  batch.indices.data(), GL_STREAM_DRAW);
    set_vertex_layout(fn);
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    if (auto status = gl::check_error(fn, kDraw); !status) {
        return status.take_error();
    }
    return upload;
}

frustum::Result<NonAffineStats> draw_non_affine_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                                      const plan::SplitGeometry& geometry,
                                                      const frustum::NonAffineFrustum<float>& frustum,
                                                      const plan::NonAffineOptions& options) {
    // A poster's tiles draw the frame's one upload (the cull and the
    // buffers are the whole frame's: the window only crops in the shader).
    std::optional<NonAffineUpload> own;
    const NonAffineUpload* upload = ctx.frame_cache ? ctx.frame_cache->non_affine.get() : nullptr;
    if (!upload) {
        auto made = upload_non_affine(ctx, geometry, frustum, options);
        if (!made) {
            return made.take_error();
        }
        if (ctx.frame_cache) {
            ctx.frame_cache->non_affine = std::make_unique<NonAffineUpload>(std::move(*made));
            upload = ctx.frame_cache->non_affine.get();
        } else {
            own = std::move(*made);
            upload = &*own;
        }
    }

    const gl::Functions& fn = ctx.fn;
    frame.bind();
    begin_frame(ctx);
    fn.BindVertexArray(upload->vertex_array.id());
    const NonAffineProgram* current = nullptr;
    bool blending = false;
    for (const NonAffineUpload::Range& range : upload->ranges) {
        const NonAffineProgram& p = ctx.programs.non_affine_program(range.group == AlphaGroup::Mask);
        if (&p != current) {
            p.use();
            set_frame_uniforms(ctx, p, frustum, window_of(ctx, frame.width(), frame.height()));
            current = &p;
        }
        if (range.group == AlphaGroup::Blend && !blending) {
            begin_blending(fn);
            blending = true;
        }
        set_material(ctx, p, *range.primitive);
        fn.DrawElements(GL_TRIANGLES, range.count, GL_UNSIGNED_INT,
                        reinterpret_cast<const void*>(static_cast<std::size_t>(range.first) * sizeof(GLuint)));
    }
    if (blending) {
        end_blending(fn);
    }
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    restore_face_state(fn);
    if (auto status = gl::check_error(fn, kDraw); !status) {
        return status.take_error();
    }
    return upload->stats;
}

} // namespace render
