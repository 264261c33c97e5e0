#include "plan/camera.hpp"

#include "plan/number_text.hpp"

#include <frustum/projection.hpp>
#include <frustum/queries.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string_view>

namespace plan {
namespace {

constexpr float kFramingFovyRad = 0.785398163f; // 45 degrees
// Framing directions (from the target towards the eye): the default camera
// looks from the front (+Z), slightly right and above; the automatic overview
// from higher up and further right, so the main camera's frustum shows
// from the side.
constexpr glm::vec3 kFrontDirection{0.35f, 0.45f, 1.0f};
constexpr glm::vec3 kOverviewDirection{1.0f, 0.9f, 1.1f};

bool is_decimal(std::string_view text) {
    return !text.empty() && text.size() <= 9 &&
           std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

int find_by_name(const scene::Scene& scene, std::string_view name) {
    using Field = std::string scene::Camera::*;
    for (const Field field : {&scene::Camera::name, &scene::Camera::node_name}) {
        for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
            if (scene.cameras[i].*field == name) {
                return static_cast<int>(i);
            }
        }
    }
    return -1;
}

std::string camera_list(const scene::Scene& scene) {
    if (scene.cameras.empty()) {
        return "the scene has no cameras";
    }
    std::string text = "the scene's cameras are: ";
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        text += (i ? ", " : "") + scene.cameras[i].name;
    }
    return text;
}

scene::Bounds including(scene::Bounds bounds, const glm::vec3& point) {
    bounds.min = glm::min(bounds.min, point);
    bounds.max = glm::max(bounds.max, point);
    return bounds;
}

constexpr float kDerivedFarMargin = 1.05f; // the derived far plane: 5% beyond the farthest corner
constexpr float kDerivedFarMinPerNear = 2.0f;

// The distance from the camera's eye to the farthest corner of `bounds`.
float farthest_corner_m(const scene::Camera& camera, const scene::Bounds& bounds) {
    const glm::vec3 eye(camera.camera_to_world[3]);
    float reach_m = 0.0f;
    for (const glm::vec3& corner : scene::corners(bounds)) {
        reach_m = std::max(reach_m, glm::length(corner - eye));
    }
    return reach_m;
}

// What far_note says: the file's far plane and the one the effects use.
std::string far_note_text(const scene::Camera& camera, float far_m, const scene::Bounds& bounds) {
    const std::string had = camera.zfar_m ? "zfar " + number_text(*camera.zfar_m) + " is " +
                                                number_text(*camera.zfar_m / camera.znear_m) + " x its znear " +
                                                number_text(camera.znear_m) + " (a float pair holds up to " +
                                                number_text(kMaxFarPerNear) + " x)"
                                          : "no zfar (an infinite far plane)";
    const bool cut = far_m < farthest_corner_m(camera, bounds);
    return "camera '" + camera.name + "': " + had + "; every effect uses far = " + number_text(far_m) +
           " m, derived from the scene's bounds (1.05 x the distance from the eye to their farthest corner" +
           (cut ? ", cut to " + number_text(kMaxFarPerNear) + " x znear: the scene beyond it is not drawn)" : ")");
}

} // namespace

std::optional<float> derived_far_m(const scene::Camera& camera, const scene::Bounds& bounds) {
    const float near_m = camera.znear_m;
    // An orthographic pair's depth is linear: only a missing far plane needs one.
    const bool perspective = camera.kind == scene::Camera::Kind::Perspective;
    if (camera.zfar_m && (!perspective || *camera.zfar_m <= kMaxFarPerNear * near_m)) {
        return std::nullopt;
    }
    float far_m = std::max(kDerivedFarMargin * farthest_corner_m(camera, bounds), kDerivedFarMinPerNear * near_m);
    if (perspective) {
        far_m = std::min(far_m, kMaxFarPerNear * near_m);
    }
    if (camera.zfar_m) {
        far_m = std::min(far_m, *camera.zfar_m);
    }
    return far_m;
}

