#include "render/curved_pass.hpp"

#include "render/face_state.hpp"
#include "render/scene_pass.hpp"

#include <frustum/depth_range.hpp>
#include <frustum/queries.hpp>
#include <gl/errors.hpp>
#include <gl/objects.hpp>

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace render {
namespace {

constexpr const char* kDraw = "render::draw_curved_mirror_frame(): ";
constexpr int kMaxAtlasSidePx = 4096; // see mirror_geometry.cpp
constexpr int kMinTilePx = 4;
constexpr int kMinCapQuads = 32; // the cap mesh has at least this many quads per side

// The cap as one indexed triangle mesh, M x M quads (M = G * quads per
// patch), its indices grouped by patch: patch (i, j) draws
// `indices_per_patch` indices from (j G + i) indices_per_patch.
struct CapMesh {
    gl::VertexArray vertex_array;
    gl::Buffer vertex_buffer, index_buffer;
    GLsizei indices_per_patch = 0;
};

frustum::Result<CapMesh> upload_cap(const gl::Functions& fn, const plan::CurvedMirror& mirror, int grid) {
    const int per_patch = (kMinCapQuads + grid - 1) / grid;
    const int m = grid * per_patch;
    std::vector<float> positions;
    positions.reserve(static_cast<std::size_t>((m + 1) * (m + 1) * 3));
    for (int y = 0; y <= m; ++y) {
        for (int x = 0; x <= m; ++x) {
            const glm::dvec3 p = mirror.at(static_cast<double>(x) / m, static_cast<double>(y) / m).position;
            positions.insert(positions.end(), {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)});
        }
    }
    // Counter-clockwise seen from the reflecting side (a1 right, a2 up).
    std::vector<std::uint32_t> indices;
    indices.reserve(static_cast<std::size_t>(m * m * 6));
    const auto vertex = [m](int x, int y) { return static_cast<std::uint32_t>(y * (m + 1) + x); };
    for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
            for (int y = j * per_patch; y < (j + 1) * per_patch; ++y) {
                for (int x = i * per_patch; x < (i + 1) * per_patch; ++x) {
                    indices.insert(indices.end(), {vertex(x, y), vertex(x + 1, y), vertex(x + 1, y + 1),
                                                   vertex(x, y), vertex(x + 1, y + 1), vertex(x, y + 1)});
                }
            }
        }
    }
    CapMesh mesh;
    auto vertex_array = gl::VertexArray::create(fn);
    auto vertex_buffer = gl::Buffer::create(fn);
    auto index_buffer = gl::Buffer::create(fn);
    if (!vertex_array || !vertex_buffer || !index_buffer) {
        return frustum::Error{kDraw + (!vertex_array ? vertex_array.error()
                                       : !vertex_buffer ? vertex_buffer.error()
                                                        : index_buffer.error())};
    }
    mesh.vertex_array = std::move(*vertex_array);
    mesh.vertex_buffer = std::move(*vertex_buffer);
    mesh.index_buffer = std::move(*index_buffer);
    mesh.indices_per_patch = static_cast<GLsizei>(per_patch * per_patch * 6);
    fn.BindVertexArray(mesh.vertex_array.id());
    fn.BindBuffer(GL_ARRAY_BUFFER, mesh.vertex_buffer.id());
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(positions.size() * sizeof(float)), positions.data(),
                  GL_STATIC_DRAW);
    fn.EnableVertexAttribArray(kPositionLocation);
    fn.VertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.index_buffer.id());
    fn.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                  indices.data(), GL_STATIC_DRAW);
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    return mesh;
}

