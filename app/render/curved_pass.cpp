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
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace render {
namespace {

constexpr const char* kDraw = "render::draw_curved_mirror_frame(): ";
constexpr int kMaxViewsSidePx = 4096; // G tiles side by side at most; see mirror_geometry.cpp
constexpr int kMinTilePx = 4;
constexpr int kMinCapQuads = 32; // the cap mesh has at least this many quads per side

// The cap's vertices, (M + 1) x (M + 1) world positions, M = G x quads per
// patch: what the mesh draws and what a patch's screen box bounds.
struct CapPoints {
    int per_patch = 0; // quads per patch side
    int m = 0;         // quads per cap side
    std::vector<glm::vec3> positions;
    const glm::vec3& at(int x, int y) const { return positions[static_cast<std::size_t>(y * (m + 1) + x)]; }
};

CapPoints cap_points(const plan::CurvedMirror& mirror, int grid) {
    CapPoints cap;
    cap.per_patch = (kMinCapQuads + grid - 1) / grid;
    cap.m = grid * cap.per_patch;
    cap.positions.reserve(static_cast<std::size_t>((cap.m + 1) * (cap.m + 1)));
    for (int y = 0; y <= cap.m; ++y) {
        for (int x = 0; x <= cap.m; ++x) {
            cap.positions.emplace_back(mirror.at(static_cast<double>(x) / cap.m, static_cast<double>(y) / cap.m).position);
        }
    }
    return cap;
}

// The cap as one indexed triangle mesh, M x M quads, its indices grouped
// by patch and, in a patch, by quad as cap_quads() lists them: quad q of
// patch k = j G + i is the 6 indices from (k per_patch^2 + q) 6.
frustum::Result<CapMesh> upload_cap(const gl::Functions& fn, const CapPoints& cap, int grid) {
    const int m = cap.m;
    // Counter-clockwise seen from the reflecting side (a1 right, a2 up).
    std::vector<std::uint32_t> indices;
    indices.reserve(static_cast<std::size_t>(m * m * 6));
    const auto vertex = [m](int x, int y) { return static_cast<std::uint32_t>(y * (m + 1) + x); };
    for (int j = 0; j < grid; ++j) {
        for (int i = 0; i < grid; ++i) {
            for (int y = j * cap.per_patch; y < (j + 1) * cap.per_patch; ++y) {
                for (int x = i * cap.per_patch; x < (i + 1) * cap.per_patch; ++x) {
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
    fn.BindVertexArray(mesh.vertex_array.id());
    fn.BindBuffer(GL_ARRAY_BUFFER, mesh.vertex_buffer.id());
    fn.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cap.positions.size() * sizeof(glm::vec3)),
                  cap.positions.data(), GL_STATIC_DRAW);
    fn.EnableVertexAttribArray(kPositionLocation);
    fn.VertexAttribPointer(kPositionLocation, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    fn.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.index_buffer.id());
    fn.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)),
                  indices.data(), GL_STATIC_DRAW);
    fn.BindVertexArray(0);
    fn.BindBuffer(GL_ARRAY_BUFFER, 0);
    return mesh;
}

// Texel rows per strip of a patch's view (CurvedViews): as many as the
// frame's target holds with the two margin rows, so that a strip is one
// scene draw (a direct render's target, as tall as the frame, holds a
// whole view: one strip per patch), and at least this many.
constexpr int kMinStripRows = 16;

// The view rows a lookup between rows lo and hi can read, rounded out by
// one (the bilinear lookup's neighbour): first and last, inclusive,
// clamped to the view's rows 0 .. last_row.
glm::ivec2 rows_read(float lo, float hi, int last_row) {
    const float first = std::clamp(std::floor(lo) - 1.0f, 0.0f, static_cast<float>(last_row));
    const float last = std::clamp(std::ceil(hi) + 1.0f, 0.0f, static_cast<float>(last_row));
    return {static_cast<int>(first), static_cast<int>(last)};
}

// `r` grown by a pixel each way (for the GPU's rounding against ours), inside width_px x height_px.
plan::PixelRect grown(const plan::PixelRect& r, int width_px, int height_px) {
    const int x0 = std::max(0, r.x - 1), y0 = std::max(0, r.y - 1);
    const int x1 = std::min(width_px, r.x + r.width + 1), y1 = std::min(height_px, r.y + r.height + 1);
    return {x0, y0, x1 - x0, y1 - y0};
}

// The cap mesh's quads, per patch: the frame pixels each can reach (its two
// triangles' pixels_seen(), whole frame's camera: clipped at the near plane
// before projecting) and the view rows its lookups can read (its vertices
// projected with the patch's matrix; the lookup is clamped into the view,
// so a vertex at or behind the patch's eye may read any row).
std::vector<std::vector<CurvedViews::Quad>> cap_quads(const CapPoints& cap, const plan::CurvedPlan& plan,
                                                      const frustum::MatrixPair<float>& camera, int width_px,
                                                      int height_px, const glm::ivec2& tile) {
    std::vector<std::vector<CurvedViews::Quad>> quads(plan.patches.size());
    std::vector<glm::vec3> triangle(3);
    for (const plan::PatchFrustum& patch : plan.patches) {
        std::vector<CurvedViews::Quad>& out = quads[static_cast<std::size_t>(patch.j * plan.grid + patch.i)];
        const glm::mat4 lookup = patch.pair ? patch.pair->matrix() : glm::mat4(1.0f);
        for (int y = patch.j * cap.per_patch; y < (patch.j + 1) * cap.per_patch; ++y) {
            for (int x = patch.i * cap.per_patch; x < (patch.i + 1) * cap.per_patch; ++x) {
                // Corners in the mesh's order: the triangles are 0 1 2 and 0 2 3 (upload_cap()).
                const glm::vec3 corners[4] = {cap.at(x, y), cap.at(x + 1, y), cap.at(x + 1, y + 1), cap.at(x, y + 1)};
                std::optional<plan::PixelRect> screen;
                for (const auto& [b, c] : {std::pair{1, 2}, std::pair{2, 3}}) {
                    triangle[0] = corners[0];
                    triangle[1] = corners[b];
                    triangle[2] = corners[c];
                    if (const auto seen = plan::pixels_seen(camera, triangle, width_px, height_px)) {
                        screen = screen ? bounding(*screen, *seen) : *seen;
                    }
                }
                float row_lo = std::numeric_limits<float>::max(), row_hi = std::numeric_limits<float>::lowest();
                bool in_view = true;
                for (const glm::vec3& corner : corners) {
                    const glm::vec4 view = lookup * glm::vec4(corner, 1.0f);
                    if (view.w > 0.0f) {
                        const float row = (view.y / view.w * 0.5f + 0.5f) * static_cast<float>(tile.y);
                        row_lo = std::min(row_lo, row);
                        row_hi = std::max(row_hi, row);
                    } else {
                        in_view = false;
                    }
                }
                CurvedViews::Quad quad;
                // Not seen: an empty rectangle, which meets no target's window.
                quad.screen = screen ? grown(*screen, width_px, height_px) : plan::PixelRect{0, 0, 0, 0};
                const glm::ivec2 rows = in_view ? rows_read(row_lo, row_hi, tile.y - 1) : glm::ivec2(0, tile.y - 1);
                quad.first_row = rows.x;
                quad.last_row = rows.y;
                out.push_back(quad);
            }
        }
    }
    return quads;
}

// The strips of one patch whose rows the quads seen in `rect` read: first
// and last (inclusive), or none when no quad is seen there.
std::optional<glm::ivec2> strips_read(const CurvedViews& views, std::size_t patch, const plan::PixelRect& rect) {
    if (views.quads.empty()) { // the whole frame in one target, each view one strip
        return glm::ivec2(0, 0);
    }
    std::optional<glm::ivec2> rows;
    for (const CurvedViews::Quad& quad : views.quads[patch]) {
        if (intersect(quad.screen, rect)) {
            rows = rows ? glm::ivec2(std::min(rows->x, quad.first_row), std::max(rows->y, quad.last_row))
                        : glm::ivec2(quad.first_row, quad.last_row);
        }
    }
    if (!rows) {
        return std::nullopt;
    }
    return *rows / views.strip_rows;
}

// View rows [first, end) of strip s, and those of its texture (a row of
// margin each side, inside the view).
struct StripRows {
    int first = 0, end = 0;
    int texture_first = 0, texture_end = 0;
};

StripRows strip_rows(const CurvedViews& views, int s) {
    StripRows r;
    r.first = s * views.strip_rows;
    r.end = std::min(views.tile.y, r.first + views.strip_rows);
    r.texture_first = std::max(0, r.first - 1);
    r.texture_end = std::min(views.tile.y, r.end + 1);
    return r;
}

// One strip of a patch's view (an ordinary view from the patch origin,
// without the cap's own mirror) into a colour-only texture. Drawn on
// `canvas` (the frame's own target, multisampled like the frame, before the
// frame is drawn there) in parts of at most its size, each the crop of the
// patch's pair to its part of the view (§5.1), resolved and blitted into
// place: no multisampled target of its own, whatever the view's size. A
// patch without a frustum: the clear colour.
frustum::Result<gl::OffscreenTarget> render_strip(const PassContext& ctx, const gl::OffscreenTarget& canvas,
                                                  const plan::PatchFrustum& patch, const CurvedViews& views, int s,
                                                  int mirror_instance) {
    const StripRows rows = strip_rows(views, s);
    const int height_px = rows.texture_end - rows.texture_first;
    auto strip = gl::OffscreenTarget::create(
        ctx.fn, {views.tile.x, height_px, gl::ColorStorage::Texture, gl::DepthFormat::None, 1});
    if (!strip) {
        return frustum::Error{kDraw + std::string("patch view: ") + strip.error()};
    }
    const gl::Functions& fn = ctx.fn;
    const plan::PixelRect image{0, 0, views.tile.x, views.tile.y};
    for (int y = 0; y < height_px; y += canvas.height()) {
        for (int x = 0; x < views.tile.x; x += canvas.width()) {
            const plan::PixelRect part{x, rows.texture_first + y, std::min(canvas.width(), views.tile.x - x),
                                       std::min(canvas.height(), height_px - y)};
            canvas.bind();
            fn.Viewport(0, 0, part.width, part.height);
            set_frame_state(ctx);
            fn.Enable(GL_SCISSOR_TEST); // clear the part only
            fn.Scissor(0, 0, part.width, part.height);
            clear_frame(ctx);
            fn.Disable(GL_SCISSOR_TEST);
            if (patch.pair) {
                auto cropped = crop_part(*patch.pair, image, part);
                if (!cropped) {
                    return cropped.take_error_in("render::draw_curved_mirror_frame(): patch view");
                }
                SceneDraw draw(*cropped);
                draw.skip_instance = mirror_instance;
                draw_scene(ctx, draw);
            }
            if (auto blit = canvas.blit_color_to(*strip, part.width, part.height, x, y); !blit) {
                return blit.take_error_in("render::draw_curved_mirror_frame(): patch view");
            }
        }
    }
    return strip;
}

// on_frame: the camera cropped to the target's window. Each patch seen in
// the window is drawn once per strip its quads there read (every one of
// them is made), each time only the quads seen in the window that read the
// strip, in runs of consecutive quads; a fragment is kept by the strip
// that holds its lookup's row (a quad across two strips is drawn by both,
// each keeping its own fragments), so nearly every fragment is shaded once.
void draw_cap(const PassContext& ctx, const CurvedDraw& draw, const frustum::MatrixPair<float>& on_frame,
              const CurvedViews& views, const plan::PixelRect& window) {
    const plan::CurvedPlan& plan = *views.plan;
    const CapMesh& mesh = views.cap;
    const gl::Functions& fn = ctx.fn;
    const CurvedMirrorProgram& p = ctx.programs.curved_mirror;
    p.use();
    p.set_view_projection(ctx.depth.to_gpu(on_frame).matrix());
    p.set_tint(draw.tint);
    p.set_half_texel(glm::vec2(0.5f / static_cast<float>(views.tile.x), 0.5f / static_cast<float>(views.tile.y)));
    p.set_view_rows(static_cast<float>(views.tile.y));
    fn.ActiveTexture(GL_TEXTURE0);
    p.set_view_texture_unit(0);
    fn.BindVertexArray(mesh.vertex_array.id());
    // The cap is single-sided: from behind it is culled like any surface.
    set_face_state(fn, false, draw.camera.flips_winding(), false);
    for (const plan::PatchFrustum& patch : plan.patches) {
        const auto k = static_cast<std::size_t>(patch.j * plan.grid + patch.i);
        const std::optional<glm::ivec2> read = strips_read(views, k, window);
        if (!read) {
            continue;
        }
        // Without a frustum any matrix will do: the view holds only the clear colour.
        p.set_patch_matrix(patch.pair ? patch.pair->matrix() : glm::mat4(1.0f));
        const auto count = static_cast<std::size_t>(views.quads_per_patch);
        for (int s = read->x; s <= read->y; ++s) {
            const StripRows rows = strip_rows(views, s);
            const auto drawn = [&](std::size_t q) {
                if (views.quads.empty()) {
                    return true;
                }
                const CurvedViews::Quad& quad = views.quads[k][q];
                return quad.first_row < rows.end && quad.last_row >= rows.first &&
                       intersect(quad.screen, window).has_value();
            };
            fn.BindTexture(GL_TEXTURE_2D,
                           views.strips[k * static_cast<std::size_t>(views.strips_per_patch) +
                                        static_cast<std::size_t>(s)]
                               ->color_texture()
                               .id());
            p.set_strip(glm::vec4(static_cast<float>(rows.first), static_cast<float>(rows.end),
                                  static_cast<float>(rows.texture_first),
                                  static_cast<float>(rows.texture_end - rows.texture_first)));
            // Quad q of patch k: 6 indices from (k quads per patch + q) 6, as upload_cap() orders them.
            for (std::size_t q = 0; q < count;) {
                if (!drawn(q)) {
                    ++q;
                    continue;
                }
                std::size_t end = q + 1;
                while (end < count && drawn(end)) {
                    ++end;
                }
                const std::size_t first = (k * count + q) * 6 * sizeof(std::uint32_t);
                fn.DrawElements(GL_TRIANGLES, static_cast<GLsizei>((end - q) * 6), GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(first));
                q = end;
            }
        }
    }
    fn.BindVertexArray(0);
    fn.BindTexture(GL_TEXTURE_2D, 0);
    restore_face_state(fn);
}

// The frame's plan (CurvedViews), made by the first target drawn into:
// `frame_height_px` tall, in `window` of the frame.
frustum::Result<std::unique_ptr<CurvedViews>> plan_views(const PassContext& ctx, const CurvedDraw& draw,
                                                         const FrameWindow& window, int frame_height_px) {
    auto views = std::make_unique<CurvedViews>();
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
        return views; // no plan: the plain frame
    }
    views->plan = std::move(**plan);
    const CapPoints cap = cap_points(*mirror, draw.options.patches);
    auto mesh = upload_cap(ctx.fn, cap, draw.options.patches);
    if (!mesh) {
        return mesh.take_error();
    }
    views->cap = std::move(*mesh);
    views->quads_per_patch = cap.per_patch * cap.per_patch;
    views->tile = curved_tile_size(*mirror, draw.camera, draw.options.patches, window.full_width_px,
                                   window.full_height_px);
    views->strip_rows = std::clamp(frame_height_px - 2, kMinStripRows, std::max(kMinStripRows, views->tile.y));
    views->strips_per_patch = (views->tile.y + views->strip_rows - 1) / views->strip_rows;
    const bool whole = window.rect.width == window.full_width_px && window.rect.height == window.full_height_px;
    if (!whole || views->strips_per_patch > 1) { // which tiles a quad reaches, which strips it reads
        views->quads = cap_quads(cap, *views->plan, draw.camera, window.full_width_px, window.full_height_px,
                                 views->tile);
    }
    views->strips.resize(views->plan->patches.size() * static_cast<std::size_t>(views->strips_per_patch));
    return views;
}

} // namespace

