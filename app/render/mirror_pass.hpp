// The mirror effect (paper §5.2 / §5.3): the scene rendered with the
// reflection camera into a texture, then the frame with the mirror surface
// looking its colour up in that texture (mirror_composite shaders).
#pragma once

#include "plan/effect.hpp"
#include "render/fog_pass.hpp"
#include "plan/mirror_geometry.hpp"
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
    plan::MirrorMethod method = plan::MirrorMethod::Oblique;
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

// Draws instance `mirror_instance` of ctx.scene with `camera`, its colour
// looked up in `reflection` at uv = (texture_matrix world).xy / w * 0.5 + 0.5
// times `tint` (mirror_composite shaders). texture_matrix is the pair the
// texture was rendered with; on the surface it must map world to clip x, y
// and w as the camera (cropped to the texture's rectangle) does: a
// reflection or a portal view of the surface's own plane does.
void draw_reflection_surface(const PassContext& ctx, const frustum::MatrixPair<float>& camera, int mirror_instance,
                             const gl::Texture& reflection, const glm::mat4& texture_matrix, const glm::vec3& tint);

} // namespace render
