#include "render/tile_pass.hpp"

#include "render/scene_pass.hpp"

#include <frustum/crop.hpp>
#include <gl/errors.hpp>

#include <string>

namespace render {
namespace {

constexpr glm::vec4 kTileBorderColor{1.0f, 0.85f, 0.1f, 1.0f}; // the frustum view's camera yellow

} // namespace

frustum::Status draw_tiles(const PassContext& ctx, const gl::OffscreenTarget& frame,
                           const std::vector<frustum::Tile<float>>& tiles, int skip_instance, const char* where) {
    const gl::Functions& fn = ctx.fn;
    frame.bind();
    set_frame_state(ctx);
    clear_frame(ctx);
    fn.Enable(GL_SCISSOR_TEST);
    const FrameWindow window = window_of(ctx, frame.width(), frame.height());
    for (const frustum::Tile<float>& tile : tiles) {
        // The tiles are the whole frame's; the target draws the part of each
        // inside its window, with the tile's pair cropped to that part.
        const plan::PixelRect tile_rect{tile.x_px, tile.y_px, tile.width_px, tile.height_px};
        const auto part = intersect(tile_rect, window.rect);
        if (!part) {
            continue;
        }
        auto pair = crop_part(tile.pair, tile_rect, *part);
        if (!pair) {
            return pair.take_error_in(where);
        }
        // Each tile draws only its own pixels.
        const plan::PixelRect r = in_target(window, *part);
        fn.Viewport(r.x, r.y, r.width, r.height);
        fn.Scissor(r.x, r.y, r.width, r.height);
        SceneDraw scene{*pair};
        scene.skip_instance = skip_instance;
        draw_scene(ctx, scene);
    }
    fn.Disable(GL_SCISSOR_TEST);
    frame.bind();
    return gl::check_error(fn, where);
}

void draw_tile_borders(const PassContext& ctx, const FrameWindow& window,
                       const std::vector<frustum::Tile<float>>& tiles, const glm::vec4& color) {
    const gl::Functions& fn = ctx.fn;
    fn.Enable(GL_SCISSOR_TEST);
    fn.ClearColor(color.r, color.g, color.b, color.a);
    const auto paint = [&](const plan::PixelRect& line) {
        if (const auto part = intersect(line, window.rect)) {
            const plan::PixelRect r = in_target(window, *part);
            fn.Scissor(r.x, r.y, r.width, r.height);
            fn.Clear(GL_COLOR_BUFFER_BIT);
        }
    };
    for (const frustum::Tile<float>& tile : tiles) {
        if (tile.x_px > 0) {
            paint({tile.x_px, tile.y_px, 1, tile.height_px});
        }
        if (tile.y_px > 0) {
            paint({tile.x_px, tile.y_px, tile.width_px, 1});
        }
    }
    fn.Disable(GL_SCISSOR_TEST);
}

frustum::Status draw_tiled_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                 const frustum::MatrixPair<float>& camera, int columns, int rows, bool borders) {
    constexpr const char* kWhere = "render::draw_tiled_frame()";
    const FrameWindow window = window_of(ctx, frame.width(), frame.height());
    auto tiles = frustum::crop_tiles(camera, window.full_width_px, window.full_height_px, columns, rows);
    if (!tiles) {
        return tiles.take_error_in(kWhere);
    }
    if (auto status = draw_tiles(ctx, frame, *tiles, -1, kWhere); !status || !borders) {
        return status;
    }
    draw_tile_borders(ctx, window, *tiles, kTileBorderColor);
    frame.bind();
    return gl::check_error(ctx.fn, kWhere);
}

} // namespace render