glm::ivec2 curved_tile_size(const plan::CurvedMirror& mirror, const frustum::MatrixPair<float>& camera, int grid,
                            int width_px, int height_px) {
    const int largest = std::max(kMinTilePx, kMaxViewsSidePx / grid);
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
    // Planned for the whole frame (the patches' views too); the target
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
    // Planned once for the whole frame (a poster's tiles share it,
    // frame_cache.hpp): the fits, the cap, the views' size and strips. A
    // strip is made when a target first reads it and let go when a target's
    // rows of the frame do not read it any more: a poster drawn a row of
    // tiles at a time keeps the strips its current row reads, each drawn
    // once when the rows read go one way.
    std::unique_ptr<CurvedViews> own_views;
    std::unique_ptr<CurvedViews>& views_slot = ctx.frame_cache ? ctx.frame_cache->curved_views : own_views;
    if (!views_slot) {
        auto made = plan_views(ctx, draw, window, frame.height());
        if (!made) {
            return made.take_error();
        }
        views_slot = std::move(*made);
    }
    CurvedViews& views = *views_slot;
    if (!views.plan) {
        return plain();
    }
    const plan::PixelRect rows{0, window.rect.y, window.full_width_px, window.rect.height};
    for (const plan::PatchFrustum& patch : views.plan->patches) {
        const auto k = static_cast<std::size_t>(patch.j * views.plan->grid + patch.i);
        const std::optional<glm::ivec2> kept = strips_read(views, k, rows);
        const std::optional<glm::ivec2> read = strips_read(views, k, window.rect);
        for (int s = 0; s < views.strips_per_patch; ++s) {
            std::optional<gl::OffscreenTarget>& strip =
                views.strips[k * static_cast<std::size_t>(views.strips_per_patch) + static_cast<std::size_t>(s)];
            if (!kept || s < kept->x || s > kept->y) {
                strip.reset();
            } else if (!strip && read && s >= read->x && s <= read->y) {
                auto made = render_strip(ctx, frame, patch, views, s, draw.mirror.instance);
                if (!made) {
                    return made.take_error();
                }
                strip = std::move(*made);
            }
        }
    }
    frame.bind();
    begin_frame(ctx);
    SceneDraw main(*on_frame);
    main.skip_instance = draw.mirror.instance;
    draw_scene(ctx, main);
    draw_cap(ctx, draw, *on_frame, views, window.rect);
    return gl::check_error(ctx.fn, "render::draw_curved_mirror_frame()");
}

} // namespace render
