#include "window/frame.hpp"

#include "window/key_help.hpp"

#include <algorithm>

namespace window {
namespace {

constexpr int kInsetMarginPx = 8;
constexpr int kMinInsetFramebufferWidthPx = 96;
constexpr int kMinInsetFramebufferHeightPx = 64;

} // namespace

frustum::Result<Frame> make_frame(const ViewerState& state, const plan::Cameras& scene_cameras,
                                  const OrbitProjection& projection, const scene::Bounds& bounds, int width_px,
                                  int height_px) {
    Frame frame{state.effect, scene_cameras};
    if (state.orbit) {
        const float aspect = static_cast<float>(width_px) / static_cast<float>(height_px);
        auto pair = orbit_pair(*state.orbit, projection, aspect, bounds);
        if (!pair) {
            return pair.take_error();
        }
        frame.cameras.main = {"orbit", *pair};
        // The twin was the file camera's; the orbit camera is perspective itself.
        frame.cameras.perspective_twin.reset();
        frame.cameras.twin_note.reset();
    }
    frame.options.width_px = width_px;
    frame.options.height_px = height_px;
    // The effect values as the state holds them (resolved from the scene
    // by the caller), the tile counts and the lens grid within this frame.
    static_cast<plan::EffectParams&>(frame.options) = state;
    frame.options.tile_columns = std::min(state.tile_columns, width_px);
    frame.options.tile_rows = std::min(state.tile_rows, height_px);
    frame.options.lens_grid = std::min(state.lens_grid, std::min(width_px, height_px));
    frame.options.link_moves = state.link_moves;
    frame.options.msaa_samples = state.msaa_samples;
    frame.options.depth = state.depth;
    frame.inset = state.show_inset;
    if (state.show_help) {
        frame.text = help_lines(state);
    }
    return frame;
}

plan::Effect inset_effect(plan::Effect main_effect) {
    return main_effect == plan::Effect::Frustum ? plan::Effect::Plain : plan::Effect::Frustum;
}

std::optional<gl::WindowRect> inset_rect(int width_px, int height_px) {
    if (width_px < kMinInsetFramebufferWidthPx || height_px < kMinInsetFramebufferHeightPx) {
        return std::nullopt;
    }
    gl::WindowRect rect;
    rect.width = width_px / 3;
    rect.height = std::max(1, rect.width * height_px / width_px);
    rect.x = width_px - kInsetMarginPx - rect.width;
    rect.y = height_px - kInsetMarginPx - rect.height;
    return rect;
}

} // namespace window
