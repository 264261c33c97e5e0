#include "plan/scene_fit.hpp"

#include "plan/number_text.hpp"

#include <frustum/queries.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace plan {
namespace {

constexpr float kPivotNearFactor = 1.05f; // the derived pivot stays 5% beyond the near plane
constexpr float kPivotFarFactor = 0.95f;  // ... and 5% short of the far plane
constexpr float kSlitPerPivot = 1.0f / 3.0f;  // the showcase's 2.6 m : 8 m, kept for every scene
constexpr float kLensCenterLimit = 0.6f;      // derived lens centre: within the middle 60% of the frame
constexpr float kLensRadiusMin = 0.1f;        // derived lens radius, fraction of the half height
constexpr float kLensRadiusMax = 0.4f;
constexpr float kSagittaPerHalfDiagonal = 0.2f;
constexpr float kSagittaPerModelReach = 0.25f; // the bulge: at most a quarter of the model's reach in front

struct EyeAxes {
    frustum::NearPlaneFrame<float> frame;
    glm::vec3 forward;
    float near_m;
};

frustum::Result<EyeAxes> eye_axes(const frustum::MatrixPair<float>& camera, const char* where) {
    auto frame = frustum::near_plane_frame(camera);
    if (!frame) {
        return frustum::Error{std::string(where) + ": " + frame.error()};
    }
    const glm::vec3 forward = frame->forward();
    return EyeAxes{*frame, forward, glm::dot(frame->center - frame->eye, forward)};
}

} // namespace

frustum::Result<NonAffineOptions> fit_non_affine(const frustum::MatrixPair<float>& camera,
                                                 const scene::Bounds& bounds, const NonAffineOptions& base,
                                                 const EffectFit& fit) {
    constexpr const char* kWhere = "nonaffine";
    auto axes = eye_axes(camera, kWhere);
    if (!axes) {
        return axes.take_error();
    }
    const auto far = frustum::far_distance(camera);
    if (!far) {
        return frustum::Error{std::string(kWhere) + ": needs a camera with a finite far plane"};
    }
    const float near_m = axes->near_m;
    const float far_m = *far;
    const std::string far_text = number_text(far_m) + " m of this camera";
    if (fit.pivot_m && !(*fit.pivot_m < far_m)) {
        return frustum::Error{"--pivot " + number_text(*fit.pivot_m) + " must be less than the far distance " +
                              far_text};
    }
    if (fit.slit_m && !(*fit.slit_m < far_m)) {
        return frustum::Error{"--slit " + number_text(*fit.slit_m) + " must be less than the far distance " +
                              far_text};
    }
    const glm::vec3 center = 0.5f * (bounds.min + bounds.max);
    const float center_depth_m = glm::dot(center - axes->frame.eye, axes->forward);
    float pivot_m = std::clamp(center_depth_m, std::min(kPivotNearFactor * near_m, far_m),
                               std::max(kPivotFarFactor * far_m, near_m));
    if (fit.pivot_m) {
        pivot_m = *fit.pivot_m;
    } else if (fit.slit_m && !(pivot_m > *fit.slit_m)) {
        pivot_m = 0.5f * (*fit.slit_m + far_m); // between the given slit and the far plane
    }
    const float slit_m = fit.slit_m ? *fit.slit_m : kSlitPerPivot * pivot_m;
    if (!(slit_m < pivot_m)) {
        return frustum::Error{"--slit " + number_text(slit_m) + " must be less than --pivot " +
                              number_text(pivot_m) + " (0 < slit < pivot < far = " + far_text + ")"};
    }
    NonAffineOptions options = base;
    options.slit_depth_m = slit_m;
    options.pivot_depth_m = pivot_m;
    return options;
}

