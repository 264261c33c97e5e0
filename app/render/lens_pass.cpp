#include "render/lens_pass.hpp"

#include "render/scene_pass.hpp"
#include "render/tile_pass.hpp"

#include <gl/errors.hpp>

#include <cmath>
#include <string>

namespace render {
namespace {

constexpr const char* kLensOnNearPlane = "render::lens_on_near_plane()";

} // namespace

frustum::Result<frustum::Lens<float>> lens_on_near_plane(const frustum::MatrixPair<float>& camera,
                                                         const std::optional<scene::LensSpot>& spot, float power) {
    if (!(power > 0.0f) || !std::isfinite(power)) {
        return frustum::Error{std::string(kLensOnNearPlane) + ": power must be finite and > 0, got power=" +
                              std::to_string(power)};
    }
    const auto frame = frustum::near_plane_frame(camera);
    if (!frame) {
        return frame.take_error_in(kLensOnNearPlane);
    }
    frustum::Lens<float> lens;
    lens.power = power;
    if (!spot) {
        lens.radius_m = 0.25f * frame->half_height_m;
        return lens;
    }
    const glm::vec3 normal = glm::cross(frame->x_axis, frame->y_axis);
    const float near_offset = glm::dot(frame->center - frame->eye, normal);
    // The near-plane coordinates (metres) of the ray from the eye to `p`.
    const auto project = [&](const glm::vec3& p, glm::vec2& out) {
        const float along = glm::dot(p - frame->eye, normal);
        if (!(along / near_offset > 0.0f)) {
            return false; // not in front of the eye
        }
        const glm::vec3 hit = frame->eye + (near_offset / along) * (p - frame->eye);
        out = glm::vec2(glm::dot(hit - frame->center, frame->x_axis), glm::dot(hit - frame->center, frame->y_axis));
        return true;
    };
    glm::vec2 rim(0.0f);
    if (!project(spot->center, lens.center_m) || !project(spot->center + spot->radius_m * frame->x_axis, rim)) {
        return frustum::Error{std::string(kLensOnNearPlane) + ": the lens spot is not in front of the camera"};
    }
    lens.radius_m = glm::length(rim - lens.center_m);
    if (!(lens.radius_m > 0.0f)) {
        return frustum::Error{std::string(kLensOnNearPlane) + ": the lens spot has no size, radius_m=" +
                              std::to_string(spot->radius_m)};
    }
    return lens;
}

frustum::Status draw_lens_frame(const PassContext& ctx, const gl::OffscreenTarget& frame, const LensDraw& draw) {
    const FrameWindow window = window_of(ctx, frame.width(), frame.height());
    auto tiles = frustum::lens_tiles(draw.camera, draw.lens, window.full_width_px, window.full_height_px, draw.grid,
                                     draw.grid);
    if (!tiles) {
        return tiles.take_error_in("render::draw_lens_frame()");
    }
    return draw_tiles(ctx, frame, *tiles, draw.skip_instance, "render::draw_lens_frame()");
}

} // namespace render
