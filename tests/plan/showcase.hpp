// The showcase scene and its cameras, shared by the suites that draw it
// (tests/gl) and those that only plan with it (tests/plan, no GL).
#pragma once

#include <doctest/doctest.h>
#include <plan/camera.hpp>
#include <scene/load_gltf.hpp>

#include <optional>
#include <string>
#include <utility>

namespace render_test {

// The showcase's main camera is 16:9; keep test images small.
inline constexpr int kWidthPx = 256;
inline constexpr int kHeightPx = 144;

inline const scene::Scene& showcase() {
    static const scene::Scene loaded = [] {
        auto result = scene::load_gltf(std::string(FRUSTUM_SOURCE_DIR) + "/assets/showcase.gltf");
        REQUIRE_MESSAGE(result.ok(), result.error());
        return std::move(*result);
    }();
    return loaded;
}

inline plan::Cameras showcase_cameras(int width_px = kWidthPx, int height_px = kHeightPx) {
    const auto index = plan::find_camera(showcase(), std::nullopt);
    REQUIRE_MESSAGE(index.ok(), index.error());
    auto cameras = plan::make_cameras(showcase(), *index, width_px, height_px);
    REQUIRE_MESSAGE(cameras.ok(), cameras.error());
    return std::move(*cameras);
}

} // namespace render_test