frustum::Result<frustum::Lens<float>> fit_lens(const frustum::MatrixPair<float>& camera,
                                               const std::optional<scene::LensSpot>& spot,
                                               const scene::Bounds& bounds, const EffectFit& fit, float power) {
    constexpr const char* kWhere = "lens";
    if (!(power > 0.0f) || !std::isfinite(power)) {
        return frustum::Error{"--lens-power must be a number in (0, 8], got " + number_text(power)};
    }
    auto axes = eye_axes(camera, kWhere);
    if (!axes) {
        return axes.take_error();
    }
    const frustum::NearPlaneFrame<float>& frame = axes->frame;
    frustum::Lens<float> lens;
    lens.power = power;
    // The near-plane coordinates (metres) of the ray from the eye to `p`; false behind the eye.
    const auto project = [&](const glm::vec3& p, glm::vec2& out) {
        const float along = glm::dot(p - frame.eye, axes->forward);
        if (!(along > 0.0f)) {
            return false;
        }
        const glm::vec3 hit = frame.eye + (axes->near_m / along) * (p - frame.eye);
        out = glm::vec2(glm::dot(hit - frame.center, frame.x_axis), glm::dot(hit - frame.center, frame.y_axis));
        return true;
    };
    if (spot && !fit.lens_center && !fit.lens_radius) {
        glm::vec2 center(0.0f), rim(0.0f);
        if (project(spot->center, center) && project(spot->center + spot->radius_m * frame.x_axis, rim) &&
            glm::length(rim - center) > 0.0f) {
            lens.center_m = center;
            lens.radius_m = glm::length(rim - center);
            return lens;
        }
    }
    const glm::vec2 half(frame.half_width_m, frame.half_height_m);
    const glm::vec3 middle = 0.5f * (bounds.min + bounds.max);
    const float radius_world_m = 0.5f * glm::length(bounds.max - bounds.min);
    glm::vec2 seen_center(0.0f), seen_rim(0.0f);
    const bool seen = project(middle, seen_center) && project(middle + radius_world_m * frame.x_axis, seen_rim);
    if (fit.lens_center) {
        lens.center_m = *fit.lens_center * half;
    } else if (seen) {
        lens.center_m = glm::clamp(seen_center, -kLensCenterLimit * half, kLensCenterLimit * half);
    }
    if (fit.lens_radius) {
        lens.radius_m = *fit.lens_radius * frame.half_height_m;
    } else {
        const float seen_radius_m = seen ? 0.5f * glm::length(seen_rim - seen_center) : 0.0f;
        lens.radius_m = std::clamp(seen_radius_m, kLensRadiusMin * frame.half_height_m,
                                   kLensRadiusMax * frame.half_height_m);
    }
    return lens;
}

float max_sagitta_m(const scene::MirrorRect& mirror, CapShape shape) {
    // d as CurvedMirror::create() measures it: the largest distance from the centre to the rim.
    const glm::vec3 e2 = glm::normalize(mirror.a2);
    const float d_m = shape == CapShape::Sphere
                          ? 0.5f * std::max(glm::length(mirror.a1 + mirror.a2), glm::length(mirror.a1 - mirror.a2))
                          : 0.5f * glm::length(mirror.a1 - glm::dot(mirror.a1, e2) * e2);
    return 0.5f * d_m;
}

float fit_sagitta_m(const scene::MirrorRect& mirror, CapShape shape, const scene::Bounds& model_bounds) {
    const float by_size_m = kSagittaPerHalfDiagonal * 2.0f * max_sagitta_m(mirror, shape);
    // How far the model reaches in front of the mirror: the farthest corner
    // of its bounds along the reflecting side's normal.
    const glm::vec3 n = glm::normalize(glm::cross(mirror.a1, mirror.a2));
    float reach_m = 0.0f;
    for (const glm::vec3& corner : scene::corners(model_bounds)) {
        reach_m = std::max(reach_m, glm::dot(corner - mirror.corner, n));
    }
    return reach_m > 0.0f ? std::min(by_size_m, kSagittaPerModelReach * reach_m) : by_size_m;
}

} // namespace plan
