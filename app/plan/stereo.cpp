#include "plan/stereo.hpp"

#include "plan/number_text.hpp"

#include <frustum/queries.hpp>
#include <frustum/screen_projection.hpp>

#include <cmath>
#include <string>

namespace plan {
frustum::Result<CameraFrame> camera_frame(const frustum::MatrixPair<float>& camera) {
    const frustum::MatrixPair<double> pair = camera.cast<double>();
    const frustum::KeyPoints<double> k = frustum::key_points(pair);
    const glm::dvec4 eye = frustum::to_point(k.eye, frustum::infinity_tolerance<double>());
    if (eye.w != 1.0) {
        return frustum::Error{"plan::camera_frame(): stereo needs a perspective camera (finite eye)"};
    }
    // Near corners C1 (1,1), C2 (-1,1), C3 (-1,-1), C4 (1,-1) (eq. 8).
    glm::dvec3 near[4];
    for (int i = 0; i < 4; ++i) {
        near[i] = glm::dvec3(k.corners[i]) / k.corners[i].w;
    }
    CameraFrame f;
    f.eye = glm::dvec3(eye);
    f.right = glm::normalize(near[0] - near[1]);
    const glm::dvec3 up_edge = near[0] - near[3];
    f.up = glm::normalize(up_edge - glm::dot(up_edge, f.right) * f.right); // exactly perpendicular
    f.forward = glm::cross(f.up, f.right);                                // right-handed: -z of the view
    f.near_m = glm::dot(near[2] - f.eye, f.forward);
    const glm::dvec4 far_corner = frustum::to_point(k.corners[6], frustum::infinity_tolerance<double>());
    if (far_corner.w == 1.0) {
        f.far_m = glm::dot(glm::dvec3(far_corner) - f.eye, f.forward);
    }
    // The near rectangle's extents on the axes, scaled to depth 1 m.
    const glm::dvec3 ll = near[2] - f.eye, ur = near[0] - f.eye;
    const double left = glm::dot(ll, f.right) / f.near_m, bottom = glm::dot(ll, f.up) / f.near_m;
    const double right = glm::dot(ur, f.right) / f.near_m, top = glm::dot(ur, f.up) / f.near_m;
    f.lower_left = f.forward + left * f.right + bottom * f.up;
    f.lower_right = f.forward + right * f.right + bottom * f.up;
    f.upper_left = f.forward + left * f.right + top * f.up;
    return f;
}

frustum::Result<StereoEyes> stereo_eyes(const frustum::MatrixPair<float>& camera, const StereoRig& rig) {
    auto frame = camera_frame(camera);
    if (!frame) {
        return frustum::Error{frame.error()};
    }
    const CameraFrame& f = *frame;
    if (!(rig.ipd_m >= 0.0f) || !std::isfinite(rig.ipd_m)) {
        return frustum::Error{"plan::stereo_eyes(): interpupillary distance must be a finite length >= 0 m, got " +
                              number_text(rig.ipd_m)};
    }
    const double convergence_m = rig.convergence_m;
    if (!(convergence_m > f.near_m) || !std::isfinite(convergence_m) || (f.far_m && !(convergence_m < *f.far_m))) {
        return frustum::Error{"plan::stereo_eyes(): convergence " + number_text(convergence_m) +
                              " m must be beyond the near plane (" + number_text(f.near_m) + " m)" +
                              (f.far_m ? " and before the far plane (" + number_text(*f.far_m) + " m)" : std::string())};
    }
    const glm::dvec3 lower_left = f.eye + convergence_m * f.lower_left;
    const glm::dvec3 lower_right = f.eye + convergence_m * f.lower_right;
    const glm::dvec3 upper_left = f.eye + convergence_m * f.upper_left;
    const double half_ipd_m = 0.5 * static_cast<double>(rig.ipd_m);
    const auto eye_pair = [&](double side) -> frustum::Result<frustum::MatrixPair<float>> {
        auto pair = frustum::screen_projection<double>(lower_left, lower_right, upper_left,
                                                       f.eye + side * half_ipd_m * f.right, f.near_m, f.far_m,
                                                       camera.depth());
        if (!pair) {
            return pair.take_error_in("plan::stereo_eyes()");
        }
        return pair->cast<float>();
    };
    auto left = eye_pair(-1.0);
    if (!left) {
        return frustum::Error{left.error()};
    }
    auto right = eye_pair(1.0);
    if (!right) {
        return frustum::Error{right.error()};
    }
    return StereoEyes{*left, *right};
}

frustum::Result<StereoCameras> stereo_cameras(const Cameras& cameras, const StereoRig& rig) {
    auto eyes = stereo_eyes(cameras.main.pair, rig);
    if (!eyes) {
        return frustum::Error{eyes.error()};
    }
    StereoCameras out{cameras, cameras};
    out.left.main = {cameras.main.name + " left", eyes->left};
    out.right.main = {cameras.main.name + " right", eyes->right};
    return out;
}

double depth_m(const CameraFrame& frame, const glm::dvec3& point) { return glm::dot(point - frame.eye, frame.forward); }

double predicted_disparity_px(const CameraFrame& frame, const StereoRig& rig, double depth, int width_px) {
    const double screen_width_m = static_cast<double>(rig.convergence_m) *
                                  glm::length(frame.lower_right - frame.lower_left);
    return static_cast<double>(rig.ipd_m) * (1.0 - static_cast<double>(rig.convergence_m) / depth) * width_px /
           screen_width_m;
}

float default_convergence_m(const frustum::MatrixPair<float>& camera, const std::optional<scene::MirrorRect>& mirror,
                            const scene::Bounds& bounds) {
    auto frame = camera_frame(camera);
    if (!frame) {
        return 1.0f; // no stereo for this camera anyway: stereo_eyes() says why
    }
    const CameraFrame& f = *frame;
    const auto usable = [&](double depth) { return depth > 1.5 * f.near_m && (!f.far_m || depth < *f.far_m); };
    if (mirror) {
        const glm::dvec3 centre = glm::dvec3(mirror->corner) + 0.5 * glm::dvec3(mirror->a1 + mirror->a2);
        if (const double d = depth_m(f, centre); usable(d)) {
            return static_cast<float>(d);
        }
    }
    if (const double d = depth_m(f, 0.5 * glm::dvec3(bounds.min + bounds.max)); usable(d)) {
        return static_cast<float>(d);
    }
    return static_cast<float>(2.0 * f.near_m);
}

} // namespace plan
