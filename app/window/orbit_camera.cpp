#include "window/orbit_camera.hpp"

#include <frustum/projection.hpp>
#include <frustum/queries.hpp>

#include <algorithm>
#include <cmath>

namespace window {
namespace {

const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

glm::vec3 bounds_center(const scene::Bounds& bounds) { return (bounds.min + bounds.max) * 0.5f; }

} // namespace

glm::vec3 OrbitCamera::eye() const {
    const float c = std::cos(pitch_rad);
    return target + distance_m * glm::vec3(c * std::sin(yaw_rad), std::sin(pitch_rad), c * std::cos(yaw_rad));
}

glm::vec3 OrbitCamera::forward() const {
    const float c = std::cos(pitch_rad);
    return -glm::vec3(c * std::sin(yaw_rad), std::sin(pitch_rad), c * std::cos(yaw_rad));
}

float bounds_radius(const scene::Bounds& bounds) {
    const float half_diagonal_m = glm::length(bounds.max - bounds.min) * 0.5f;
    return half_diagonal_m > 0.0f ? half_diagonal_m : 1.0f;
}

OrbitCamera orbit_from_pair(const frustum::MatrixPair<float>& camera, const scene::Bounds& bounds) {
    const float tolerance = frustum::infinity_tolerance<float>();
    const frustum::KeyPoints<float> points = frustum::key_points(camera);
    // The near plane is inward-positive: its normal points along the view.
    const glm::vec3 forward = glm::normalize(frustum::planes(camera).near.normal());
    const auto eye = frustum::eye_point(camera);
    const bool perspective = eye.has_value();
    // A point on the viewing axis: the eye, or an orthographic frustum's centre.
    const glm::vec3 on_axis = perspective ? *eye : glm::vec3(frustum::to_point(points.center, tolerance));
    const float radius_m = bounds_radius(bounds);
    const float depth_m = glm::dot(bounds_center(bounds) - on_axis, forward);

    OrbitCamera orbit;
    if (perspective) {
        orbit.distance_m = std::max(depth_m, 0.1f * radius_m);
        orbit.target = on_axis + forward * orbit.distance_m;
    } else {
        orbit.target = on_axis + forward * depth_m;
        orbit.distance_m = 2.5f * radius_m;
    }
    const glm::vec3 back = -forward; // from the target towards the eye
    orbit.yaw_rad = std::atan2(back.x, back.z);
    orbit.pitch_rad = std::clamp(std::asin(std::clamp(back.y, -1.0f, 1.0f)), -kMaxPitchRad, kMaxPitchRad);
    return orbit;
}

OrbitProjection orbit_projection(const scene::Scene& scene, int main_camera) {
    OrbitProjection projection;
    if (main_camera < 0 || static_cast<std::size_t>(main_camera) >= scene.cameras.size()) {
        return projection;
    }
    const scene::Camera& camera = scene.cameras[static_cast<std::size_t>(main_camera)];
    if (camera.kind == scene::Camera::Kind::Perspective) {
        projection.yfov_rad = camera.yfov_rad;
        projection.near_m = camera.znear_m;
        projection.far_m = camera.zfar_m;
    }
    return projection;
}

void orbit(OrbitCamera& camera, float yaw_delta_rad, float pitch_delta_rad) {
    constexpr float kTwoPi = 6.28318531f;
    camera.yaw_rad = std::remainder(camera.yaw_rad + yaw_delta_rad, kTwoPi);
    camera.pitch_rad = std::clamp(camera.pitch_rad + pitch_delta_rad, -kMaxPitchRad, kMaxPitchRad);
}

void pan(OrbitCamera& camera, float right_m, float up_m) {
    const glm::vec3 forward = camera.forward();
    const glm::vec3 right = glm::normalize(glm::cross(forward, kUp)); // |pitch| < 90 degrees
    const glm::vec3 up = glm::cross(right, forward);
    camera.target += right * right_m + up * up_m;
}

void zoom(OrbitCamera& camera, float factor, float min_m, float max_m) {
    camera.distance_m = std::clamp(camera.distance_m * factor, min_m, max_m);
}

frustum::Result<frustum::MatrixPair<float>> orbit_pair(const OrbitCamera& camera, const OrbitProjection& projection,
                                                       float aspect, const scene::Bounds& bounds) {
    float near_m = 0.0f;
    std::optional<float> far_m;
    if (projection.near_m) {
        near_m = *projection.near_m;
        far_m = projection.far_m;
    } else {
        const float radius_m = bounds_radius(bounds);
        const float distance_to_center_m = glm::length(camera.eye() - bounds_center(bounds));
        near_m = std::max((distance_to_center_m - radius_m) * 0.5f, radius_m * 1e-3f);
        far_m = distance_to_center_m + 2.0f * radius_m;
    }
    auto perspective = frustum::perspective<float>(projection.yfov_rad, aspect, near_m, far_m, frustum::DepthRange::ZeroToOne);
    if (!perspective) {
        return frustum::Error{"window::orbit_pair(): " + perspective.error()};
    }
    auto view = frustum::look_at<float>(camera.eye(), camera.target, kUp);
    if (!view) {
        return frustum::Error{"window::orbit_pair(): " + view.error()};
    }
    return frustum::compose(*perspective, *view);
}

} // namespace window