frustum::Result<frustum::MatrixPair<float>> camera_pair(const scene::Camera& camera, float image_aspect) {
    const auto depth = frustum::DepthRange::ZeroToOne;
    // The image's aspect wins over the camera's own (glTF 2.0, "Projection
    // Matrices": the viewport's aspect is used; otherwise the picture is
    // stretched): the vertical extent (yfov, ymag) is kept and the
    // horizontal one follows, xmag = ymag * image_aspect.
    frustum::Result<frustum::MatrixPair<float>> projection =
        frustum::Error{"plan::camera_pair(): camera '" + camera.name + "': orthographic camera without zfar"};
    if (camera.kind == scene::Camera::Kind::Perspective) {
        projection = frustum::perspective<float>(camera.yfov_rad, image_aspect, camera.znear_m, camera.zfar_m, depth);
    } else if (camera.zfar_m) {
        const float half_width = camera.ymag * image_aspect;
        projection = frustum::orthographic<float>(-half_width, half_width, -camera.ymag, camera.ymag,
                                                  camera.znear_m, *camera.zfar_m, depth);
    }
    if (!projection) {
        return frustum::Error{"plan::camera_pair(): camera '" + camera.name + "': " + projection.error()};
    }
    // camera_to_world = [R | t] is rigid (scene.hpp), so world_to_camera = [R^T | -R^T t].
    const glm::mat3 rotation_transposed = glm::transpose(glm::mat3(camera.camera_to_world));
    const glm::vec3 translation(camera.camera_to_world[3]);
    const auto view = frustum::RigidTransform<float>::from_rotation_translation(rotation_transposed,
                                                                                -(rotation_transposed * translation));
    return frustum::compose(*projection, view);
}

frustum::Result<frustum::MatrixPair<float>> perspective_twin(const scene::Camera& camera, const scene::Bounds& bounds,
                                                             float image_aspect) {
    const glm::vec3 position(camera.camera_to_world[3]);
    const glm::vec3 forward = -glm::vec3(camera.camera_to_world[2]); // glTF cameras look down -Z
    const glm::vec3 centre = (bounds.min + bounds.max) * 0.5f;
    const float centre_depth_m = glm::dot(centre - position, forward);
    const float distance_m = camera.ymag / std::tan(kFramingFovyRad * 0.5f);
    scene::Camera twin = camera;
    twin.name = camera.name + " (perspective twin)";
    twin.kind = scene::Camera::Kind::Perspective;
    twin.yfov_rad = kFramingFovyRad;
    const glm::vec3 eye = position + forward * (centre_depth_m - distance_m);
    twin.camera_to_world[3] = glm::vec4(eye, 1.0f);
    float far_m = 0.0f, nearest_m = std::numeric_limits<float>::max();
    for (const glm::vec3& corner : scene::corners(bounds)) {
        far_m = std::max(far_m, glm::length(corner - eye));
        nearest_m = std::min(nearest_m, glm::dot(corner - eye, forward));
    }
    far_m = std::max(kDerivedFarMargin * far_m, distance_m);
    twin.zfar_m = far_m;
    twin.znear_m = std::max(far_m / kMaxFarPerNear, nearest_m * 0.5f);
    auto pair = camera_pair(twin, image_aspect);
    if (!pair) {
        return pair.take_error_in("plan::perspective_twin()");
    }
    return pair;
}

Cameras cameras_for(Effect effect, const Cameras& cameras) {
    if (!effect_needs_finite_eye(effect) || !cameras.perspective_twin) {
        return cameras;
    }
    Cameras out = cameras;
    out.main = *cameras.perspective_twin;
    return out;
}

frustum::Result<frustum::MatrixPair<float>> framing_camera(const scene::Bounds& bounds,
                                                           const glm::vec3& from_direction, float aspect) {
    const glm::vec3 center = (bounds.min + bounds.max) * 0.5f;
    const float half_diagonal_m = glm::length(bounds.max - bounds.min) * 0.5f;
    const float radius_m = half_diagonal_m > 0.0f ? half_diagonal_m : 1.0f;
    // The sphere fits when its radius subtends the smaller half field of view.
    const float half_fovy_rad = kFramingFovyRad * 0.5f;
    const float half_fovx_rad = std::atan(aspect * std::tan(half_fovy_rad));
    const float distance_m = radius_m / std::sin(std::min(half_fovy_rad, half_fovx_rad));
    const glm::vec3 eye = center + glm::normalize(from_direction) * distance_m;
    auto view = frustum::look_at<float>(eye, center, glm::vec3(0.0f, 1.0f, 0.0f));
    if (!view) {
        return view.take_error_in("plan::framing_camera()");
    }
    // distance > radius (sin < 1), so near > 0.
    const float near_m = (distance_m - radius_m) * 0.5f;
    const float far_m = distance_m + radius_m * 2.0f;
    auto projection = frustum::perspective<float>(kFramingFovyRad, aspect, near_m, far_m, frustum::DepthRange::ZeroToOne);
    if (!projection) {
        return projection.take_error_in("plan::framing_camera()");
    }
    return frustum::compose(*projection, *view);
}