// Renders every patch's view into its tile: tile (i, j) is the rectangle
// (i w, j h, w, h) of the atlas, from the bottom-left. The atlas is single-
// sampled colour only; each patch is drawn into one tile-sized target
// sampled like the frame, resolved there and copied into its tile (a
// resolve blit keeps its rectangle; the copy moves it). So the atlas's
// multisampled colour and depth (4x MSAA at 4096 x 4096: 512 MiB) are never
// alive at once, only one tile's; the pixels are the same.
frustum::Result<gl::OffscreenTarget> render_atlas(const PassContext& ctx, const plan::CurvedPlan& plan,
                                                  const glm::ivec2& tile, int mirror_instance) {
    auto atlas = gl::OffscreenTarget::create(
        ctx.fn, {plan.grid * tile.x, plan.grid * tile.y, gl::ColorStorage::Texture, gl::DepthFormat::None, 1});
    auto scratch = gl::OffscreenTarget::create(
        ctx.fn, {tile.x, tile.y, gl::ColorStorage::Renderbuffer, gl::DepthFormat::Depth24, ctx.samples});
    if (!atlas || !scratch) {
        return frustum::Error{kDraw + std::string("atlas: ") + (!atlas ? atlas.error() : scratch.error())};
    }
    const gl::Functions& fn = ctx.fn;
    for (const plan::PatchFrustum& patch : plan.patches) {
        scratch->bind();
        set_frame_state(ctx);
        clear_frame(ctx);
        if (patch.pair) {
            SceneDraw draw(*patch.pair);
            draw.skip_instance = mirror_instance;
            draw_scene(ctx, draw);
        }
        scratch->resolve();
        fn.BindFramebuffer(GL_READ_FRAMEBUFFER, scratch->resolved_framebuffer().id());
        fn.ReadBuffer(GL_COLOR_ATTACHMENT0);
        fn.BindFramebuffer(GL_DRAW_FRAMEBUFFER, atlas->framebuffer().id());
        fn.BlitFramebuffer(0, 0, tile.x, tile.y, patch.i * tile.x, patch.j * tile.y, (patch.i + 1) * tile.x,
                           (patch.j + 1) * tile.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    fn.BindFramebuffer(GL_FRAMEBUFFER, 0);
    return atlas;
}

// on_frame: the camera cropped to the target's window.
void draw_cap(const PassContext& ctx, const CurvedDraw& draw, const frustum::MatrixPair<float>& on_frame,
              const plan::CurvedPlan& plan, const CapMesh& mesh, const gl::OffscreenTarget& atlas,
              const glm::ivec2& tile) {
    const gl::Functions& fn = ctx.fn;
    const CurvedMirrorProgram& p = ctx.programs.curved_mirror;
    p.use();
    p.set_view_projection(ctx.depth.to_gpu(on_frame).matrix());
    p.set_tint(draw.tint);
    const glm::vec2 atlas_size(static_cast<float>(atlas.width()), static_cast<float>(atlas.height()));
    p.set_half_texel(glm::vec2(0.5f / atlas_size.x, 0.5f / atlas_size.y));
    fn.ActiveTexture(GL_TEXTURE0);
    fn.BindTexture(GL_TEXTURE_2D, atlas.color_texture().id());
    p.set_atlas_texture_unit(0);
    fn.BindVertexArray(mesh.vertex_array.id());
    // The cap is single-sided: from behind it is culled like any surface.
    set_face_state(fn, false, draw.camera.flips_winding(), false);
    const glm::vec2 tile_uv = glm::vec2(tile) / atlas_size;
    for (const plan::PatchFrustum& patch : plan.patches) {
        // Without a frustum any matrix will do: the lookup stays inside the
        // tile, which holds only the clear colour.
        const glm::mat4 matrix = patch.pair ? patch.pair->matrix() : glm::mat4(1.0f);
        p.set_patch_matrix(matrix);
        p.set_tile(glm::vec4(patch.i * tile_uv.x, patch.j * tile_uv.y, tile_uv.x, tile_uv.y));
        const auto first = static_cast<std::size_t>(patch.j * plan.grid + patch.i) *
                           static_cast<std::size_t>(mesh.indices_per_patch) * sizeof(std::uint32_t);
        fn.DrawElements(GL_TRIANGLES, mesh.indices_per_patch, GL_UNSIGNED_INT, reinterpret_cast<const void*>(first));
    }
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    restore_face_state(fn);
}

} // namespace

glm::ivec2 curved_tile_size(const plan::CurvedMirror& mirror, const frustum::MatrixPair<float>& camera, int grid,
                            int width_px, int height_px) {
    const int largest = std::max(kMinTilePx, kMaxAtlasSidePx / grid);
    const float sign = frustum::clip_z_span<float>(camera.depth()) > 0.0f ? 1.0f : -1.0f;
    const float z_near = frustum::clip_z_near<float>(camera.depth());
    // Pixels of the (grid + 1)^2 patch corners; a corner behind the near
    // plane makes the lengths unknown: then the frame's longer side / G.
    std::vector<glm::vec2> px;
    for (int j = 0; j <= grid; ++j) {
        for (int i = 0; i <= grid; ++i) {
            const glm::dvec3 p = mirror.at(static_cast<double>(i) / grid, static_cast<double>(j) / grid).position;
            const glm::vec4 clip = camera.matrix() * glm::vec4(glm::vec3(p), 1.0f);
            if (!(sign * (clip.z - z_near * clip.w) > 0.0f && clip.w > 0.0f)) {
                const int side = std::clamp((std::max(width_px, height_px) + grid - 1) / grid, kMinTilePx, largest);
                return {side, side};
            }
            px.push_back((glm::vec2(clip) / clip.w * 0.5f + 0.5f) *
                         glm::vec2(static_cast<float>(width_px), static_cast<float>(height_px)));
        }
    }
    float along_a1 = 0.0f, along_a2 = 0.0f;
    const auto at = [&](int i, int j) { return px[static_cast<std::size_t>(j * (grid + 1) + i)]; };
    for (int j = 0; j <= grid; ++j) {
        for (int i = 0; i <= grid; ++i) {
            if (i < grid) along_a1 = std::max(along_a1, glm::distance(at(i, j), at(i + 1, j)));
            if (j < grid) along_a2 = std::max(along_a2, glm::distance(at(i, j), at(i, j + 1)));
        }
    }
    const auto side = [&](float length_px) {
        return std::clamp(static_cast<int>(std::ceil(length_px)), kMinTilePx, largest);
    };
    return {side(along_a1), side(along_a2)};
}

frustum::Status draw_curved_mirror_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                         const CurvedDraw& draw) {
    // Planned for the whole frame (the atlas's tile size too); the target
    // draws its window's crop.
    const FrameWindow window = window_of(ctx, frame.width(), frame.height());
    auto on_frame = crop_to_window(draw.camera, window);
    if (!on_frame) {
        return on_frame.take_error_in("render::draw_curved_mirror_frame()");
    }
    const auto plain = [&]() -> frustum::Status {
        frame.bind();
        begin_frame(ctx);
        draw_scene(ctx, SceneDraw{*on_frame});
        return {};
    };
    auto mirror = plan::CurvedMirror::create(draw.mirror, draw.options.shape, draw.options.sagitta_m);
    if (!mirror) {
        return frustum::Error{kDraw + mirror.error()};
    }
    const auto eye = frustum::eye_point(draw.camera);
    if (!eye) {
        return frustum::Error{std::string(kDraw) + "the curved mirror needs a finite eye (perspective camera)"};
    }
    auto plan = plan::plan_curved_mirror(*mirror, glm::dvec3(*eye), draw.bounds, draw.options.patches);
    if (!plan) {
        return frustum::Error{kDraw + plan.error()};
    }
    if (!plan->has_value()) {
        return plain();
    }
    const glm::ivec2 tile = curved_tile_size(*mirror, draw.camera, draw.options.patches, window.full_width_px,
                                              window.full_height_px);
    // One atlas per frame: the tiles of a poster share it (frame_cache.hpp).
    std::optional<gl::OffscreenTarget> own_atlas;
    std::optional<gl::OffscreenTarget>& atlas_slot = ctx.frame_cache ? ctx.frame_cache->curved_atlas : own_atlas;
    if (!atlas_slot) {
        auto made = render_atlas(ctx, **plan, tile, draw.mirror.instance);
        if (!made) {
            return made.take_error();
        }
        atlas_slot = std::move(*made);
    }
    const gl::OffscreenTarget* atlas = &*atlas_slot;
    auto mesh = upload_cap(ctx.fn, *mirror, draw.options.patches);
    if (!mesh) {
        return mesh.take_error();
    }
    frame.bind();
    begin_frame(ctx);
    SceneDraw main(*on_frame);
    main.skip_instance = draw.mirror.instance;
    draw_scene(ctx, main);
    draw_cap(ctx, draw, *on_frame, **plan, *mesh, *atlas, tile);
    return gl::check_error(ctx.fn, "render::draw_curved_mirror_frame()");
}

} // namespace render
