#include "plan/non_affine_frustum.hpp"

#include <frustum/lens.hpp>
#include <frustum/queries.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <string>

namespace plan {
namespace {

// The plane through the lines a + t up and b + t up, outward: `inside` on
// its negative side.
frustum::Plane<float> outward_plane(const glm::vec3& a, const glm::vec3& b, const glm::vec3& up,
                                    const glm::vec3& inside) {
    return frustum::Plane<float>::at(glm::normalize(glm::cross(b - a, up)), a).facing(inside).flipped();
}

} // namespace

frustum::Result<frustum::NonAffineFrustum<float>> crossed_slits_frustum(const frustum::MatrixPair<float>& camera,
                                                                        const NonAffineOptions& options,
                                                                        frustum::DepthRange depth) {
    constexpr const char* kWhere = "plan::crossed_slits_frustum()";
    const auto frame = frustum::near_plane_frame(camera);
    if (!frame) {
        return frame.take_error_in(kWhere);
    }
    const auto camera_planes = frustum::planes(camera);
    if (!camera_planes.far) {
        return frustum::Error{std::string(kWhere) + ": needs a camera with a finite far plane"};
    }
    const glm::vec3 up = frame->y_axis;
    const glm::vec3 forward = frame->forward();
    const float near_m = glm::dot(frame->center - frame->eye, forward);
    const float far_m = std::abs(camera_planes.far->distance(frame->eye));
    if (!(options.slit_depth_m > 0.0f && options.slit_depth_m < options.pivot_depth_m &&
          options.pivot_depth_m < far_m)) {
        return frustum::Error{std::string(kWhere) + ": needs 0 < slit_depth_m < pivot_depth_m < far, got slit_depth_m=" +
                              std::to_string(options.slit_depth_m) + " pivot_depth_m=" +
                              std::to_string(options.pivot_depth_m) + " far=" + std::to_string(far_m)};
    }
    // Points at a depth along the rays through the near centre and the
    // middles of the near rectangle's left and right edges.
    const auto along = [&](const glm::vec3& near_point, float depth_m) {
        return frame->eye + (depth_m / near_m) * (near_point - frame->eye);
    };
    const glm::vec3 slit = along(frame->center, options.slit_depth_m);
    const glm::vec3 inside = along(frame->center, options.pivot_depth_m);
    const glm::vec3 left_pivot = along(frame->center - frame->half_width_m * frame->x_axis, options.pivot_depth_m);
    const glm::vec3 right_pivot = along(frame->center + frame->half_width_m * frame->x_axis, options.pivot_depth_m);
    return frustum::NonAffineFrustum<float>::from_planes(
        outward_plane(slit, left_pivot, up, inside), outward_plane(slit, right_pivot, up, inside),
        camera_planes.bottom.flipped(), camera_planes.top.flipped(), camera_planes.near.flipped(),
        camera_planes.far->flipped(), inside, depth);
}

} // namespace plan
