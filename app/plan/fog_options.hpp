// What the fog asks for (EffectParams::fog, drawn by render/fog_pass.hpp);
// unset values are derived from the scene (render::fit_fog()). Pure data.
#pragma once

#include <glm/glm.hpp>

#include <optional>

namespace plan {

struct FogOptions {
    std::optional<glm::vec3> color;     // sRGB-encoded; default: the frame's clear colour (the sky)
    std::optional<float> density_per_m; // default: ln 2 / the scene's diagonal (half fog one diagonal away)
    float start_m = 0.0f;               // no fog closer than this to the eye
    // A counter-example for tests and the README: the reflection's depth
    // decoded with the reflected pair before its oblique near plane (what
    // engines that keep only the projection they started from do). Meant
    // for MirrorMethod::Oblique, whose crop that pair shares.
    bool decode_reflection_unclipped = false;
};

} // namespace plan