frustum::Result<int> find_camera(const scene::Scene& scene, const std::optional<std::string>& selector) {
    if (!selector) {
        const int main = find_by_name(scene, "main");
        return main >= 0 ? main : (scene.cameras.empty() ? -1 : 0);
    }
    if (const int named = find_by_name(scene, *selector); named >= 0) {
        return named;
    }
    if (is_decimal(*selector)) {
        const int index = std::stoi(*selector);
        if (static_cast<std::size_t>(index) < scene.cameras.size()) {
            return index;
        }
    }
    return frustum::Error{"plan::find_camera(): no camera '" + *selector + "'; " + camera_list(scene)};
}

frustum::Result<Cameras> make_cameras(const scene::Scene& scene, int main_camera, int width_px, int height_px) {
    const float aspect = static_cast<float>(width_px) / static_cast<float>(height_px);
    const bool from_file = main_camera >= 0 && static_cast<std::size_t>(main_camera) < scene.cameras.size();
    std::optional<std::string> far_note;
    std::optional<scene::Camera> file_camera;
    if (from_file) {
        file_camera = scene.cameras[static_cast<std::size_t>(main_camera)];
        if (const auto far_m = derived_far_m(*file_camera, scene.world_bounds)) {
            far_note = far_note_text(*file_camera, *far_m, scene.world_bounds);
            file_camera->zfar_m = *far_m;
        }
    }
    auto main = from_file ? camera_pair(*file_camera, aspect)
                          : framing_camera(scene.world_bounds, kFrontDirection, aspect);
    if (!main) {
        return main.take_error();
    }
    const std::string main_name = from_file ? scene.cameras[static_cast<std::size_t>(main_camera)].name : "framing";
    std::optional<NamedCamera> twin;
    std::optional<std::string> twin_note;
    if (from_file && file_camera->kind == scene::Camera::Kind::Orthographic) {
        auto pair = perspective_twin(*file_camera, scene.world_bounds, aspect);
        if (!pair) {
            return pair.take_error();
        }
        twin = NamedCamera{main_name + " (perspective twin)", *pair};
        const glm::vec3 eye = *frustum::eye_point(*pair);
        twin_note = "camera '" + main_name +
                    "' is orthographic: curved, lens, nonaffine, portal and recursion need a finite eye and draw "
                    "with its perspective twin (the same axis and up, yfov 45 deg, the eye at (" +
                    number_text(eye.x) + ", " + number_text(eye.y) + ", " + number_text(eye.z) +
                    ") m, showing the same height at the scene's centre)";
    }

    const int overview_index = find_by_name(scene, "overview");
    if (overview_index >= 0 && overview_index != main_camera) {
        auto overview = camera_pair(scene.cameras[static_cast<std::size_t>(overview_index)], aspect);
        if (!overview) {
            return overview.take_error();
        }
        return Cameras{{main_name, *main}, {"overview", *overview}, far_note, twin, twin_note};
    }
    // Automatic: frame the scene together with the main camera's eye (when
    // finite: an orthographic eye is at infinity).
    const auto eye = frustum::eye_point(*main);
    const scene::Bounds bounds = eye ? including(scene.world_bounds, *eye) : scene.world_bounds;
    auto overview = framing_camera(bounds, kOverviewDirection, aspect);
    if (!overview) {
        return overview.take_error();
    }
    return Cameras{{main_name, *main}, {"automatic overview", *overview}, far_note, twin, twin_note};
}

} // namespace plan
