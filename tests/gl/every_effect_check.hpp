// The "every effect visible" check (issue 33, docs/any-scene.md): on a scene
// it has never seen, with every parameter derived (derive_scene(): the
// mirror placed where the default camera sees it, the links placed per
// frame), the placed surfaces must show. mirror, curved, portal and
// recursion each change at least kMinChangedFraction of the frame's pixels
// against plain; lens and nonaffine render, show more than sky and change at
// least kMinWarpChangedFraction. Shared by the generated models' test
// (render_every_effect_visible_test.cpp) and the samples corpus
// (render_samples_test.cpp).
#pragma once

#include "any_scene_check.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace every_effect {

inline constexpr int kWidthPx = 160;
inline constexpr int kHeightPx = 90;
inline constexpr int kToleranceLsb = 2;               // a pixel differs when a channel is further off
inline constexpr double kMinChangedFraction = 0.01;   // mirror, curved, portal, recursion: 1% of the frame
inline constexpr double kMinWarpChangedFraction = 0.001; // lens, nonaffine: they move pixels, 0.1% of the frame

// Pixels with a channel more than kToleranceLsb away between a and b.
inline int changed_pixels(const image::Image& a, const image::Image& b) {
    const auto diff = image::compare(a, b, kToleranceLsb);
    REQUIRE_MESSAGE(diff.ok(), diff.error());
    return diff->pixels_over;
}

struct Outcome {
    std::string file;
    std::string effect;
    double changed_fraction = 0.0;
};

// Renders every file through one backend (EGL, else OSMesa; none: a skip)
// and returns what fell short, after a CHECK for each; `report` lists each
// effect's changed fraction with MESSAGE.
inline std::vector<Outcome> check_files(const std::vector<std::filesystem::path>& files, bool report = false) {
    std::vector<Outcome> short_of;
    auto env = gl_test::make_any_environment();
    if (!env) {
        return short_of;
    }
    const double frame_px = double(kWidthPx) * double(kHeightPx);
    for (const auto& file : files) {
        INFO(file.filename().string());
        auto scene = scene::load_gltf(file.string());
        REQUIRE_MESSAGE(scene.ok(), scene.error());
        const render_test::DerivedScene derived = render_test::derive_scene(*env, *scene, kWidthPx, kHeightPx);
        const auto render = [&](plan::Effect effect) {
            auto picture = derived.renderer->render(effect, derived.cameras, derived.options);
            REQUIRE_MESSAGE(picture.ok(), plan::to_string(effect) << ": " << picture.error());
            return std::move(*picture);
        };
        const image::Image plain = render(plan::Effect::Plain);
        std::string line = file.filename().string() + ":";
        for (plan::Effect effect : {plan::Effect::Mirror, plan::Effect::Curved, plan::Effect::Portal,
                                    plan::Effect::Recursion, plan::Effect::Lens, plan::Effect::NonAffine}) {
            INFO(plan::to_string(effect));
            const image::Image picture = render(effect);
            const double changed = changed_pixels(plain, picture) / frame_px;
            const bool warp = effect == plan::Effect::Lens || effect == plan::Effect::NonAffine;
            const double needed = warp ? kMinWarpChangedFraction : kMinChangedFraction;
            line += " " + std::string(plan::to_string(effect)) + " " + std::to_string(changed * 100.0).substr(0, 5) + "%";
            CHECK(changed >= needed);
            if (warp) {
                CHECK(any_scene::not_sky_pixels(picture) >= frame_px / 100.0); // not empty: 1% not sky
            }
            if (changed < needed) {
                short_of.push_back({file.filename().string(), std::string(plan::to_string(effect)), changed});
                render_test::save_failure("every-effect-" + file.stem().string() + "-" +
                                              std::string(plan::to_string(effect)),
                                          plain, picture);
            }
        }
        if (report) {
            MESSAGE(line);
        }
    }
    return short_of;
}

} // namespace every_effect
