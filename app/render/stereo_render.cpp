#include "render/stereo_render.hpp"

#include <algorithm>
#include <cstddef>
#include <string>

namespace render {

frustum::Result<image::Image> render_stereo(const Renderer& renderer, plan::Effect effect, const plan::Cameras& cameras,
                                            const RenderOptions& options, const plan::StereoRig& rig) {
    if (options.width_px % 2 != 0) {
        return frustum::Error{"render::render_stereo(): the image width must be even (two eyes side by side), got " +
                              std::to_string(options.width_px) + " px"};
    }
    auto eyes = plan::stereo_cameras(cameras, rig);
    if (!eyes) {
        return frustum::Error{eyes.error()};
    }
    RenderOptions eye_options = options;
    eye_options.width_px = options.width_px / 2;
    auto left = renderer.render(effect, eyes->left, eye_options);
    if (!left) {
        return frustum::Error{left.error()};
    }
    auto right = renderer.render(effect, eyes->right, eye_options);
    if (!right) {
        return frustum::Error{right.error()};
    }
    image::Image both = image::make_image(options.width_px, options.height_px, {0, 0, 0, 255});
    const std::size_t eye_row = static_cast<std::size_t>(eye_options.width_px) * 4;
    for (int y = 0; y < options.height_px; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * eye_row;
        auto out = both.rgba.begin() + static_cast<std::ptrdiff_t>(2 * row);
        std::copy_n(left->rgba.begin() + static_cast<std::ptrdiff_t>(row), eye_row, out);
        std::copy_n(right->rgba.begin() + static_cast<std::ptrdiff_t>(row), eye_row,
                    out + static_cast<std::ptrdiff_t>(eye_row));
    }
    return both;
}

} // namespace render
