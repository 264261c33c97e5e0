// What every pass draws with: the GL table, the programs, the uploaded
// scene, the depth policy, and the frame's look.
#pragma once

#include "render/depth_policy.hpp"
#include "render/frame_cache.hpp"
#include "render/frame_window.hpp"
#include "render/gpu_scene.hpp"
#include "render/programs.hpp"

#include <gl/context.hpp>
#include <gl/functions.hpp>

#include <glm/glm.hpp>

#include <functional>
#include <optional>

namespace render {

// One directional light plus ambient, in world space (scene.frag).
struct Lighting {
    glm::vec3 to_light{0.35f, 1.0f, 0.45f}; // towards the light; normalized when used
    float ambient = 0.3f;
    float diffuse = 0.75f;
};

// The frame's background: an sRGB-encoded sky blue.
inline constexpr glm::vec4 kClearColor{0.62f, 0.74f, 0.86f, 1.0f};

struct PassContext {
    const gl::Functions& fn;
    gl::Api api; // desktop core GL needs GL_PROGRAM_POINT_SIZE for gl_PointSize
    const Programs& programs;
    const GpuScene& scene;
    const DepthPolicy& depth;
    Lighting lighting;
    glm::vec4 clear_color = kClearColor;
    // MSAA samples of the frame; the passes' own targets (the reflection
    // texture, the curved mirror's patch views) are multisampled alike and resolved.
    int samples = 1;
    // RenderOptions::pass_end: called as a pass ends, when set.
    std::function<void(const char* pass)> pass_end = {};
    // The part of the frame the bound frame target holds (a poster tile):
    // the passes plan for window->full_* and draw the crop to window->rect.
    // Unset: the target is the whole frame.
    std::optional<FrameWindow> window = {};
    // The tiles of one poster share what each would draw the same (the
    // curved mirror's patch views); null: nothing kept.
    FrameCache* frame_cache = nullptr;
};

// ctx.window, else the whole frame of a target_width_px x target_height_px target.
inline FrameWindow window_of(const PassContext& ctx, int target_width_px, int target_height_px) {
    return ctx.window ? *ctx.window : whole_frame(target_width_px, target_height_px);
}

} // namespace render
