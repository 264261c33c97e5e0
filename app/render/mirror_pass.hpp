// The mirror effect (paper §5.2 / §5.3): the scene rendered with the
// reflection camera into a texture, then the frame with the mirror surface
// looking its colour up in that texture (mirror_composite shaders).
#pragma once

#include "render/effect.hpp"
#include "render/fog_pass.hpp"
#include "render/mirror_geometry.hpp"
#include "render/pass_context.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/offscreen_target.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace render {

struct MirrorDraw {
    frustum::MatrixPair<float> camera; // ZeroToOne
    scene::MirrorRect mirror;          // mirror.instance is the surface drawn with the reflection
    MirrorMethod method = MirrorMethod::Oblique;
    glm::vec3 tint{0.92f, 0.95f, 1.0f}; // times the reflection; (1, 1, 1) = a perfect mirror
    scene::Bounds bounds;              // for the Rectangle method's far plane
    // Distance fog over the frame and, decoded with the reflection's own
    // pair, over the reflection texture (fog_pass.hpp); unset: none.
    std::optional<FogDraw> fog;
};

// Draws the whole frame into `frame` (left bound). Without a reflection (the
// mirror is off-screen, seen from behind, or has no surface) the frame is
// the plain scene and the surface shows its own material.
frustum::Status draw_mirror_frame(const PassContext& ctx, const gl::OffscreenTarget& frame, const MirrorDraw& draw);

} // namespace render
