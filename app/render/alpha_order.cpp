#include "render/alpha_order.hpp"

#include <frustum/depth_range.hpp>

namespace render {

AlphaGroup alpha_group(scene::AlphaMode mode) {
    switch (mode) {
    case scene::AlphaMode::Mask: return AlphaGroup::Mask;
    case scene::AlphaMode::Blend: return AlphaGroup::Blend;
    case scene::AlphaMode::Opaque: break;
    }
    return AlphaGroup::Opaque;
}

float view_depth(const frustum::MatrixPair<float>& camera, const glm::vec3& world) {
    const glm::mat4& m = camera.matrix();
    const glm::vec4 clip = m * glm::vec4(world, 1.0f);
    const bool affine = m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f;
    if (!affine) {
        return clip.w;
    }
    const float direction = frustum::clip_z_span<float>(camera.depth()) > 0.0f ? 1.0f : -1.0f;
    return direction * clip.z / clip.w;
}

void begin_blending(const gl::Functions& fn) {
    fn.Enable(GL_BLEND);
    fn.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    fn.DepthMask(GL_FALSE);
}

void end_blending(const gl::Functions& fn) {
    fn.Disable(GL_BLEND);
    fn.DepthMask(GL_TRUE);
}

} // namespace render
