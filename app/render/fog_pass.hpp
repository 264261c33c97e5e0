// Depth that decodes: distance fog computed after the scene is drawn, from
// the depth buffer and the exact inverse of the pair that wrote it
// (shaders/fog.frag with frustum_world_from_depth() of shaders/frustum.glsl).
// The mirror effect runs the same pass on its reflection texture with the
// reflection's own pair (oblique near plane and crop included), so the
// reflection fogs by the length of the reflected ray, as a direct render of
// the mirrored scene would (docs/depth-precision.md, README "Fog").
#pragma once

#include "render/pass_context.hpp"
#include "render/program_support.hpp"

#include <plan/fog_options.hpp>

#include <frustum/matrix_pair.hpp>
#include <frustum/result.hpp>
#include <gl/functions.hpp>
#include <gl/objects.hpp>
#include <gl/offscreen_target.hpp>
#include <scene/scene.hpp>

#include <glm/glm.hpp>

#include <optional>

namespace render {

struct FogParams {
    glm::vec3 color{0.62f, 0.74f, 0.86f};
    float density_per_m = 0.1f;
    float start_m = 0.0f;
};

// The fog of `options` for a scene with `bounds`, drawn over `clear_color`.
FogParams fit_fog(const plan::FogOptions& options, const scene::Bounds& bounds, const glm::vec4& clear_color);

// shaders/fog.frag (+ frustum.glsl) over lens_remap.vert's full-screen
// triangle: the depth texture decoded with a pair's inverse, fog blended.
class FogProgram : public ShaderProgram {
public:
    static frustum::Result<FogProgram> build(const gl::Functions& fn);

    void set_depth_texture_unit(int unit) const;
    // The GPU pair's inverse, its clip-z range and the frame's size.
    void set_decode(const glm::mat4& inverse, const glm::vec2& z_range, const glm::vec2& frame_px) const;
    void set_eye(const glm::vec3& eye_m) const;
    void set_fog(const glm::vec3& color, float density_per_m, float start_m) const;

private:
    GLint depth_ = -1, inverse_ = -1, z_range_ = -1, frame_px_ = -1, eye_ = -1;
    GLint fog_color_ = -1, density_per_m_ = -1, start_m_ = -1;
};

class FogPass {
public:
    // Builds shaders/fog.frag (+ frustum.glsl) with lens_remap.vert's
    // full-screen triangle. Errors as render::ShaderProgram::link()'s.
    static frustum::Result<FogPass> build(const gl::Functions& fn);

    // Blends fog over `target`'s colour, decoding its depth with `pair`: the
    // pair the target was drawn with, in any depth range (converted to the
    // GPU's with ctx.depth). The target's depth must be Depth24. Leaves the
    // target bound with set_frame_state()'s state.
    frustum::Status apply(const PassContext& ctx, const gl::OffscreenTarget& target,
                          const frustum::MatrixPair<float>& pair, const FogParams& fog) const;

private:
    FogPass() = default;
    FogProgram program_;
    gl::VertexArray vertex_array_; // the triangle has no attributes
};

// What a pass needs to fog its frame (MirrorDraw::fog, the plain frame).
struct FogDraw {
    const FogPass* pass = nullptr;
    FogParams params;
    bool decode_reflection_unclipped = false; // FogOptions's counter-example
};

} // namespace render
