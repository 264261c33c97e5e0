// The "any scene" check (docs/any-scene.md), shared by the gl suite's
// generated models (render_any_scene_test.cpp) and the external samples
// corpus (render_samples_test.cpp): every effect on every file through both
// backends, with the effect parameters derived from the scene and a mirror
// placed when the scene has none. Each image has something besides the sky,
// and the mirror changes the plain frame only inside the mirror's screen
// rectangle.
#pragma once

#include "render_test_support.hpp"

#include <plan/mirror_geometry.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <vector>

namespace any_scene {


inline constexpr int kWidthPx = 96;
inline constexpr int kHeightPx = 64;
inline constexpr int kToleranceLsb = 2;
inline constexpr int kMinNotSkyPixels = kWidthPx * kHeightPx / 100; // 1% of the image

// Pixels more than kToleranceLsb away from the clear colour.
inline int not_sky_pixels(const image::Image& picture) {
    const glm::vec4 c = render::kClearColor;
    const image::Image sky = image::make_image(
        picture.width, picture.height,
        {static_cast<std::uint8_t>(c.r * 255.0f + 0.5f), static_cast<std::uint8_t>(c.g * 255.0f + 0.5f),
         static_cast<std::uint8_t>(c.b * 255.0f + 0.5f), 255});
    const auto diff = image::compare(picture, sky, kToleranceLsb);
    REQUIRE(diff.ok());
    return diff->pixels_over;
}

struct MirrorDiff {
    int inside = 0;  // pixels of the mirror's screen rectangle that differ
    int outside = 0; // pixels elsewhere that differ
};

inline MirrorDiff mirror_diff(const image::Image& plain, const image::Image& mirror, const plan::PixelRect& rect) {
    MirrorDiff d;
    for (int row = 0; row < plain.height; ++row) {
        const int y = plain.height - 1 - row; // PixelRect counts from the bottom
        for (int x = 0; x < plain.width; ++x) {
            const image::Rgba a = image::pixel_at(plain, x, row), b = image::pixel_at(mirror, x, row);
            bool differs = false;
            for (int k = 0; k < 3; ++k) {
                differs = differs || std::abs(int(a[k]) - int(b[k])) > kToleranceLsb;
            }
            const bool in = x >= rect.x && x < rect.x + rect.width && y >= rect.y && y < rect.y + rect.height;
            (in ? d.inside : d.outside) += differs ? 1 : 0;
        }
    }
    return d;
}

// Every effect on every file, both backends (a missing backend is a skip).
inline void check_every_effect(const std::vector<std::filesystem::path>& files) {
    for (gl::Backend backend : gl_test::kBackends) {
        auto env = gl_test::make_environment(backend);
        if (!env) {
            continue;
        }
        for (const auto& file : files) {
            INFO(gl::to_string(backend) << " " << file.filename().string());
            auto scene = scene::load_gltf(file.string());
            REQUIRE_MESSAGE(scene.ok(), scene.error());
            const render_test::DerivedScene derived = render_test::derive_scene(*env, *scene, kWidthPx, kHeightPx);
            const plan::Cameras& cameras = derived.cameras;

            std::map<plan::Effect, image::Image> pictures;
            for (plan::Effect effect : plan::kAllEffects) {
                INFO(plan::to_string(effect));
                auto picture = derived.renderer->render(effect, cameras, derived.options);
                REQUIRE_MESSAGE(picture.ok(), picture.error());
                const int not_sky = not_sky_pixels(*picture);
                CHECK(not_sky >= kMinNotSkyPixels);
                if (not_sky < kMinNotSkyPixels) {
                    render_test::save_failure("any-scene-" + file.stem().string() + "-" +
                                                  std::string(plan::to_string(effect)),
                                              *picture, *picture);
                }
                pictures.emplace(effect, std::move(*picture));
            }

            const auto rect = plan::mirror_screen_rect(*scene->mirror, cameras.main.pair, kWidthPx, kHeightPx);
            REQUIRE_MESSAGE(rect, "the mirror is off-screen");
            const image::Image& plain = pictures.at(plan::Effect::Plain);
            const image::Image& mirror = pictures.at(plan::Effect::Mirror);
            const MirrorDiff d = mirror_diff(plain, mirror, *rect);
            MESSAGE(file.filename().string() << ": mirror rectangle " << rect->width << "x" << rect->height << ", "
                                             << d.inside << " pixels reflect, " << d.outside << " elsewhere differ");
            CHECK(d.inside >= kMinNotSkyPixels);
            CHECK(d.outside == 0);
            if (d.inside < kMinNotSkyPixels || d.outside != 0) {
                render_test::save_failure("any-scene-mirror-" + file.stem().string(), plain, mirror);
            }
        }
    }
}

} // namespace any_scene
