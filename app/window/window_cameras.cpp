#include "window/window_cameras.hpp"

#include <cmath>
#include <string>

namespace window {
namespace {

constexpr float kAspectTolerance = 1e-3f; // relative

// The pair of scene camera `index` with the framebuffer's aspect when its
// own one differs; empty when it can stay as make_cameras() made it.
frustum::Result<std::optional<frustum::MatrixPair<float>>> refit(const scene::Scene& scene, int index, float aspect) {
    scene::Camera camera = scene.cameras[static_cast<std::size_t>(index)];
    if (!camera.aspect || std::abs(*camera.aspect - aspect) <= kAspectTolerance * aspect) {
        return std::optional<frustum::MatrixPair<float>>();
    }
    camera.aspect.reset();
    auto pair = render::camera_pair(camera, aspect);
    if (!pair) {
        return frustum::Error{"window::window_cameras(): " + pair.error()};
    }
    return std::optional<frustum::MatrixPair<float>>(*pair);
}

} // namespace

frustum::Result<render::Cameras> window_cameras(const scene::Scene& scene, int main_camera, int width_px,
                                                int height_px) {
    auto cameras = render::make_cameras(scene, main_camera, width_px, height_px);
    if (!cameras) {
        return cameras;
    }
    const float aspect = static_cast<float>(width_px) / static_cast<float>(height_px);
    if (main_camera >= 0 && static_cast<std::size_t>(main_camera) < scene.cameras.size()) {
        auto main = refit(scene, main_camera, aspect);
        if (!main) {
            return frustum::Error{main.error()};
        }
        if (*main) {
            cameras->main.pair = **main;
        }
    }
    if (cameras->overview.name == "overview") {
        auto index = render::find_camera(scene, std::string("overview"));
        if (!index) {
            return frustum::Error{index.error()};
        }
        auto overview = refit(scene, *index, aspect);
        if (!overview) {
            return frustum::Error{overview.error()};
        }
        if (*overview) {
            cameras->overview.pair = **overview;
        }
    }
    return cameras;
}

} // namespace window
