// The showcase scene and its cameras, loaded once for the window suite.
#pragma once

#include <doctest/doctest.h>

#include <plan/camera.hpp>
#include <scene/load_gltf.hpp>

#include <string>
#include <utility>

namespace window_test {

inline const scene::Scene& showcase() {
    static const scene::Scene loaded = [] {
        auto result = scene::load_gltf(std::string(FRUSTUM_SOURCE_DIR) + "/assets/showcase.gltf");
        REQUIRE_MESSAGE(result.ok(), result.error());
        return std::move(*result);
    }();
    return loaded;
}

inline int showcase_main_index() {
    const auto index = render::find_camera(showcase(), std::nullopt);
    REQUIRE_MESSAGE(index.ok(), index.error());
    return *index;
}

// render::make_cameras() of the showcase at 256 x 144 (its camera's 16:9).
inline render::Cameras showcase_cameras(int width_px = 256, int height_px = 144) {
    auto cameras = render::make_cameras(showcase(), showcase_main_index(), width_px, height_px);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    return std::move(*cameras);
}

} // namespace window_test
