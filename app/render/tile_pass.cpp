#include "render/tile_pass.hpp"

#include "render/scene_pass.hpp"

#include <frustum/crop.hpp>
#include <gl/errors.hpp>

namespace render {

frustum::Status draw_tiles(const PassContext& ctx, const gl::OffscreenTarget& frame,
                           const std::vector<frustum::Tile<float>>& tiles, int skip_instance, const char* where) {
    const gl::Functions& fn = ctx.fn;
    frame.bind();
    set_frame_state(ctx);
    clear_frame(ctx);
    fn.Enable(GL_SCISSOR_TEST);
    for (const frustum::Tile<float>& tile : tiles) {
        // Each tile draws only its own pixels.
        fn.Viewport(tile.x_px, tile.y_px, tile.width_px, tile.height_px);
        fn.Scissor(tile.x_px, tile.y_px, tile.width_px, tile.height_px);
        SceneDraw scene{tile.pair};
        scene.skip_instance = skip_instance;
        draw_scene(ctx, scene);
    }
    fn.Disable(GL_SCISSOR_TEST);
    frame.bind();
    return gl::check_error(fn, where);
}

frustum::Status draw_tiled_frame(const PassContext& ctx, const gl::OffscreenTarget& frame,
                                 const frustum::MatrixPair<float>& camera, int columns, int rows) {
    auto tiles = frustum::crop_tiles(camera, frame.width(), frame.height(), columns, rows);
    if (!tiles) {
        return frustum::Error{"render::draw_tiled_frame(): " + tiles.error()};
    }
    return draw_tiles(ctx, frame, *tiles, -1, "render::draw_tiled_frame()");
}

} // namespace render
