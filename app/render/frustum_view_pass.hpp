// An outside view: the scene from a viewer camera plus other cameras'
// frustums as coloured lines (frustum_lines), drawn over the scene without
// depth test so they stay visible behind objects.
#pragma once

#include "plan/frustum_lines.hpp"
#include "render/pass_context.hpp"

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>

#include <glm/glm.hpp>

#include <vector>

namespace render {

struct FrustumOverlay {
    frustum::MatrixPair<float> pair; // any depth range: key points are read in its own
    glm::vec4 color;                 // sRGB-encoded
};

// Draws into the bound framebuffer and viewport.
frustum::Status draw_frustum_view(const PassContext& ctx, const frustum::MatrixPair<float>& viewer,
                                  const std::vector<FrustumOverlay>& overlays, const plan::FrustumLineStyle& style);

} // namespace render
